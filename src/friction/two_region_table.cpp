#include <cmath>

#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"

namespace selfalign {
namespace {

// The transition region must be resolvable in double precision, or the exact solver's harmonic
// arcs there (frequency sqrt(b1), amplitude ~ y''/b1) shrink below the rounding of t and x and
// the object chatters through ~1e8 zero-progress arcs a period (issue 9, D09, D12).
//  - b1 = (c_mu - 1)/w <= 1e12: arcs last >= 1e-6 periods and their amplitude is >= 1e-12 (for
//    |y''| ~ 1), four orders above the rounding of positions of order 1;
//  - w >= 1e-9 |x_mu|: the transition spans >= 4e6 ulps of x_mu.
// (The field's own checks, friction_field.cpp, are the same bounds for any field.)
constexpr double kMaxTransitionStiffness = 1e12;  // largest b1 [1/-]
constexpr double kMinRelativeWidth = 1e-9;        // smallest w / |x_mu| [-]

double resolvable_width(double x_mu, double width, double c_mu) {
  if (!std::isfinite(x_mu + width))
    throw InvalidParameter("width", width,
                           "x_mu + width must be finite (x_mu = " + format_number(x_mu) + ")");
  if (width < kMinRelativeWidth * std::abs(x_mu))
    throw InvalidParameter("width", width,
                           "must be >= 1e-9 |x_mu| = " +
                               format_number(kMinRelativeWidth * std::abs(x_mu)) +
                               " for the transition region to be resolvable");
  if (!((c_mu - 1.0) / width <= kMaxTransitionStiffness))
    throw InvalidParameter("c_mu, width", format_number(c_mu) + ", " + format_number(width),
                           "the friction transition must be resolvable: need (c_mu - 1)/width "
                           "<= 1e12, i.e. c_mu <= " +
                               format_number(1.0 + kMaxTransitionStiffness * width) +
                               " for this width");
  return width;
}

}  // namespace

TwoRegionTable::TwoRegionTable(double x_mu, double width, double c_mu)
    : x_mu_(require_finite("x_mu", x_mu)),
      width_(require_positive("width", width)),
      c_mu_(require_greater("c_mu", c_mu, 1.0)) {
  resolvable_width(x_mu_, width_, c_mu_);
  // The field's own range (friction_field.hpp), so that the field never refuses the table.
  require_moderate("x_mu", x_mu_);
  require_positive_moderate("width", width_);
  require_moderate("c_mu", c_mu_);
}

FrictionField TwoRegionTable::field() const { return FrictionField::steps({x_mu_}, {1.0, c_mu_}); }

FieldFriction::FieldFriction(const TwoRegionTable& table)
    : FieldFriction(table.field(), UniformFootprint{table.width()}) {
  two_region_ = table;
}

FieldFriction two_region_friction(double x_mu, double width, double c_mu) {
  return FieldFriction(TwoRegionTable(x_mu, width, c_mu));
}

std::optional<TwoRegionTable> as_two_region_table(const FrictionMap& friction) {
  if (const TwoRegionTable* named = friction.two_region()) return *named;
  const FieldFriction* field = friction.field_friction();
  if (!field) return std::nullopt;
  const auto* footprint = std::get_if<UniformFootprint>(&field->footprint());
  const auto nodes = field->field().nodes();
  if (!footprint || nodes.size() != 1 || nodes[0].left != 1.0 || !(nodes[0].right > 1.0))
    return std::nullopt;
  // The field passed the same resolvability checks as the table (friction_field.cpp), so the
  // table accepts its values.
  return TwoRegionTable(nodes[0].position, footprint->width, nodes[0].right);
}

}  // namespace selfalign
