#pragma once
/// \file friction_field.hpp
/// The table's friction field and the object's footprint, kept apart: eq. (7) is the average of
/// the field over the footprint (docs/friction-field.md).
///
///   m(x) = mu_bar(x)/mu_1 = integral of field(xi) p(x - xi) dxi,   field = mu(xi)/mu_1,
///
/// with p the footprint's normalised contact pressure and x the object's LEADING edge. A point
/// footprint gives m(x) = field(x); a uniform footprint of width w gives the window average
/// m(x) = (1/w) * integral over [x - w, x] of field, which for the two-region field (mu_1 before
/// x_mu, mu_2 = c_mu mu_1 after) is exactly the paper's table, eqs. (7)-(9): the named
/// constructor `two_region_friction(x_mu, width, c_mu)` builds it as a FieldFriction.

#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "selfalign/friction/friction_map.hpp"

namespace selfalign {

/// Resolvability of a friction level in double precision (FieldFriction and TwoRegionTable check
/// the same bounds). A steeper or narrower transition leaves the exact solver's harmonic arcs
/// (frequency sqrt(slope), amplitude ~ y''/slope) below the rounding of t and x, and the object
/// chatters through ~1e8 zero-progress arcs a period (issue 9, D09, D12):
///  - slopes of m at most kMaxFrictionSlope [1/-]: arcs last >= 1e-6 periods and their amplitude
///    is >= 1e-12 (for |y''| ~ 1), four orders above the rounding of positions of order 1;
///  - sloped stretches at least kMinRelativeStretch |position| wide (>= 4e6 ulps).
inline constexpr double kMaxFrictionSlope = 1e12;
inline constexpr double kMinRelativeStretch = 1e-9;

/// One node of a piecewise-linear friction field: at `position` the field jumps from `left`
/// (its limit from the left) to `right` (its value at and just after the node; the field is
/// right-continuous). left == right on a continuous (ramp) node.
struct FieldNode {
  double position;  ///< table position xi [-]
  double left;      ///< limit of mu/mu_1 from the left [-]
  double right;     ///< mu/mu_1 at the node and just after it [-]
  bool operator==(const FieldNode&) const = default;
};

/// How tabulated samples (position, level) become a field.
enum class FieldInterpolation {
  steps,  ///< each sample's level holds until the next position (piecewise constant)
  linear  ///< straight lines between samples (ramps)
};

/// "steps" or "linear"; throws InvalidParameter("interpolation", text, ...) otherwise.
FieldInterpolation parse_field_interpolation(const std::string& text);

/// The table's relative friction mu(xi)/mu_1 over table position xi, piecewise linear: between
/// consecutive nodes it goes straight from the first node's `right` to the next node's `left`;
/// before the first node it is the first node's `left`, after the last the last node's `right`.
/// Valid fields: >= 1 node; positions finite, |position| <= 1e50, strictly increasing; levels
/// finite, within [0, 1e50], and > 0 somewhere. Every factory throws InvalidParameter otherwise.
class FrictionField {
 public:
  /// The general form; validated as above.
  explicit FrictionField(std::vector<FieldNode> nodes);

  /// Piecewise constant: levels[0] for xi < positions[0], levels[i] on
  /// [positions[i-1], positions[i]), levels.back() from positions.back() on.
  /// Needs levels.size() == positions.size() + 1 (no positions: a uniform field).
  static FrictionField steps(const std::vector<double>& positions,
                             const std::vector<double>& levels);
  /// Piecewise linear through (positions[i], levels[i]), constant outside; levels.size() ==
  /// positions.size() >= 1.
  static FrictionField ramps(const std::vector<double>& positions,
                             const std::vector<double>& levels);
  /// Samples (positions[i], levels[i]) as the rows of a field file: steps (each level holds from
  /// its position to the next, the first also before it) or linear (ramps through them).
  /// positions strictly increasing, one level per position, at least one.
  static FrictionField samples(const std::vector<double>& positions,
                               const std::vector<double>& levels, FieldInterpolation interpolation);
  /// Reads a CSV of rows "position,level" (one leading header line, blank lines and '#'
  /// comments allowed; positions strictly increasing; levels finite, in [0, 1e50], > 0
  /// somewhere). steps: each level holds from its position to the next (the first also before
  /// it); linear: ramps through the samples. Bad input throws a one-line InvalidParameter naming
  /// "<path>:<line>", e.g. "invalid friction field f.csv:4 level = -0.2: must be >= 0".
  static FrictionField from_csv(const std::string& path, FieldInterpolation interpolation);
  static FrictionField from_csv(const std::string& path, const std::string& interpolation);

