#include "selfalign/io/summary_json.hpp"

#include <cmath>

#include "selfalign/profiles/fourier.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {
namespace {

using nlohmann::json;

json profile_json(const TableProfile& p, const OutputUnits& u) {
  json j = {{"kind", p.kind()},
            {"period", u.time(p.period())},                       // Δt [-] | [s]
            {"stroke", u.length(p.stroke())},                     // Δy [-] | [m]
            {"peak_acceleration", u.acceleration(p.peak_acceleration())}};  // [-] | [m/s^2]
  if (const ThreePhaseProfile* tp = p.three_phase()) {
    const ThreePhaseParameters& a = tp->parameters();
    const ThreePhaseSolution& s = tp->solution();  // Appendix, eqs. (61)-(67)
    j["a2"] = u.acceleration(a.a2);
    j["a3"] = u.acceleration(a.a3);
    j["t1"] = u.time(s.t1);
    j["t2"] = u.time(s.t2);
    j["t3"] = u.time(s.t3);
    j["y_ini"] = u.length(s.y_ini);
    j["y_dot_ini"] = u.velocity(s.yd_ini);
  } else if (const FourierProfile* fp = p.smooth() ? p.smooth()->fourier_series() : nullptr) {
    json cos = json::array(), sin = json::array();
    for (double c : fp->cos_coeffs()) cos.push_back(u.length(c));
    for (double s : fp->sin_coeffs()) sin.push_back(u.length(s));
    j["fourier_cos"] = cos;
    j["fourier_sin"] = sin;
  } else if (const PiecewisePolynomialProfile* pc = p.piecewise_polynomial()) {
    json durations = json::array(), accelerations = json::array();
    const auto segments = pc->segments();
    for (const AccelerationSegment& s : segments) {
      durations.push_back(u.time(s.duration));
      accelerations.push_back(u.acceleration(s.accel));
    }
    j["durations"] = durations;
    j["accelerations"] = accelerations;
  }
  return j;
}


json state_json(const ObjectState& s, const OutputUnits& u) {
  return {{"t", u.time(s.t)}, {"x", u.length(s.x)}, {"x_dot", u.velocity(s.xd)}};
}

json scales_json(const SimulateModel& m) {
  if (m.units != UnitSystem::si) return nullptr;
  const Scales& s = m.scales;
  return {{"length_m", s.length()},
          {"time_s", s.time()},
          {"velocity_m_per_s", s.velocity()},
          {"acceleration_m_per_s2", s.acceleration()},
          {"mu", s.mu()},
          {"g", s.gravity()},
          {"mass_kg", m.mass}};
}

}  // namespace

json number_or_null(double value) {
  return std::isfinite(value) ? json(value) : json(nullptr);
}

json friction_json(const FrictionMap& f, const OutputUnits& u) {
  if (const TwoRegionTable* two = f.two_region())
    return {{"kind", "two-region"},
            {"x_mu", u.length(two->x_mu())},    // [-] | [m]
            {"width", u.length(two->width())},  // [-] | [m]
            {"c_mu", two->c_mu()}};             // [-]
  if (const FieldFriction* field = f.field_friction()) {
    const auto* uniform = std::get_if<UniformFootprint>(&field->footprint());
    return {{"kind", "field"},
            {"x_mu", nullptr},
            {"width", uniform ? json(u.length(uniform->width)) : json(nullptr)},
            {"c_mu", nullptr},
            {"footprint", uniform ? "uniform" : "point"},
            {"field_nodes", field->field().nodes().size()},
            {"exact", field->piecewise_affine() != nullptr}};
  }
  return {{"kind", "uniform"}, {"x_mu", nullptr}, {"width", nullptr}, {"c_mu", nullptr}};
}

json law_json(const FrictionLaw& law, const OutputUnits& u, double mu) {
  const bool stribeck = law.stribeck_velocity() > 0;
  return {{"mu", mu},  // the coefficients as given (absolute) [-]
          {"mu_static", mu * law.static_coefficient()},
          {"mu_backward", mu * law.kinetic_backward()},
          {"static", law.static_coefficient()},  // ratios to mu [-]
          {"kinetic_forward", law.kinetic_forward()},
          {"kinetic_backward", law.kinetic_backward()},
          {"stribeck_velocity", stribeck ? json(u.velocity(law.stribeck_velocity())) : json(nullptr)},
          {"stribeck_exponent", stribeck ? json(law.stribeck_exponent()) : json(nullptr)},
          {"viscous", law.viscous() > 0 ? json(law.viscous() / u.time(1.0)) : json(nullptr)}};
}

json integrator_json(Method method, const IntegratorOptions& options,
                     const IntegratorStatistics& stats, const char* stepper) {
  if (method != Method::integrator) return nullptr;
  return {{"stepper", stepper},
          {"relative_tolerance", options.relative_tolerance},
          {"absolute_tolerance", options.absolute_tolerance},
          {"steps", stats.steps},
          {"rejected", stats.rejected},
          {"rhs_evaluations", stats.rhs_evaluations},
          {"events", stats.events}};
}

json simulate_summary_json(const SimulateModel& model, const SimulationResult& result,
                           const std::optional<std::string>& trajectory_file) {
  const OutputUnits u = model.output_units();
  json j;
  j["units"] = to_string(model.units);
  j["method"] = to_string(result.method);  // integrator where exact met a speed-dependent law
  j["profile"] = profile_json(*model.profile, u);
  j["friction"] = friction_json(*model.friction, u);
  j["law"] = law_json(model.law, u, model.scales.mu());
  j["initial"] = state_json(model.initial, u);
  j["final"] = state_json(result.final_state, u);
  j["periods"] = model.periods;
  j[result.method == Method::time_stepping ? "steps"
    : result.method == Method::exact       ? "arcs"
                                           : "intervals"] = result.work;
  j["integrator"] = integrator_json(result.method, model.options.integrator, result.integrator);
  j["mean_velocity_last_period"] = number_or_null(u.velocity(result.mean_velocity_last_period));
  j["stick_fraction"] = result.stick_fraction;  // [-]
  j["scales"] = scales_json(model);
  j["trajectory_file"] = trajectory_file ? json(*trajectory_file) : json(nullptr);
  return j;
}

}  // namespace selfalign
