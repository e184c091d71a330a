#include "selfalign/planar/planar_steady_state.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <variant>

#include "selfalign/error.hpp"
#include "selfalign/planar/planar_exact_point.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "step_sinks.hpp"

namespace selfalign {
namespace {

// One period of either stepper: pose and twist at the period's end, the level under the part
// at each step (Moreau) or the uniform level (exact), and the census of the period's steps.
struct PeriodResult {
  PlanarPose pose;
  PlanarTwist twist;
  double level_min = 0, level_max = 0;
  PlanarCensus census;
};

}  // namespace

PlanarSteadyState planar_steady_state(const PlanarProblem& p, const PlanarPose& pose,
                                      const PlanarTwist& twist,
                                      const PlanarSteadyStateOptions& o) {
  validate(p);
  if (o.max_periods < 1 || o.max_periods > 1000000)
    throw InvalidParameter("max_periods", std::to_string(o.max_periods), "must be in [1, 1e6]");
  if (o.transient_periods < 0 || o.transient_periods > 100000)
    throw InvalidParameter("transient_periods", std::to_string(o.transient_periods),
                           "must be in [0, 1e5]");
  if (!(o.tolerance >= 0 && o.tolerance < 1))
    throw InvalidParameter("tolerance", o.tolerance, "must be in [0, 1) (0: the default)");
  for (double v : {pose.x, pose.y, pose.angle, twist.ux, twist.uy, twist.omega})
    require_moderate("start", v);
  const double P = planar_period(p.motion);
  const bool exact = exact_point_applies(p);
  if (!exact) require_planar_steps("max_periods", o.transient_periods + o.max_periods, p);
  const double tol = o.tolerance > 0 ? o.tolerance : exact ? 1e-13 : 10 * p.options.step;

  PlanarSteadyState r;
  r.method = exact ? Method::exact : Method::time_stepping;
  // The two steppers behind one "one period" call.
  PlanarExactState point{0, pose.x, pose.y, twist.ux, twist.uy};
  double point_angle = pose.angle;
  PlanarRigidState rigid = make_planar_rigid_state(p.motion, 0, pose, twist);
  const UniformPlanarField* uniform = std::get_if<UniformPlanarField>(&p.field);
  const long long steps = exact ? 0 : steps_per_period(p);
  auto one_period = [&](int n) {
    PeriodResult out;
    if (exact) {
      advance_planar_exact_point(p.motion, *uniform, p.law, point, n * P);
      point_angle = pose.angle + twist.omega * (n * P);  // no torque about a centred point
      out.pose = {point.x, point.y, point_angle};
      out.twist = {point.ux, point.uy, twist.omega};
      out.level_min = out.level_max = uniform->level;
    } else {
      detail::LevelSink levels(p.field, p.part.patch);
      detail::CensusSink census;
      levels.census = &census;
      advance_planar_rigid(p.motion, p.field, p.law, p.part, p.options, rigid, steps, &levels);
      detail::require_finite(rigid);
      out.pose = rigid.pose;
      out.twist = rigid.twist;
      out.level_min = levels.lo;
      out.level_max = levels.hi;
      out.census = census.census;
    }
    return out;
  };

  const double start_level = level_under_patch(p.field, p.part.patch, pose);
  r.level_min = r.level_max = start_level;
  PlanarPose before = pose;
  PlanarTwist twist_before = twist;
  double dx0 = NAN, dy0 = NAN, da0 = NAN, e_prev = HUGE_VAL;
  const int total = o.transient_periods + o.max_periods;
  for (int n = 1; n <= total; ++n) {
    const PeriodResult period = one_period(n);
    r.periods = n;
    r.end_pose = period.pose;
    r.level_min = std::min(r.level_min, period.level_min);
    r.level_max = std::max(r.level_max, period.level_max);
    const double dx = period.pose.x - before.x, dy = period.pose.y - before.y,
                 da = period.pose.angle - before.angle;
    // z's change: the twist at phase 0 and the displacement per unit time.
    const double e = std::max({std::abs(period.twist.ux - twist_before.ux),
                               std::abs(period.twist.uy - twist_before.uy),
                               std::abs(period.twist.omega - twist_before.omega),
                               std::abs(dx - dx0) / P, std::abs(dy - dy0) / P,
                               std::abs(da - da0) / P});
    const double scale = 1 + std::max({std::abs(period.twist.ux), std::abs(period.twist.uy),
                                       std::abs(period.twist.omega), std::abs(dx) / P,
                                       std::abs(dy) / P, std::abs(da) / P});
    const bool level_held = !levels_differ(period.level_min, period.level_max);
    // z needs a previous period's displacement: the first period of the search gives none.
    if (n > o.transient_periods + 1 && level_held) {
      r.residual = e;
      // The contraction needs two residuals (e_prev finite), unless the map reached its fixed
      // point exactly (a stick resets the twist: e = 0).
      // At the rounding floor of z (displacements are differences of positions that grow
      // along the path) the map has reached its fixed point in floating point; e is the error.
      const double floor =
          16 * std::numeric_limits<double>::epsilon() *
          (scale + (std::abs(period.pose.x) + std::abs(period.pose.y) +
                    std::abs(period.pose.angle)) / P);
      const double lambda = e / e_prev;
      r.error = e <= floor ? e
                : std::isfinite(e_prev) && lambda < 1 ? e * lambda / (1 - lambda)
                                                       : HUGE_VAL;
      if (e <= tol * scale && r.error <= tol * scale) {
        r.converged = true;
        r.drift_x = dx / P;
        r.drift_y = dy / P;
        r.rotation_rate = da / P;
        r.twist_0s = twist_before;
        r.census = period.census;
        break;
      }
      e_prev = e;
    } else {
      e_prev = HUGE_VAL;  // no residual yet, or the map changed under the part: measured afresh
    }
    before = period.pose;
    twist_before = period.twist;
    dx0 = dx, dy0 = dy, da0 = da;
  }
  r.level_changed = levels_differ(r.level_min, r.level_max);
  return r;
}

}  // namespace selfalign
