#include "selfalign/planar/planar_field.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "selfalign/error.hpp"
#include "selfalign/overloaded.hpp"

namespace selfalign {
namespace {

void require_c_mu(double c_mu) {
  if (!(c_mu >= 1) || !std::isfinite(c_mu) || c_mu > 1e6)
    throw InvalidParameter("c_mu", c_mu, "must be in [1, 1e6]");
}

// A rough region's placement (a point and, where it has one, its direction) and its band.
void require_point(const char* x_name, double x, const char* y_name, double y) {
  require_moderate(x_name, x);
  require_moderate(y_name, y);
}
void require_band(double width, double c_mu) {
  require_positive_moderate("width", width);
  require_c_mu(c_mu);
}

double ramp(double c_mu, double depth, double width) {
  return 1 + (c_mu - 1) * std::clamp(depth / width, 0.0, 1.0);
}

void rotate(double angle, double& x, double& y) {
  const double c = std::cos(angle), s = std::sin(angle);
  const double rx = c * x - s * y, ry = s * x + c * y;
  x = rx, y = ry;
}

}  // namespace

void validate(const PlanarField& field) {
  std::visit(Overloaded{
                 [](const UniformPlanarField& u) { require_positive_moderate("level", u.level); },
                 [](const HalfPlaneStepField& h) {
                   require_point("origin_x", h.origin_x, "origin_y", h.origin_y);
                   require_finite("angle", h.angle);
                   require_band(h.width, h.c_mu);
                 },
                 [](const StripField& f) {
                   require_point("origin_x", f.origin_x, "origin_y", f.origin_y);
                   require_finite("angle", f.angle);
                   require_positive_moderate("half_width", f.half_width);
                   require_band(f.width, f.c_mu);
                 },
                 [](const RectangularPocketField& f) {
                   require_point("centre_x", f.centre_x, "centre_y", f.centre_y);
                   require_finite("angle", f.angle);
                   require_positive_moderate("half_length", f.half_length);
                   require_positive_moderate("half_width", f.half_width);
                   require_band(f.width, f.c_mu);
                 },
                 [](const CircularPocketField& f) {
                   require_point("centre_x", f.centre_x, "centre_y", f.centre_y);
                   require_positive_moderate("radius", f.radius);
                   require_band(f.width, f.c_mu);
                 },
                 [](const GridField& f) {
                   require_point("origin_x", f.origin_x, "origin_y", f.origin_y);
                   require_finite("angle", f.angle);
                   require_positive_moderate("dx", f.dx);
                   require_positive_moderate("dy", f.dy);
                   if (f.nx < 2 || f.ny < 2 || f.nx > 100000 || f.ny > 100000)
                     throw InvalidParameter("nx", std::to_string(f.nx) + " x " + std::to_string(f.ny),
                                            "grid needs 2 to 100000 nodes per direction");
                   if (f.levels.size() != static_cast<std::size_t>(f.nx) * static_cast<std::size_t>(f.ny))
                     throw InvalidParameter("levels", std::to_string(f.levels.size()) + " values",
                                            "needs nx * ny = " + std::to_string(static_cast<long long>(f.nx) * f.ny) + " values");
                   for (std::size_t i = 0; i < f.levels.size(); ++i)
                     if (!(f.levels[i] > 0) || !(f.levels[i] <= 1e6))
                       throw InvalidParameter("levels", f.levels[i],
                                              "must be finite and in (0, 1e6] (value " + std::to_string(i) + ")");
                 },
                 [](const AxisField& f) {
                   require_point("origin_x", f.origin_x, "origin_y", f.origin_y);
                   require_finite("angle", f.angle);
                   // The FrictionField checked its nodes; a planar level must be > 0 everywhere.
                   if (!(f.field.min_level() > 0))
                     throw InvalidParameter("levels", f.field.min_level(),
                                            "must be > 0 everywhere on a planar table (a level "
                                            "of 0 holds nothing)");
                   if (!(f.field.max_level() <= 1e6))
                     throw InvalidParameter("levels", f.field.max_level(), "must be <= 1e6");
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
                          return ramp(h.c_mu, d, h.width);
                        },
                        [&](const StripField& f) {
                          const double d = std::cos(f.angle) * (x - f.origin_x) +
                                           std::sin(f.angle) * (y - f.origin_y);
                          return ramp(f.c_mu, f.half_width - std::abs(d), f.width);
                        },
                        [&](const RectangularPocketField& f) {
                          const double c = std::cos(f.angle), s = std::sin(f.angle);
                          const double rx = x - f.centre_x, ry = y - f.centre_y;
                          const double xi = c * rx + s * ry, eta = -s * rx + c * ry;
                          return ramp(f.c_mu,
                                      std::min(f.half_length - std::abs(xi),
                                               f.half_width - std::abs(eta)),
                                      f.width);
                        },
                        [&](const CircularPocketField& f) {
                          return ramp(f.c_mu, f.radius - std::hypot(x - f.centre_x, y - f.centre_y),
                                      f.width);
                        },
                        [&](const GridField& f) {
                          const double c = std::cos(f.angle), s = std::sin(f.angle);
                          const double rx = x - f.origin_x, ry = y - f.origin_y;
                          const double u = std::clamp((c * rx + s * ry) / f.dx, 0.0, f.nx - 1.0);
                          const double v = std::clamp((-s * rx + c * ry) / f.dy, 0.0, f.ny - 1.0);
                          const int i = std::min(static_cast<int>(u), f.nx - 2);
                          const int j = std::min(static_cast<int>(v), f.ny - 2);
                          const double a = u - i, b = v - j;
                          const auto at = [&](int ii, int jj) {
                            return f.levels[static_cast<std::size_t>(jj) * f.nx + ii];
                          };
                          return (1 - a) * (1 - b) * at(i, j) + a * (1 - b) * at(i + 1, j) +
                                 (1 - a) * b * at(i, j + 1) + a * b * at(i + 1, j + 1);
                        },
                        [&](const AxisField& f) {
                          return f.field(std::cos(f.angle) * (x - f.origin_x) +
                                         std::sin(f.angle) * (y - f.origin_y));
                        },
                    },
                    field);
}

double max_planar_level(const PlanarField& field) {
  return std::visit(Overloaded{
                        [](const UniformPlanarField& u) { return u.level; },
                        [](const HalfPlaneStepField& f) { return std::max(1.0, f.c_mu); },
                        [](const StripField& f) { return std::max(1.0, f.c_mu); },
                        [](const RectangularPocketField& f) { return std::max(1.0, f.c_mu); },
                        [](const CircularPocketField& f) { return std::max(1.0, f.c_mu); },
                        [](const GridField& f) {
                          return *std::max_element(f.levels.begin(), f.levels.end());
                        },
                        [](const AxisField& f) { return f.field.max_level(); },
                    },
                    field);
}

PlanarField rotated_field(const PlanarField& field, double angle) {
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
                        [&](const StripField& f) {
                          StripField r = f;
                          rotate(angle, r.origin_x, r.origin_y);
                          r.angle += angle;
                          return PlanarField(r);
                        },
                        [&](const RectangularPocketField& f) {
                          RectangularPocketField r = f;
                          rotate(angle, r.centre_x, r.centre_y);
                          r.angle += angle;
                          return PlanarField(r);
                        },
                        [&](const CircularPocketField& f) {
                          CircularPocketField r = f;
                          rotate(angle, r.centre_x, r.centre_y);
                          return PlanarField(r);
                        },
                        [&](const GridField& f) {
                          GridField r = f;
                          rotate(angle, r.origin_x, r.origin_y);
                          r.angle += angle;
                          return PlanarField(r);
                        },
                        [&](const AxisField& f) {
                          AxisField r = f;
                          rotate(angle, r.origin_x, r.origin_y);
                          r.angle += angle;
                          return PlanarField(r);
                        },
                    },
                    field);
}

}  // namespace selfalign
