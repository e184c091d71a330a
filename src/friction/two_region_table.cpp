#include <cmath>

#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"

namespace selfalign {
namespace {

// The transition must be resolvable (friction_field.hpp): b1 = (c_mu - 1)/w, the slope of m, at
// most kMaxFrictionSlope, and w at least kMinRelativeStretch |x_mu|. The messages name the
// table's parameters.
void require_resolvable(double x_mu, double width, double c_mu) {
  if (!std::isfinite(x_mu + width))
    throw InvalidParameter("width", width,
                           "x_mu + width must be finite (x_mu = " + format_number(x_mu) + ")");
  if (width < kMinRelativeStretch * std::abs(x_mu))
    throw InvalidParameter("width", width,
                           "must be >= 1e-9 |x_mu| = " +
                               format_number(kMinRelativeStretch * std::abs(x_mu)) +
                               " for the transition region to be resolvable");
  if (!((c_mu - 1.0) / width <= kMaxFrictionSlope))
    throw InvalidParameter("c_mu, width", format_number(c_mu) + ", " + format_number(width),
                           "the friction transition must be resolvable: need (c_mu - 1)/width "
                           "<= 1e12, i.e. c_mu <= " +
                               format_number(1.0 + kMaxFrictionSlope * width) +
                               " for this width");
}

}  // namespace

TwoRegionTable::TwoRegionTable(double x_mu, double width, double c_mu)
    : x_mu_(require_finite("x_mu", x_mu)),
      width_(require_positive("width", width)),
      c_mu_(require_greater("c_mu", c_mu, 1.0)) {
  require_resolvable(x_mu_, width_, c_mu_);
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
