#include "selfalign/planar/planar_point.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "selfalign/error.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "../profiles/tracked_velocity.hpp"

namespace selfalign {

PlanarPointState make_planar_point_state(const PlanarTableMotion& motion, double t, double x,
                                         double y, double ux, double uy) {
  validate(motion);
  for (double v : {t, x, y, ux, uy}) require_moderate("start", v);
  PlanarPointState s;
  s.t0 = s.t = t;
  s.x = x, s.y = y, s.ux = ux, s.uy = uy;
  table_velocity(motion, t, s.table_vx, s.table_vy);
  s.stick = ux == 0 && uy == 0;
  return s;
}

namespace {

// The step loop of advance_planar_point, for any table-velocity and level functors (so that the
// common cases, piecewise-polynomial profiles and a uniform level, run without virtual calls or
// a variant visit per step).
template <class TableVelocity, class Level>
void point_steps(const TableVelocity& table_v, const Level& level, double s, double kin, double h,
                 double theta, PlanarPointState& st, long long steps) {
  double x = st.x, y = st.y, ux = st.ux, uy = st.uy, tvx = st.table_vx, tvy = st.table_vy;
  long long k = st.step_index;
  for (long long i = 0; i < steps; ++i) {
    ++k;
    const double t = st.t0 + static_cast<double>(k) * h;
    double tvx1 = 0, tvy1 = 0;
    table_v(t, tvx1, tvy1);
    const double m = level(x + 0.5 * h * ux, y + 0.5 * h * uy);
    const double vx = ux - (tvx1 - tvx), vy = uy - (tvy1 - tvy);  // v*: no friction
    // |v*|: sqrt of the sum of squares (within an ulp of hypot) wherever that sum is far from
    // overflow and underflow, hypot elsewhere (a tenth of the step's cost, bench/floors.cpp)
    const double q = vx * vx + vy * vy;
    const double speed = q > 1e-290 && q < 1e290 ? std::sqrt(q) : std::hypot(vx, vy);
    const bool sliding_on = vx * ux + vy * uy > 0;
    const double hold = h * ((sliding_on ? kin : s) * m);
    double ux1 = 0, uy1 = 0;
    if (speed > hold) {  // slide: the kinetic impulse against v*
      const double impulse = h * (kin * m);
      ux1 = vx - impulse * (vx / speed);
      uy1 = vy - impulse * (vy / speed);
    }
    x += h * ((1 - theta) * ux + theta * ux1);
    y += h * ((1 - theta) * uy + theta * uy1);
    ux = ux1, uy = uy1, tvx = tvx1, tvy = tvy1;
  }
  st.step_index = k;
  st.t = st.t0 + static_cast<double>(k) * h;
  st.x = x, st.y = y, st.ux = ux, st.uy = uy, st.table_vx = tvx, st.table_vy = tvy;
  st.stick = ux == 0 && uy == 0;
}

template <class TableVelocity>
void point_steps_on(const TableVelocity& table_v, const PlanarField& field, double s, double kin,
                    double h, double theta, PlanarPointState& st, long long steps) {
  if (const auto* u = std::get_if<UniformPlanarField>(&field)) {
    const double m = u->level;
    point_steps(table_v, [m](double, double) { return m; }, s, kin, h, theta, st, steps);
  } else {
    point_steps(table_v, [&field](double x, double y) { return planar_level(field, x, y); }, s,
                kin, h, theta, st, steps);
  }
}

}  // namespace

void advance_planar_point(const PlanarTableMotion& motion, const PlanarField& field,
                          const FrictionLaw& law, const TimeSteppingOptions& o,
                          PlanarPointState& st, long long steps) {
  validate(o);
  validate(motion);
  validate(field);
  if (motion.rotation)
    throw InvalidParameter("rotation", motion.rotation->kind(),
                           "a point contact needs a translating table (use the rigid part)");
  require_no_normal_motion(motion, "the point stepper");
  require_planar_law(law);
  const double h = o.step, theta = o.theta;
  const double s = law.static_coefficient(), kin = law.kinetic_forward();
  // Both directions piecewise polynomial (or absent): call their velocity directly.
  const PiecewisePolynomialProfile* p1 = motion.first ? motion.first->piecewise_polynomial() : nullptr;
  const PiecewisePolynomialProfile* p2 = motion.second ? motion.second->piecewise_polynomial() : nullptr;
  if (p1 && p2 && p1->piecewise_constant() && p2->piecewise_constant()) {
    // The velocities tracked across the steps: the same numbers, without a division and a
    // segment scan per step (profiles/tracked_velocity.hpp).
    const double e1x = motion.e1_x, e1y = motion.e1_y, e2x = motion.e2_x, e2y = motion.e2_y;
    point_steps_on(
        [=, first = detail::TrackedVelocity(*p1), second = detail::TrackedVelocity(*p2)](
            double t, double& vx, double& vy) {
          const double v1 = first(t), v2 = second(t);
          vx = v1 * e1x + v2 * e2x, vy = v1 * e1y + v2 * e2y;
        },
        field, s, kin, h, theta, st, steps);
  } else if (p1 && p2) {
    const double e1x = motion.e1_x, e1y = motion.e1_y, e2x = motion.e2_x, e2y = motion.e2_y;
    point_steps_on(
        [=](double t, double& vx, double& vy) {
          const double v1 = p1->velocity(t), v2 = p2->velocity(t);
          vx = v1 * e1x + v2 * e2x, vy = v1 * e1y + v2 * e2y;
        },
        field, s, kin, h, theta, st, steps);
  } else {
    point_steps_on([&motion](double t, double& vx, double& vy) { table_velocity(motion, t, vx, vy); },
                   field, s, kin, h, theta, st, steps);
  }
}

}  // namespace selfalign
