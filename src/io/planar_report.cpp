// The reports of a planar run: io/planar_report.hpp.
#include "selfalign/io/planar_report.hpp"

#include <cmath>

#include "selfalign/error.hpp"
#include "selfalign/io/summary_json.hpp"
#include "selfalign/simulate/simulate.hpp"  // kMaxRecordedSamples

namespace selfalign {

using nlohmann::json;

json planar_census_json(const PlanarCensus& c) {
  const double n = static_cast<double>(c.total());
  return {{"stick", c.stick}, {"pivot", c.pivot}, {"slip", c.slip},
          {"stick_fraction", number_or_null(n > 0 ? c.stick / n : NAN)}};
}

json planar_pose_json(const PlanarPose& p, const PlanarUnits& si) {
  return {{"x", number_or_null(si.length(p.x))}, {"y", number_or_null(si.length(p.y))},
          {"angle_rad", number_or_null(p.angle)}};
}

json planar_report_header(const PlanarSetup& s) {
  return {{"config", s.path},
          {"units", s.si ? "si" : "dimensionless"},
          {"scales", {{"length_m", s.scales.length()}, {"mu", s.scales.mu()}, {"g", s.scales.gravity()}, {"time_s", s.scales.time()}}},
          {"contact_points", s.problem.part.patch.size()},
          {"inertia_per_unit_mass", s.problem.part.inertia},
          {"step", s.problem.options.step},
          {"steps_per_period", steps_per_period(s.problem)}};
}

PlanarTrajectory planar_simulate_run(const PlanarSetup& s, const PlanarRunProgress& progress) {
  require_planar_steps("run.periods", s.periods, s.problem);
  const double rows = s.periods * static_cast<double>(steps_per_period(s.problem)) / s.every;
  if (!(rows <= kMaxRecordedSamples))
    throw InvalidParameter("run.every", s.every,
                           "records " + format_number(rows) + " rows; at most " +
                               format_number(kMaxRecordedSamples));
  if (s.method == Method::exact && !exact_point_applies(s.problem))
    throw InvalidParameter("run.method", "exact",
                           "the exact point solver needs a point part at its centre on a uniform "
                           "field and a translating table with piecewise-constant accelerations");
  if (s.method == Method::integrator && !patch_integrator_applies(s.problem))
    throw InvalidParameter("run.method", "integrator",
                           "the patch integrator needs a translating table with "
                           "piecewise-constant accelerations");
  return simulate_planar(s.problem, s.pose, s.twist, planar_steps_of_periods(s.problem, s.periods),
                         s.every, progress, s.method);
}

json planar_simulate_report_json(const PlanarSetup& s, const PlanarTrajectory& run) {
  const PlanarUnits si{s};
  const PlanarRigidState& st = run.end;
  json r = planar_report_header(s);
  r["command"] = "planar simulate";
  r["method"] = to_string(s.method);
  r["periods"] = s.periods;
  r["end_pose"] = planar_pose_json(st.pose, si);
  r["end_twist"] = {{"ux", si.velocity(st.twist.ux)}, {"uy", si.velocity(st.twist.uy)}, {"omega", si.rate(st.twist.omega)}};
  r["census"] = planar_census_json(run.census);
  r["solver"] = {{"sweeps", st.sweeps}, {"newton_steps", st.newton_steps}};
  r["integrator"] = integrator_json(s.method, s.problem.integrator, run.integration,
                                    "Boost.Odeint runge_kutta_dopri5, controlled steps");
  if (s.method == Method::integrator) r["integrator"]["pivots"] = run.integration.pivots;
  return r;
}

}  // namespace selfalign
