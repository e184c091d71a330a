// The explorer's API (issue 26, item 1): the library's own front doors behind embind, with
// configs and results as JSON text so that the page and the native CLI speak the same keys.
//   simulate(configJson)  -> the CLI's `simulate --summary` JSON (io/summary_json.hpp) plus
//                            "trajectory": the CSV's columns as arrays (io/trajectory_csv.hpp)
//   steady(configJson)    -> the CLI's `steady --json` report (io/steady_report.hpp)
//   sweep(configJson, a2Lo, a2Hi, n2, a3Lo, a3Hi, n3)
//                         -> `sweep accelerations`' cells on a linear (y2'', y3'') grid (run
//                            units), row-major with a2 outer: {a2, a3, case_a_priori, case,
//                            v_bar, f} as arrays (null for NaN)
//   stop(configJson, maxPeriods)
//                         -> the CLI's `stop --json` report (io/stop_report.hpp) plus
//                            "trajectory" (as `stop --out`, at most 20000 samples) and "map": eq. (59) sampled between
//                            x_mu and past its fixed point (three-phase on the two-region table;
//                            else null)
//   regimes(requestJson)  -> the feeder's regime chart (`selfalign regimes --json` and its --csv
//                            rows as arrays); the request's keys are the CLI's flags with _
//                            (angle_min, angles, k_min, machine_numbers, mu_static, ...)
//   planar(configText, format)
//                         -> `selfalign planar simulate --json` for a planar config given as text
//                            ("toml" or "json"; docs/planar.md), plus "trajectory" (the --csv
//                            columns as arrays, in the config's units)
// Errors come back as {"error": "<the CLI's one-line message>"} rather than as exceptions.

#include <emscripten/bind.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <fstream>
#include <vector>
#include <optional>
#include <string>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "selfalign/analysis/sweep.hpp"
#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/io/simulate_config.hpp"
#include "selfalign/io/simulate_model.hpp"
#include "selfalign/analysis/stick_position.hpp"
#include "selfalign/io/planar_report.hpp"
#include "selfalign/io/profile_analyses.hpp"
#include "selfalign/io/regime_chart_report.hpp"
#include "selfalign/io/steady_report.hpp"
#include "selfalign/io/stop_report.hpp"
#include "selfalign/io/summary_json.hpp"
#include "selfalign/simulate/simulate.hpp"

