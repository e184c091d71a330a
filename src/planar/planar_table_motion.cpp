#include "selfalign/planar/planar_table_motion.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "selfalign/error.hpp"

namespace selfalign {

void require_unit_vector(const std::string& name, double x, double y) {
  if (!(std::abs(std::hypot(x, y) - 1) <= 1e-12))
    throw InvalidParameter(name, std::hypot(x, y), "must be a unit vector (|" + name + "| = 1)");
}

void validate(const PlanarTableMotion& m) {
  if (m.first) require_unit_vector("e1", m.e1_x, m.e1_y);
  if (m.second) require_unit_vector("e2", m.e2_x, m.e2_y);
}

void require_no_normal_motion(const PlanarTableMotion& m, const char* solver) {
  if (m.normal)
    throw InvalidParameter("normal", m.normal->kind(),
                           std::string(solver) +
                               " has no normal load: the table's normal motion needs the contact "
                               "core's model with gravity (core::Model::gravity)");
}

void require_planar_law(const FrictionLaw& law) {
  if (law.kinetic_forward() != law.kinetic_backward() || law.velocity_dependent())
    throw InvalidParameter("law", law.describe(),
                           "planar friction must be isotropic (kinetic_forward = "
                           "kinetic_backward) and velocity-independent");
}

PlanarTablePose table_pose(const PlanarTableMotion& m, double t) {
  PlanarTablePose p;
  if (m.first) {
    const TableState s = m.first->state(t);
    p.x += s.y * m.e1_x, p.y += s.y * m.e1_y, p.vx += s.yd * m.e1_x, p.vy += s.yd * m.e1_y;
  }
  if (m.second) {
    const TableState s = m.second->state(t);
    p.x += s.y * m.e2_x, p.y += s.y * m.e2_y, p.vx += s.yd * m.e2_x, p.vy += s.yd * m.e2_y;
  }
  if (m.rotation) {
    const TableState s = m.rotation->state(t);
    p.angle = s.y, p.rate = s.yd;
  }
  if (m.normal) {
    const TableState s = m.normal->state(t);
    p.z = s.y, p.vz = s.yd;
  }
  return p;
}

double planar_period(const PlanarTableMotion& m) {
  double period = 0;
  for (const TableProfile* p : {m.first, m.second, m.rotation, m.normal})
    if (p) period = std::max(period, p->period());
  if (period == 0) throw InvalidParameter("motion", "no profile", "needs at least one profile");
  for (const TableProfile* p : {m.first, m.second, m.rotation, m.normal})
    if (p) {
      const double ratio = period / p->period();
      if (!(std::abs(ratio - std::round(ratio)) <= 1e-9 * ratio))
        throw InvalidParameter("period", p->period(),
                               "must divide the longest period " + std::to_string(period));
    }
  return period;
}

void table_velocity(const PlanarTableMotion& m, double t, double& vx, double& vy) {
  vx = vy = 0;
  if (m.first) {
    const double v = m.first->velocity(t);
    vx += v * m.e1_x, vy += v * m.e1_y;
  }
  if (m.second) {
    const double v = m.second->velocity(t);
    vx += v * m.e2_x, vy += v * m.e2_y;
  }
}

double largest_step_velocity_change(const PlanarTableMotion& m, double t0, double h,
                                    long long steps) {
  double largest = 0, vx0, vy0;
  table_velocity(m, t0, vx0, vy0);
  for (long long k = 1; k <= steps; ++k) {
    double vx, vy;
    table_velocity(m, t0 + static_cast<double>(k) * h, vx, vy);
    largest = std::max(largest, std::hypot(vx - vx0, vy - vy0));
    vx0 = vx, vy0 = vy;
  }
  return largest;
}

}  // namespace selfalign
