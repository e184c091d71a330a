// `selfalign design`: from SI actuator limits and an object to the three-phase table profile
// that minimises the process time T_p subject to accumulation (Δx_d = 0) or a positioning
// tolerance (design/process_design.hpp). Reports the profile, v̄, T_p, the end position and its
// band, the motion case, and writes the profile sampled for a motion controller.

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "report.hpp"
#include "selfalign/design/process_design.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/units.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;

struct DesignFlags {
  DesignRequest request;
  bool as_json = false;
  std::optional<std::string> out, profile_csv;
  double sample_rate = 10'000;  // [Hz]
};

// One period of the recommended profile, SI: t [s], y [m], y' [m/s], y'' [m/s^2].
std::string profile_csv(const DesignRequest& q, const DesignResult& d, double rate) {
  const Scales sc(q.width, q.mu, q.gravity);
  const std::unique_ptr<TableProfile> recommended = recommended_profile(d);
  const TableProfile& profile = *recommended;
  const long long n = std::max(2LL, std::llround(d.period * rate));
  std::string csv = "t,y,y_dot,y_ddot\n";
  for (long long i = 0; i <= n; ++i) {
    const double t = d.period * static_cast<double>(i) / static_cast<double>(n);
    const TableState s = profile.state(sc.time_from_si(t));
    csv += csv_number(t) + ',' + csv_number(sc.length_to_si(s.y)) + ',' +
           csv_number(sc.velocity_to_si(s.yd)) + ',' + csv_number(sc.acceleration_to_si(s.ydd)) +
           '\n';
  }
  return csv;
}

json design_json(const DesignRequest& q, const DesignResult& d) {
  json j;
  j["units"] = "si";
  j["feasible"] = d.feasible;
  j["message"] = d.message;
  j["profile"] = {{"kind", std::isinf(d.jerk) ? "three-phase" : "jerk-limited-three-phase"},
                  {"jerk_m_per_s3", std::isinf(d.jerk) ? json(nullptr) : json(d.jerk)},
                  {"period_s", d.period}, {"frequency_hz", 1 / d.period},
                  {"stroke_m", d.stroke}, {"a2_m_per_s2", d.a2}, {"a3_m_per_s2", d.a3},
                  {"t1_s", d.t1}, {"t2_s", d.t2}, {"t3_s", d.t3}, {"y_ini_m", d.y_ini},
                  {"y_dot_ini_m_per_s", d.y_dot_ini}, {"velocity_peak_m_per_s", d.velocity_peak}};
  j["case"] = static_cast<int>(d.motion_case);
  j["case_name"] = describe(d.motion_case);
  j["v_bar_m_per_s"] = number_or_null(d.v_bar);
  j["x_mu_m"] = d.x_mu;
  j["end_position_m"] = d.end_position;
  j["error_band_m"] = d.error_band;
  j["process_time_s"] = number_or_null(d.process_time);
  j["stop"] = to_string(d.stop);
  j["requirement"] = q.tolerance == 0 ? "accumulation" : "tolerance";
  j["candidates"] = d.candidates;
  j["feasible_candidates"] = d.feasible_candidates;
  return j;
}

std::string design_table(const json& j) {
  TextTable t;
  for (const char* key : {"frequency_hz", "stroke_m", "a2_m_per_s2", "a3_m_per_s2",
                          "velocity_peak_m_per_s"})
    t.row(std::string("profile ") + key, table_text(j["profile"][key]));
  for (const char* key : {"case_name", "v_bar_m_per_s", "x_mu_m", "end_position_m",
                          "error_band_m", "process_time_s", "stop"})
    t.row(key, table_text(j[key]));
  return t.str();
}

void run_design(const DesignFlags& f) {
  if (f.out) require_output_path("out", *f.out);
  if (f.profile_csv) require_output_path("profile-csv", *f.profile_csv);
  if (f.out && f.profile_csv && *f.out == *f.profile_csv)
    throw InvalidParameter("profile-csv", *f.profile_csv, "must differ from --out");
  const DesignResult d = design_process(f.request);
  if (!d.feasible) throw std::runtime_error("design infeasible: " + d.message);
  const json report = design_json(f.request, d);
  if (f.profile_csv) {
    AtomicFileSet files;
    files.add(*f.profile_csv, profile_csv(f.request, d, f.sample_rate), "profile-csv");
    if (f.out) files.add(*f.out, report.dump(2) + "\n", "out");
    files.commit();
    if (!f.out) deliver_report(report, design_table(report), f.as_json, std::nullopt);
    return;
  }
  deliver_report(report, design_table(report), f.as_json, f.out);
}

}  // namespace

void add_design_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "design",
      "Recommend a three-phase table profile from SI actuator limits: minimise the process "
      "time T_p subject to accumulation (Δx_d = 0) or --tolerance. Reports the profile, v̄, "
      "T_p [s], the end position and its band, the motion case; --profile-csv writes one "
      "period (t,y,y_dot,y_ddot in s, m, m/s, m/s^2) for a motion controller. An infeasible "
      "request is an error naming the binding limit.");
  auto f = std::make_shared<DesignFlags>();
  DesignRequest& q = f->request;
  auto num = [&](const char* flag, double& field, const std::string& help) {
    sub->add_option(flag, field, help + " Default: " + format_number(field))->group("Request");
  };
  num("--mass", q.mass, "object mass [kg] (reported only).");
  num("--width", q.width, "object width [m], > 0.");
  num("--mu", q.mu, "low-friction coefficient mu_1 [-], > 0.");
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
                  "static friction coefficient [-], >= mu. Default: mu")
      ->group("Request");
  sub->add_option("--mu-backward", q.mu_backward,
                  "kinetic friction coefficient of backward slip [-], <= mu-static. Default: mu")
      ->group("Request");
  num("--tolerance", q.tolerance,
      "allowed positioning error Δx_d [m]; 0 requires accumulation (Δx_d = 0).");
  sub->add_option("--acceleration-grid", q.acceleration_grid,
                  "candidates per acceleration axis, in [2, 200]")->group("Search");
  sub->add_option("--period-grid", q.period_grid, "candidate periods, in [1, 100]")
      ->group("Search");
  sub->add_option("--stroke-grid", q.stroke_grid, "candidate strokes, in [1, 20]")
      ->group("Search");
  sub->add_option("--entries", q.entries,
                  "steady entries per candidate (Sect. 7.1), in [2, 1000]")
      ->group("Search");
  sub->add_flag("--json", f->as_json, "print the report as JSON")->group("Output");
  sub->add_option("--out", f->out, "write the JSON report to FILE")->type_name("FILE")->group("Output");
  sub->add_option("--profile-csv", f->profile_csv,
                  "write one period of the profile, sampled at --sample-rate, to FILE")
      ->type_name("FILE")
      ->group("Output");
  sub->add_option("--sample-rate", f->sample_rate,
                  "profile CSV sample rate [Hz], > 0, at most 1e7 rows a period "
                  "(sample-rate / frequency-min <= 1e7)")
      ->group("Output");
  sub->callback([f] {
    // One period has sample_rate / frequency rows; the slowest allowed frequency bounds it.
    constexpr double kMaxRows = 1e7;
    const double f_min = f->request.frequency_min;  // design_process checks it itself
    if (!(f->sample_rate > 0) || (f_min > 0 && !(f->sample_rate <= kMaxRows * f_min)))
      throw InvalidParameter("sample-rate", f->sample_rate,
                             "must be in (0, 1e7 x frequency-min]: one period at most 1e7 rows");
    run_design(*f);
  });
}

}  // namespace selfalign::cli