namespace selfalign::wasm {
namespace {

// A config from JSON text, read as a config file's keys are (simulate_config_from_json).
SimulateConfig config_of(const std::string& text) {
  return simulate_config_from_json(nlohmann::json::parse(text), "config");
}

std::string error_json(const std::exception& e) {
  return nlohmann::json{{"error", e.what()}}.dump();
}

// The trajectory CSV's columns (io/trajectory_csv.hpp) as arrays in the run's units.
nlohmann::json trajectory_json(const Trajectory& tr, const OutputUnits& u) {
  nlohmann::json j;
  auto column = [&](const char* key, const std::vector<double>& v, double (OutputUnits::*f)(double) const) {
    std::vector<double> c(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) c[i] = (u.*f)(v[i]);
    j[key] = std::move(c);
  };
  column("t", tr.t, &OutputUnits::time);
  column("x", tr.x, &OutputUnits::length);
  column("x_dot", tr.xd, &OutputUnits::velocity);
  column("y", tr.y, &OutputUnits::length);
  column("y_dot", tr.yd, &OutputUnits::velocity);
  column("y_ddot", tr.ydd, &OutputUnits::acceleration);
  j["stick"] = tr.stick;
  return j;
}

std::string simulate_json(const std::string& config_text) {
  try {
    SimulateConfig config = config_of(config_text);
    config.out.reset();
    config.summary.reset();
    const SimulateModel model = build_simulate_model(config);
    SimulationOptions options = model.options;
    const SimulationResult result =
        simulate(*model.profile, *model.friction, model.law, model.initial, options);
    nlohmann::json j = simulate_summary_json(model, result, std::nullopt);
    j["trajectory"] = trajectory_json(result.trajectory, model.output_units());
    return j.dump();
  } catch (const std::exception& e) {
    return error_json(e);
  }
}

// As `selfalign steady --json`: a non-physical three-phase request is a result (case 0).
std::string steady_json(const std::string& config_text) {
  try {
    const SimulateConfig config = config_of(config_text);
    const ProfileModel model = build_profile_model(config, NonPhysicalProfile::allow);
    return steady_report_json(model, steady_state_of(model)).dump();
  } catch (const std::exception& e) {
    return error_json(e);
  }
}

// As `selfalign sweep accelerations --a2-range LO:HI:N --a3-range LO:HI:N` (linear grids).
std::string sweep_json(const std::string& config_text, double a2_lo, double a2_hi, int n2,
                       double a3_lo, double a3_hi, int n3) {
  try {
    const SimulateConfig config = config_of(config_text);
    const ProfileModel model = build_profile_model(config, NonPhysicalProfile::allow);
    if (!model.three_phase)
      throw InvalidParameter("profile", model.profile ? model.profile->kind() : "none",
                             "the acceleration sweep needs profile = three-phase");
    const std::vector<double> a2 = linear_grid(a2_lo, a2_hi, n2), a3 = linear_grid(a3_lo, a3_hi, n3);
    std::vector<double> a2m, a3m;
    for (double v : a2) a2m.push_back(model.to_model_units(Dimension::acceleration, v));
    for (double v : a3) a3m.push_back(model.to_model_units(Dimension::acceleration, v));
    SweepOptions o = sweep_options_of(model);
    o.threads = 1;
    const std::vector<AccelerationCell> cells =
        sweep_accelerations(model.three_phase->period, model.three_phase->stroke, a2m, a3m, o);
    const OutputUnits u = model.output_units();
    nlohmann::json j;
    j["a2"] = a2, j["a3"] = a3;
    for (const char* key : {"case_a_priori", "case", "v_bar", "f"}) j[key] = nlohmann::json::array();
    for (const AccelerationCell& c : cells) {
      j["case_a_priori"].push_back(static_cast<int>(c.predicted));
      j["case"].push_back(static_cast<int>(c.observed));
      j["v_bar"].push_back(number_or_null(u.velocity(c.v_bar)));
      j["f"].push_back(number_or_null(c.f));
    }
    return j.dump();
  } catch (const std::exception& e) {
    return error_json(e);
  }
}

// Eq. (59) on kMapSamples points from x_mu to past the fixed point (eq. 60), in the run's units;
// null unless the profile is three-phase and the table the paper's two-region one.
nlohmann::json stick_position_map_json(const SimulateModel& model) {
  constexpr int kMapSamples = 200;
  const ThreePhaseProfile* profile = model.profile->three_phase();
  const std::optional<TwoRegionTable> table = as_two_region_table(*model.friction);
  if (!profile || !table) return nullptr;
  const StickPositionMap map(*profile, *table);
  const double lo = table->x_mu(), fixed = map.fixed_point();
  const double hi = fixed + 0.25 * std::max(fixed - lo, table->width());
  const OutputUnits u = model.output_units();
  nlohmann::json j;
  j["fixed_point"] = length_or_null(u, fixed);
  j["x_n"] = nlohmann::json::array();
  j["x_next"] = nlohmann::json::array();
  for (int i = 0; i < kMapSamples; ++i) {
    const double x = lo + (hi - lo) * i / (kMapSamples - 1);
    j["x_n"].push_back(u.length(x));
    j["x_next"].push_back(length_or_null(u, map(x)));
  }
  return j;
}

// As `selfalign stop --json --max-periods N` (and its --out trajectory, sampled by simulate()).
std::string stop_json(const std::string& config_text, int max_periods) {
  try {
    const SimulateModel model = stopping_model(config_of(config_text), "stop");
    StoppingOptions options;
    options.max_periods = max_periods;
    options.integrator = model.options.integrator;
    const StoppingRun run =
        stopping_run(*model.profile, *model.friction, model.law, model.initial, options);
    nlohmann::json j = stop_report_json(model, options, run);
    // The trajectory of `stop --out`, thinned to at most kMaxStopSamples samples for the page
    // (a run that never stops spans max_periods periods).
    constexpr double kMaxStopSamples = 20000;
    SimulationOptions o = model.options;
    o.duration = stop_trajectory_end(run, model.initial.t, model.profile->period(), max_periods) -
                 model.initial.t;
    const double step = o.output_step > 0 ? o.output_step : model.profile->period() / 200;
    o.output_step = std::max(step, o.duration / kMaxStopSamples);
    j["trajectory"] = trajectory_json(
        simulate(*model.profile, *model.friction, model.law, model.initial, o).trajectory,
        model.output_units());
    j["map"] = stick_position_map_json(model);
    return j.dump();
  } catch (const std::exception& e) {
    return error_json(e);
  }
}

// The request's keys: the CLI's flag names with '_' for '-'; an unknown key is refused.
RegimeChartRequest regime_request_of(const nlohmann::json& j) {
  RegimeChartRequest r;
  r.threads = 1;
  if (!j.is_object()) throw InvalidParameter("request", j.dump(), "must be a JSON object");
  for (auto item = j.begin(); item != j.end(); ++item) {
    // (no structured binding: clang 14 cannot capture one in the lambda below)
    const std::string key = item.key();
    const nlohmann::json& value = item.value();
    auto number = [&](auto& target) {
      if (!value.is_number()) throw InvalidParameter(key, value.dump(), "must be a number");
      target = value.get<std::remove_reference_t<decltype(target)>>();
    };
    if (key == "angle_min") number(r.angle_min);
    else if (key == "angle_max") number(r.angle_max);
    else if (key == "angles") number(r.angles);
    else if (key == "k_min") number(r.k_min);
    else if (key == "k_max") number(r.k_max);
    else if (key == "machine_numbers") number(r.machine_numbers);
    else if (key == "incline") number(r.incline);
    else if (key == "mu_static") number(r.mu_static);
    else if (key == "mu_kinetic") number(r.mu_kinetic);
    else if (key == "periods") number(r.periods);
    else if (key == "steps_per_period") number(r.steps_per_period);
    else if (key == "restitution") number(r.restitution);
    else if (key == "method" && value.is_string()) r.method = value.get<std::string>();
    else
      throw InvalidParameter(key, value.dump(),
                             "not a key of a regime chart (angle_min, angle_max, angles, k_min, "
                             "k_max, machine_numbers, incline, mu_static, mu_kinetic, periods, "
                             "steps_per_period, method, restitution)");
  }
  return r;
}

// As `selfalign regimes --json --csv F` (single-threaded): the summary and the rows as arrays.
std::string regimes_json(const std::string& request_text) {
  try {
    const RegimeChartRequest request = regime_request_of(nlohmann::json::parse(request_text));
    const std::vector<FeederChartCell> cells = regime_chart(request);
    nlohmann::json j = regime_chart_summary_json(request, cells);
    nlohmann::json rows;
    for (const char* key : {"vibration_angle_rad", "machine_number", "throw_number", "regime",
                            "first_event", "lifted_off", "dimensionless_speed", "stick_fraction",
                            "flight_fraction", "status"})
      rows[key] = nlohmann::json::array();
    for (const FeederChartCell& c : cells) {
      rows["vibration_angle_rad"].push_back(c.vibration_angle);
      rows["machine_number"].push_back(c.machine_number);
      rows["throw_number"].push_back(number_or_null(c.throw_number));
      rows["regime"].push_back(feeder_regime_name(c.regime));
      rows["first_event"].push_back(feeder_event_name(c.run.first_event));
      rows["lifted_off"].push_back(c.run.lifted_off);
      rows["dimensionless_speed"].push_back(number_or_null(c.dimensionless_speed));
      rows["stick_fraction"].push_back(number_or_null(c.run.stick_fraction));
      rows["flight_fraction"].push_back(number_or_null(c.run.flight_fraction));
      rows["status"].push_back(c.failure.empty() ? "ok" : "failed");
    }
    j["rows"] = std::move(rows);
    return j.dump();
  } catch (const std::exception& e) {
    return error_json(e);
  }
}

// As `selfalign planar simulate --config F --json` (and its --csv columns): the config text is
// written to the module's in-memory file system and read as a file is (load_planar_config).
std::string planar_json(const std::string& config_text, const std::string& format) {
  try {
    if (format != "toml" && format != "json")
      throw InvalidParameter("format", format, "must be toml or json");
    const std::string path = "/planar." + format;
    std::ofstream(path, std::ios::binary | std::ios::trunc) << config_text;
    const PlanarSetup setup = load_planar_config(path);
    const PlanarTrajectory run = planar_simulate_run(setup);
    nlohmann::json j = planar_simulate_report_json(setup, run);
    j["config"] = nullptr;  // given as text
    j["unused_keys"] = setup.unused_keys;
    const PlanarUnits u{setup};
    nlohmann::json tr;
    auto column = [&](const char* key, const std::vector<double>& v, auto convert) {
      std::vector<double> c(v.size());
      for (std::size_t i = 0; i < v.size(); ++i) c[i] = convert(v[i]);
      tr[key] = std::move(c);
    };
    column("t", run.t, [&](double v) { return u.time(v); });
    column("x", run.x, [&](double v) { return u.length(v); });
    column("y", run.y, [&](double v) { return u.length(v); });
    column("angle_rad", run.angle, [](double v) { return v; });
    column("ux", run.ux, [&](double v) { return u.velocity(v); });
    column("uy", run.uy, [&](double v) { return u.velocity(v); });
    column("omega", run.omega, [&](double v) { return u.rate(v); });
    tr["mode"] = nlohmann::json::array();
    for (PatchMode m : run.mode) tr["mode"].push_back(patch_mode_name(m));
    j["trajectory"] = std::move(tr);
    return j.dump();
  } catch (const std::exception& e) {
    return error_json(e);
  }
}

}  // namespace
}  // namespace selfalign::wasm

EMSCRIPTEN_BINDINGS(selfalign) {
  emscripten::function("simulate", &selfalign::wasm::simulate_json);
  emscripten::function("steady", &selfalign::wasm::steady_json);
  emscripten::function("sweep", &selfalign::wasm::sweep_json);
  emscripten::function("stop", &selfalign::wasm::stop_json);
  emscripten::function("regimes", &selfalign::wasm::regimes_json);
  emscripten::function("planar", &selfalign::wasm::planar_json);
}