  std::span<const FieldNode> nodes() const noexcept { return nodes_; }
  /// The same field with every position divided by `length` > 0: positions in metres to the
  /// model's x/L (Sect. 3.2; Scales::length_from_si), levels unchanged.
  FrictionField in_units_of(double length) const;
  /// mu(xi)/mu_1 (right-continuous at jumps). O(log n).
  double operator()(double xi) const noexcept;
  /// The integral of the field over [a, b] (a <= b; 0 for a >= b). O(log n + nodes inside).
  double integral(double a, double b) const noexcept;
  /// True when every stretch between nodes is flat (the field is a step function).
  bool piecewise_constant() const noexcept { return piecewise_constant_; }
  double min_level() const noexcept { return min_level_; }
  double max_level() const noexcept { return max_level_; }

  bool operator==(const FrictionField& other) const { return nodes_ == other.nodes_; }

 private:
  std::vector<FieldNode> nodes_;
  bool piecewise_constant_ = true;
  double min_level_ = 0, max_level_ = 0;
};

/// The parameters of the paper's two-region table (Sect. 3.3): mu_1 for x < x_mu, mu_2 = c_mu
/// mu_1 beyond x_mu + w, in between the width-averaged transition of eqs. (7)-(9)
///   m(x) = 1 + (c_mu - 1)/w * z,   z = min(max(x - x_mu, 0), w),
/// x the object's leading edge [-], w its dimensionless width. A value: the friction map is
/// `two_region_friction(x_mu, width, c_mu)` (a FieldFriction); the closed forms written for the
/// table (eqs. 41, 42, 59, 60) read these parameters.
class TwoRegionTable {
 public:
  /// \param x_mu  start of the high-friction region [-], finite, |x_mu| <= 1e50
  /// \param width object width w [-], in [1e-50, 1e50], with w >= 1e-9 |x_mu|
  /// \param c_mu  friction ratio mu_2/mu_1 [-], in (1, 1e50], with b1 = (c_mu - 1)/w <= 1e12
  /// The last two bounds keep the transition region resolvable in double precision (a sharper
  /// transition leaves the exact solver's arcs below the rounding of t and x); each violation
  /// throws InvalidParameter naming the parameter(s) and the bound.
  TwoRegionTable(double x_mu, double width, double c_mu);

  double x_mu() const noexcept { return x_mu_; }
  double width() const noexcept { return width_; }
  double c_mu() const noexcept { return c_mu_; }
  /// b_1 = (c_mu - 1)/w, the "stiffness" of the transition region (eq. 42) [-].
  double b1() const noexcept { return (c_mu_ - 1.0) / width_; }
  /// b_2 = (c_mu - 1) x_mu / w - 1 (eq. 42) [-].
  double b2() const noexcept { return b1() * x_mu_ - 1.0; }
  /// The table as a field: 1 before x_mu, c_mu from x_mu on (the footprint averages it).
  FrictionField field() const;
  bool operator==(const TwoRegionTable&) const = default;

