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

class TwoRegionTable;
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
  /// The parameters of the paper's two-region table (eq. 9) when the map was built as it
  /// (`two_region_friction`, friction_field.hpp): eqs. (41), (59), (60) and the stick-position
  /// map are written for them. nullptr otherwise.
  virtual const TwoRegionTable* two_region() const { return nullptr; }
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

}  // namespace selfalign
