#pragma once
/// \file friction_map.hpp
/// The position-dependent friction bound mu_bar(x)/mu_1 of eqs. (7)-(9), behind an interface.
///
/// In the dimensionless model (Sect. 3.2) the friction force lies in -m(x) Sign(x'), with
/// m(x) = mu_bar(x)/mu_1 >= 0 [-]: m = 1 on the low-friction table. Every FrictionMap gives
/// m(x) for the time-stepping solver; maps that are piecewise affine in x also expose their
/// pieces, which lets the exact event-driven solver integrate them in closed form
/// (constant piece: parabolic arcs; affine piece: harmonic or hyperbolic arcs, eqs. 42-47).

#include <cstddef>
#include <span>
#include <vector>

namespace selfalign {

class TwoRegionFriction;
class FieldFriction;
class UniformFriction;

/// One affine piece of a friction map: m(x) = bound_at_begin + slope (x - begin) for
/// begin <= x < end. Positions [-], bound [-], slope [1/-].
struct AffinePiece {
  double begin;           ///< left end of the piece [-] (may be -inf)
  double end;             ///< right end of the piece [-] (may be +inf)
  double bound_at_begin;  ///< m at x = begin [-] (for begin = -inf: the constant value)
  double slope;           ///< dm/dx on the piece [-]; 0 on constant pieces

  double bound(double x) const noexcept {
    return slope == 0.0 ? bound_at_begin : bound_at_begin + slope * (x - begin);
  }
};

/// A piecewise-affine friction map: 1 to kMaxPieces pieces, sorted, covering the real line.
/// piece_index is a binary search (O(log n)), so fields of many pieces (friction_field.hpp)
/// stay fast; a single piece is answered without searching.
class PiecewiseAffineFriction {
 public:
  /// A sanity bound on the piece count (memory), far above any tabulated friction field.
  static constexpr std::size_t kMaxPieces = 50'000'000;

  /// \param pieces sorted, contiguous (pieces[i].end == pieces[i+1].begin), first begins at
  ///        -inf and last ends at +inf, bound >= 0 everywhere. Throws InvalidParameter otherwise.
  explicit PiecewiseAffineFriction(std::span<const AffinePiece> pieces);

  std::span<const AffinePiece> pieces() const noexcept { return pieces_; }
  /// Index of the piece containing x (pieces are closed on the left).
  std::size_t piece_index(double x) const noexcept;
  double bound(double x) const noexcept { return pieces_[piece_index(x)].bound(x); }

 private:
  std::vector<AffinePiece> pieces_;
};

/// Interface for friction laws m(x) = mu_bar(x)/mu_1. Implement it for new friction laws.
class FrictionMap {
 public:
  virtual ~FrictionMap() = default;
  /// Friction bound m(x) = mu_bar(x)/mu_1 at dimensionless position x [-]; >= 0.
  virtual double bound(double x) const = 0;
  /// The map as affine pieces, or nullptr when it is not piecewise affine (then only the
  /// time-stepping solver can use it).
  virtual const PiecewiseAffineFriction* piecewise_affine() const { return nullptr; }
  /// The map as the paper's two-region table (eq. 9), when it is one: eqs. (41), (59), (60)
  /// and the stick-position map are written for it. nullptr otherwise.
  virtual const TwoRegionFriction* two_region() const { return nullptr; }
  /// The map as a friction field averaged over a footprint (friction_field.hpp), when it is
  /// one. nullptr otherwise. (Capability queries: no caller casts a friction map.)
  virtual const FieldFriction* field_friction() const { return nullptr; }
  /// The map as one constant level, when it is one (UniformFriction): time-stepping then reads
  /// it once instead of calling bound() every step. nullptr otherwise.
  virtual const UniformFriction* uniform() const { return nullptr; }
};

/// Uniform Coulomb friction: m(x) = level (1 on the paper's low-friction table).
class UniformFriction final : public FrictionMap {
 public:
  /// \param level m = mu/mu_1 [-], finite and > 0.
  explicit UniformFriction(double level = 1.0);
  double bound(double) const override { return level_; }
  const PiecewiseAffineFriction* piecewise_affine() const override { return &affine_; }
  const UniformFriction* uniform() const override { return this; }
  double level() const noexcept { return level_; }

 private:
  double level_;
  PiecewiseAffineFriction affine_;
};

/// The paper's two-region table (Sect. 3.3): mu_1 for x < x_mu, mu_2 = c_mu mu_1 beyond
/// x_mu + w, and in between the width-averaged transition of eqs. (7)-(9):
///   m(x) = 1 + (c_mu - 1)/w * z,   z = min(max(x - x_mu, 0), w)          (eqs. 7, 8)
/// x is the position of the object's leading edge [-], w its dimensionless width.
class TwoRegionFriction final : public FrictionMap {
 public:
  /// \param x_mu  start of the high-friction region [-], finite
  /// \param width object width w [-], > 0, with x_mu + w finite and w >= 1e-9 |x_mu|
  /// \param c_mu  friction ratio mu_2/mu_1 [-], > 1, with b1 = (c_mu - 1)/w <= 1e12
  /// The last two bounds keep the transition region resolvable in double precision (a sharper
  /// transition leaves the exact solver's arcs below the rounding of t and x); each violation
  /// throws InvalidParameter naming the parameter(s) and the bound.
  TwoRegionFriction(double x_mu, double width, double c_mu);

  double bound(double x) const override;  // eq. (9)
  const PiecewiseAffineFriction* piecewise_affine() const override { return &affine_; }
  const TwoRegionFriction* two_region() const override { return this; }

  double x_mu() const noexcept { return x_mu_; }
  double width() const noexcept { return width_; }
  double c_mu() const noexcept { return c_mu_; }
  /// b_1 = (c_mu - 1)/w, the "stiffness" of the transition region (eq. 42) [-].
  double b1() const noexcept { return (c_mu_ - 1.0) / width_; }
  /// b_2 = (c_mu - 1) x_mu / w - 1 (eq. 42) [-].
  double b2() const noexcept { return b1() * x_mu_ - 1.0; }

 private:
  double x_mu_, width_, c_mu_;
  PiecewiseAffineFriction affine_;
};

}  // namespace selfalign