 private:
  double x_mu_, width_, c_mu_;
};

/// A point contact: m(x) = field(x).
struct PointFootprint {
  bool operator==(const PointFootprint&) const = default;
};
/// Uniform contact pressure over [x - width, x] (x the leading edge): m(x) is the field's
/// average over that window. width [-] in [1e-50, 1e50].
struct UniformFootprint {
  double width;
  bool operator==(const UniformFootprint&) const = default;
};
/// The object's contact footprint (closed set of shapes).
using Footprint = std::variant<PointFootprint, UniformFootprint>;

/// m(x) = the field averaged over the footprint (eq. 7), for any field and footprint.
///
/// bound(x) is exact (up to rounding): O(log n) for a point footprint, O(log n + nodes under the
/// window) for a uniform one. piecewise_affine() is non-null exactly when m is piecewise
/// affine:
///  - point footprint, any field: the field's own pieces (jumps allowed);
///  - uniform footprint on a piecewise-constant (steps) field: breakpoints at the positions and
///    the positions + w, merged and sorted; each step k adds (right_k - left_k)/w (x - p_k) while
///    p_k < x < p_k + w, which is eq. (9) for one step;
///  - uniform footprint on a field with ramps: m is piecewise QUADRATIC, piecewise_affine() is
///    nullptr and only the time-stepping solver can use the map.
/// Breakpoints closer than 4 ulps are merged (a sliver piece would stall the exact solver; the
/// merged piece is off by at most slope x 4 ulps there).
///
/// Resolvability (as TwoRegionTable): the slopes of m must be <= 1e12 in magnitude, and its
/// sloped stretches must be wide enough to resolve in double precision: a ramp under a point
/// footprint at least 1e-9 |position| wide, a uniform footprint's width >= 1e-9 max |position|.
/// Violations throw a one-line InvalidParameter.
class FieldFriction final : public FrictionMap {
 public:
  FieldFriction(FrictionField field, Footprint footprint);
  /// The paper's two-region table (eq. 9) as the field it is: FrictionField::steps({x_mu},
  /// {1, c_mu}) under UniformFootprint{width}; two_region() then gives `table`, so the closed
  /// forms written for it (eqs. 41, 59, 60) apply. A field of that shape built by the general
  /// constructor (e.g. read from a file) is the same level but is not tagged as the paper's.
  explicit FieldFriction(const TwoRegionTable& table);

  double bound(double x) const override;
  const PiecewiseAffineFriction* piecewise_affine() const override {
    return affine_ ? &*affine_ : nullptr;
  }
  const FieldFriction* field_friction() const override { return this; }
  const TwoRegionTable* two_region() const override {
    return two_region_ ? &*two_region_ : nullptr;
  }

  const FrictionField& field() const noexcept { return field_; }
  const Footprint& footprint() const noexcept { return footprint_; }

 private:
  double window_average_of_steps(double x) const noexcept;

  FrictionField field_;
  Footprint footprint_;
  double width_ = 0;                      // 0 for a point footprint
  std::vector<double> window_ends_;       // p_k + w (uniform footprint on steps)
  std::vector<double> jump_per_width_;    // (right_k - left_k)/w (uniform footprint on steps)
  std::optional<PiecewiseAffineFriction> affine_;
  std::optional<TwoRegionTable> two_region_;  // set by the paper's named constructor only
};

/// The paper's two-region table (Sect. 3.3), eq. (9): m = 1 for x < x_mu, c_mu beyond
/// x_mu + w, and in between the width-averaged transition m = 1 + (c_mu - 1)/w (x - x_mu).
/// The named constructor of the field family: FieldFriction(TwoRegionTable(x_mu, width, c_mu)).
/// Throws InvalidParameter as TwoRegionTable's constructor does.
FieldFriction two_region_friction(double x_mu, double width, double c_mu);

/// The paper's table that `friction` is, where it is one: its named table (two_region()), or a
/// field of one step from level 1 to c_mu > 1 under a uniform footprint (eq. 7 of that field is
/// eq. 9: the same level), e.g. read from a file. nullopt otherwise (several steps, ramps, a
/// point footprint, a level other than 1 before the step, a uniform level).
std::optional<TwoRegionTable> as_two_region_table(const FrictionMap& friction);

}  // namespace selfalign
