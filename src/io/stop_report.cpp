// The stopping run's report (Sect. 7): io/stop_report.hpp.
#include "selfalign/io/stop_report.hpp"

#include <algorithm>
#include <cmath>

#include "selfalign/analysis/stick_position.hpp"
#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/io/summary_json.hpp"

namespace selfalign {

using nlohmann::json;

SimulateModel stopping_model(const SimulateConfig& config, const std::string& command) {
  SimulateConfig c = config;
  // friction as the config resolves it (a field_file alone implies field: simulate_config.cpp)
  const bool field = *resolve_simulate_config(config).friction == "field";
  if (config.friction && *config.friction == "uniform")
    throw InvalidParameter("friction", "uniform",
                           command + " needs a rise of friction: two-region or field");
  if (!field) c.friction = "two-region";
  c.method = "exact";
  return build_simulate_model(c);
}

json stopping_context_json(const SimulateModel& model, bool with_x_mu) {
  const OutputUnits u = model.output_units();
  json j;
  j["units"] = to_string(model.units);
  j["profile"] = model.profile->kind();
  if (const TwoRegionTable* f = model.friction->two_region()) {
    if (with_x_mu) j["x_mu"] = u.length(f->x_mu());
    j["width"] = u.length(f->width());
    j["c_mu"] = f->c_mu();
    return j;
  }
  // A field: the rise of its level stands for x_mu (stopping.hpp), no single c_mu.
  if (with_x_mu) j["x_mu"] = length_or_null(u, friction_rise(*model.friction));
  add_field_json(j, *model.friction, u);
  return j;
}

void add_field_json(json& j, const FrictionMap& field, const OutputUnits& u) {
  const FieldFriction* f = field.field_friction();
  const auto* uniform = f ? std::get_if<UniformFootprint>(&f->footprint()) : nullptr;
  j["width"] = uniform ? json(u.length(uniform->width)) : json(nullptr);
  j["c_mu"] = nullptr;
  j["friction"] = friction_json(field, u);
}

json length_or_null(const OutputUnits& u, double x) { return number_or_null(u.length(x)); }

json stop_report_json(const SimulateModel& model, const StoppingOptions& o, const StoppingRun& r) {
  const OutputUnits u = model.output_units();
  json j = stopping_context_json(model, true);
  const bool stopped = r.kind != StopKind::not_stopped;
  j["stop"] = to_string(r.kind);
  j["accumulation_proven"] = r.kind == StopKind::accumulation && r.accumulation_proven;
  j["law"] = law_json(model.law, u, model.scales.mu());
  // The solver of the run: the exact one, or the slip integrator for a Stribeck/viscous law.
  j["method"] = to_string(r.method);
  j["end_position"] = stopped ? json(u.length(r.end_position)) : json(nullptr);
  j["process_time"] = stopped ? number_or_null(u.time(r.process_time)) : json(nullptr);
  j["entry_time"] = number_or_null(u.time(r.entry_time));
  j["x_stick_min"] = length_or_null(u, r.x_stick_min);
  j["stick_positions"] = json::array();
  for (double x : r.stick_positions) j["stick_positions"].push_back(u.length(x));
  j["fractions"] = json::array();
  // Where stopping_run measures the fractions from: x_mu, or the rise of a field's level.
  const double x_mu = friction_rise(*model.friction);
  for (std::size_t k = 0; k < o.fractions.size(); ++k) {
    const double p = o.fractions[k];
    const int periods = r.periods_to_fraction[k];
    j["fractions"].push_back(
        {{"p", p},
         {"position", length_or_null(u, x_mu + p * (r.x_stick_min - x_mu))},
         {"time", number_or_null(u.time(r.time_to_fraction[k]))},
         {"periods_from_entry", periods < 0 ? json(nullptr) : json(periods)}});
  }
  j["initial"] = {{"t", u.time(model.initial.t)},
                  {"x", u.length(model.initial.x)},
                  {"x_dot", u.velocity(model.initial.xd)}};
  j["max_periods"] = o.max_periods;
  return j;
}

double stop_trajectory_end(const StoppingRun& r, double t0, double period, int max_periods) {
  double end = t0 + max_periods * period;
  if (r.kind == StopKind::permanent_stick) end = r.process_time;
  if (r.kind == StopKind::accumulation) {
    double last = std::isnan(r.entry_time) ? t0 : r.entry_time;
    for (double t : r.time_to_fraction)
      if (std::isfinite(t)) last = std::max(last, t);
    end = last + period;
  }
  return end > t0 ? end : t0 + period;
}

}  // namespace selfalign
