#include "robust_flags.hpp"

#include <cmath>

#include "report.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/uncertainty_file.hpp"
#include "warnings.hpp"

namespace selfalign::cli {

using nlohmann::json;

void add_request_flags(CLI::App* sub, DesignRequest& q) {
  auto num = [&](const char* flag, double& field, const std::string& help) {
    sub->add_option(flag, field, help + " Default: " + format_number(field))->group("Request");
  };
  num("--mass", q.mass, "object mass [kg] (reported only).");
  num("--width", q.width, "object width = transition width [m], > 0.");
  num("--mu", q.mu,
      "low-friction coefficient mu_1 [-], the kinetic one: --mu-static and --mu-backward are "
      "taken relative to it, > 0.");
  num("--c-mu", q.c_mu, "friction ratio mu_2/mu_1 of the stopping region [-], > 1.");
  num("--g", q.gravity, "gravitational acceleration [m/s^2].");
  num("--distance", q.distance, "desired end position from the start [m], > 0.");
  num("--stroke-max", q.stroke_max, "actuator stroke limit [m], > 0.");
  num("--frequency-min", q.frequency_min, "lowest table frequency [Hz], > 0.");
  num("--frequency-max", q.frequency_max, "highest table frequency [Hz].");
  num("--velocity-max", q.velocity_max, "table velocity limit [m/s], > 0.");
  num("--acceleration-max", q.acceleration_max, "table acceleration limit [m/s^2], > 0.");
  sub->add_option("--jerk-max", q.jerk_max,
                  "table jerk limit [m/s^3], > 0: each switch becomes a ramp at this jerk "
                  "(jerk-limited three-phase profile). Default: none (jump accelerations)")
      ->group("Request");
  sub->add_option("--mu-static", q.mu_static,
                  "static friction coefficient [-], absolute like --mu (give --mu with it), "
                  ">= mu. Default: mu")
      ->group("Request");
  sub->add_option("--mu-backward", q.mu_backward,
                  "kinetic friction coefficient of backward slip [-], absolute like --mu, "
                  "<= mu-static. Default: mu")
      ->group("Request");
  num("--tolerance", q.tolerance,
      "allowed positioning error Δx_d [m]; 0 requires accumulation (Δx_d = 0).");
}

ProcessUncertainty UncertaintyFlags::read() const {
  ProcessUncertainty u = file ? load_uncertainty(*file) : ProcessUncertainty{};
  for (const std::string& a : uncertain) {
    const auto eq = a.find('=');
    if (eq == std::string::npos)
      throw InvalidParameter("uncertain", a, "must be NAME=DIST, e.g. mu=normal:0.2,5%");
    set_input(u, a.substr(0, eq), a.substr(eq + 1));
  }
  validate(u);
  return u;
}

void add_uncertainty_flags(CLI::App* sub, UncertaintyFlags& f) {
  std::string names;
  for (const UncertainInput& in : uncertain_inputs())
    names += std::string(names.empty() ? "" : ", ") + in.name + " [" + in.unit + "]";
  sub->add_option("--uncertain", f.uncertain,
                  "an uncertain input, NAME=DIST (repeatable): NAME one of " + names +
                      "; DIST normal:MEAN,SD[,LOWER,UPPER] (SD may be a % of MEAN), "
                      "uniform:LOWER,UPPER, interval:LOWER,UPPER, samples:V1,V2,... or known")
      ->type_name("NAME=DIST")
      ->group("Uncertainty");
  sub->add_option("--uncertainty-file", f.file,
                  "a JSON or TOML file of NAME = \"DIST\" pairs; --uncertain overrides it")
      ->type_name("FILE")
      ->group("Uncertainty");
}

void add_monte_carlo_run_flags(CLI::App* sub, int& runs, std::uint64_t& seed,
                               std::uint64_t& first_run, int& threads) {
  sub->add_option("--runs", runs,
                  "Monte-Carlo runs, in [1, 1e7]. Default: " + std::to_string(runs))
      ->group("Monte Carlo");
  sub->add_option("--seed", seed, "seed of the draws. Default: 1")->group("Monte Carlo");
  sub->add_option("--first-run", first_run,
                  "index of the first run (a chunk of a larger study). Default: 0")
      ->group("Monte Carlo");
  sub->add_option("--threads", threads, "worker threads, >= 0 (0: all cores). Default: 0")
      ->group("Monte Carlo");
}

void warn_about_request(const DesignRequest& q, bool mu_given) {
  warn_default_mu(mu_given, q.mu, q.mu_static, q.mu_backward);
  warn_if_millimetres("--width", q.width, 1);
  warn_if_millimetres("--stroke-max", q.stroke_max, 1);
  warn_if_millimetres("--tolerance", q.tolerance, 1);
  warn_if_millimetres("--distance", q.distance, 10);
  warn_if_grams("--mass", q.mass);
}

bool any_uncertain(const ProcessUncertainty& u) {
  for (const UncertainInput& in : uncertain_inputs())
    if (is_uncertain(u.*in.member)) return true;
  return false;
}

json uncertainty_json(const DesignRequest& q, const ProcessUncertainty& u) {
  json j = json::object();
  for (const UncertainInput& in : uncertain_inputs())
    j[in.name] = {{"unit", in.unit},
                  {"distribution", describe(u.*in.member)},
                  {"nominal", nominal(u.*in.member, in.known(q))}};
  return j;
}

json fragility_json(const Fragility& f) {
  const auto ends = [](const std::array<double, 2>& e) {
    return json::array({number_or_null(e[0]), number_or_null(e[1])});
  };
  return {{"level", f.level},
          {"stop_margin", f.stop_margin},
          {"motion_margin", f.motion_margin},
          {"end_nominal_m", number_or_null(f.end_nominal)},
          {"end_m_with_mu_low_high", ends(f.end_mu)},
          {"end_m_with_c_mu_low_high", ends(f.end_c_mu)},
          {"end_m_with_mu_static_low_high", ends(f.end_static)},
          {"end_shift_mu_m", number_or_null(f.end_shift_mu)},
          {"end_shift_c_mu_m", number_or_null(f.end_shift_c_mu)},
          {"end_shift_mu_static_m", number_or_null(f.end_shift_static)},
          {"assumes_equal_static", f.assumes_equal_static},
          {"fragile", !f.warnings.empty()},
          {"warnings", f.warnings}};
}

json monte_carlo_json(const MonteCarloResult& r, double time_quantile, int bins) {
  json quantiles = json::object(), ends = json::object();
  for (double q : {0.5, 0.9, 0.99})
    quantiles[format_number(q)] = number_or_null(process_time_quantile(r, q));
  for (double q : {0.005, 0.05, 0.5, 0.95, 0.995})
    ends[format_number(q)] = number_or_null(end_position_quantile(r, q));
  const Histogram h = histogram(r.end_position, bins);
  return {{"runs", r.runs},
          {"seed", r.seed},
          {"first_run", r.first_run},
          {"target_m", r.target},
          {"tolerance_m", r.tolerance},
          {"stopped", r.stopped},
          {"within", r.within},
          {"never_entered", r.never_entered},
          {"p_stop", r.p_stop},
          {"p_within", r.p_within},
          {"p_within_95ci", {r.p_within_low, r.p_within_high}},
          {"process_time_quantiles_s", quantiles},
          {"time_quantile", time_quantile},
          {"process_time_at_quantile_s", number_or_null(process_time_quantile(r, time_quantile))},
          {"end_position_quantiles_m", ends},
          {"end_position_histogram", {{"edges_m", h.edges}, {"counts", h.counts}}}};
}

json worst_case_json(const WorstCase& w) {
  json box = json::object(), worst = json::object(), slowest = json::object();
  const auto& inputs = uncertain_inputs();
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    if (w.box[k].first == w.box[k].second) continue;
    box[inputs[k].name] = {w.box[k].first, w.box[k].second};
    worst[inputs[k].name] = w.worst_inputs[k];
    slowest[inputs[k].name] = w.slowest_inputs[k];
  }
  return {{"method", w.method},
          {"evaluations", w.evaluations},
          {"box", box},
          {"all_within", w.all_within},
          {"worst_error_m", number_or_null(w.worst_error)},
          {"worst_stops", w.worst.kind != StopKind::not_stopped},
          {"worst_end_position_m", number_or_null(w.worst.end_position)},
          {"worst_inputs", worst},
          {"slowest_process_time_s", number_or_null(w.slowest_time)},
          {"slowest_inputs", slowest}};
}

std::string monte_carlo_csv(const MonteCarloResult& r) {
  std::string csv = "run";
  for (const UncertainInput& in : uncertain_inputs())
    csv += "," + std::string(in.name) + (std::string(in.unit) == "m" ? "_m" : "");
  csv += ",stop,end_position_m,process_time_s,entry_time_s\n";
  for (std::size_t i = 0; i < r.kind.size(); ++i) {
    csv += std::to_string(r.first_run + i);
    for (const auto& column : r.inputs) csv += "," + csv_number(column[i]);
    csv += std::string(",") + to_string(r.kind[i]) + "," + csv_number(r.end_position[i]) + "," +
           csv_number(r.process_time[i]) + "," + csv_number(r.entry_time[i]) + "\n";
  }
  return csv;
}

}  // namespace selfalign::cli
