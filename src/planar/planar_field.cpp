#include "selfalign/planar/planar_field.hpp"

#include <algorithm>
#include <cmath>

#include "selfalign/error.hpp"
#include "selfalign/overloaded.hpp"

namespace selfalign {
namespace {

}  // namespace

void validate(const PlanarField& field) {
  std::visit(Overloaded{
                 [](const UniformPlanarField& u) { require_positive_moderate("level", u.level); },
                 [](const HalfPlaneStepField& h) {
                   require_moderate("origin_x", h.origin_x);
                   require_moderate("origin_y", h.origin_y);
                   require_finite("angle", h.angle);
                   require_positive_moderate("width", h.width);
                   if (!(h.c_mu >= 1) || !std::isfinite(h.c_mu))
                     throw InvalidParameter("c_mu", h.c_mu, "must be >= 1 and finite");
                 },
             },
             field);
}

double planar_level(const PlanarField& field, double x, double y) {
  return std::visit(Overloaded{
                        [](const UniformPlanarField& u) { return u.level; },
                        [&](const HalfPlaneStepField& h) {
                          const double d = std::cos(h.angle) * (x - h.origin_x) +
                                           std::sin(h.angle) * (y - h.origin_y);
                          return 1 + (h.c_mu - 1) * std::clamp(d / h.width, 0.0, 1.0);
                        },
                    },
                    field);
}

PlanarField rotated(const PlanarField& field, double angle) {
  return std::visit(Overloaded{
                        [](const UniformPlanarField& u) { return PlanarField(u); },
                        [&](const HalfPlaneStepField& h) {
                          HalfPlaneStepField r = h;
                          const double c = std::cos(angle), s = std::sin(angle);
                          r.origin_x = c * h.origin_x - s * h.origin_y;
                          r.origin_y = s * h.origin_x + c * h.origin_y;
                          r.angle = h.angle + angle;
                          return PlanarField(r);
                        },
                    },
                    field);
}

}  // namespace selfalign
