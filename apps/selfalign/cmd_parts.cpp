// `selfalign parts simulate | stop`: a queue of 1-D parts on the table (docs/rows.md), read from
// a config with a list of parts ([[parts]]): conveyed on the table (clusters, mean velocities,
// throughput) or stopping at a friction step (end positions, process times, spacing,
// accumulation, positioning errors). Exact (the exact row solver) or Moreau's time stepping.
// Dimensionless units of the paper (Sect. 3.2).

#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "parts_config.hpp"
#include "report.hpp"
#include "selfalign/analysis/row.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/config_reader.hpp"
#include "selfalign/io/document.hpp"
#include "selfalign/io/run_files.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;

const DocumentKind kPartsDocument{"config", "--config", 3};

// The keys of the parts config (docs/rows.md, "The parts config"): [table], [friction], [run]
// and each [[parts]] entry.
constexpr KeySpec kPartsKeys[] = {
    {"table", "period", ValueType::number, Dimension::none, {}, {}, {}, "Δt [-], the paper's 1"},
    {"table", "stroke", ValueType::number, Dimension::none, {}, {}, {}, "Δy [-]"},
    {"table", "a2", ValueType::number, Dimension::none, {}, {}, {}, "y2'' [-] (> 0)"},
    {"table", "a3", ValueType::number, Dimension::none, {}, {}, {}, "y3'' [-] (> 0)"},
    {"friction", "step_position", ValueType::number, Dimension::none, {}, {}, {}, "x_mu [-]"},
    {"friction", "c_mu", ValueType::number, Dimension::none, {}, {}, {}, "level beyond the step"},
    {"run", "method", ValueType::text},
    {"run", "periods", ValueType::number, Dimension::none, {}, {}, {}, {}, KeyRole::setting},
    {"run", "max_periods", ValueType::number, Dimension::none, {}, {}, {}, {}, KeyRole::setting},
    {"run", "steps_per_period", ValueType::number, Dimension::none, {}, {}, {}, {}, KeyRole::setting},
    {"run", "samples_per_period", ValueType::number, Dimension::none, {}, {}, {}, {}, KeyRole::setting},
    {"run", "restitution", ValueType::number},
};
constexpr KeySpec kPartKeys[] = {
    {"", "length", ValueType::number}, {"", "mass", ValueType::number},
    {"", "mu_static", ValueType::number}, {"", "mu_kinetic", ValueType::number},
    {"", "mu_forward", ValueType::number}, {"", "mu_backward", ValueType::number},
    {"", "x", ValueType::number}, {"", "v", ValueType::number},
    {"", "count", ValueType::number}, {"", "pitch", ValueType::number},
};

// One [[parts]] entry: `count` parts (default 1) at `pitch` (default: the length) from x.
void read_part(const json& entry, std::size_t index, const std::string& file, RowQueue& q) {
  const std::string name = "parts[" + std::to_string(index) + "]";
  if (!entry.is_object()) throw InvalidParameter(name, document_value_text(entry), "must be a table (in " + file + ")");
  const KeyTable table{kPartKeys, "docs/rows.md"};
  try {
    const ConfigValues values = read_config_values(entry, table, file);
    const ConfigSection v(values, "", InputUnits());
    const double s = v.number("mu_static", 1.0);
    const double k = v.number("mu_kinetic", s);
    const double kf = v.number("mu_forward", k), kb = v.number("mu_backward", k);
    FrictionLaw law;
    try {
      law = FrictionLaw(s, kf, kb);
    } catch (const InvalidParameter& e) {
      throw InvalidParameter("friction (" + e.name() + ")", e.value(), e.allowed());
    }
    const RowPart p{v.number("length", 0.3), v.number("mass", 1.0), law, v.number("x", 0.0),
                    v.number("v", 0.0)};
    const int count = v.integer("count", 1, 1, 100000);
    const double pitch = v.number("pitch", p.length);  // checked for repeated parts only
    if (count > 1 && !(std::isfinite(pitch) && pitch > 0))
      throw InvalidParameter("pitch", pitch, "must be > 0");
    for (int c = 0; c < count; ++c) {
      RowPart one = p;
      one.x = p.x + static_cast<double>(c) * pitch;
      q.parts.push_back(one);
    }
  } catch (const InvalidParameter& e) {
    throw InvalidParameter(name + "." + e.name(), e.value(), e.allowed());
  }
}

}  // namespace

PartsSetup read_parts_config(const PartsFlags& f) {
  json doc = read_document(f.config, kPartsDocument);
  PartsSetup s;
  if (!doc.contains("parts") || !doc["parts"].is_array() || doc["parts"].empty())
    throw InvalidParameter("parts", f.config, "the config needs a list of parts ([[parts]] tables)");
  const json parts = doc["parts"];
  doc.erase("parts");
  const KeyTable table{kPartsKeys, "docs/rows.md"};
  const ConfigValues v = read_config_values(doc, table, f.config);
  const ConfigSection tab(v, "table", InputUnits()), fr(v, "friction", InputUnits()),
      run(v, "run", InputUnits());
  s.table = {tab.number("period", 1.0), tab.number("stroke", 0.084), tab.number("a2", 3.0),
             tab.number("a3", 0.9)};
  if (fr.has("step_position")) s.step_position = fr.number("step_position", 0);
  s.c_mu = fr.number("c_mu", 2.5);
  if (run.has("method")) s.solver.method = parse_method(run.text("method", ""));
  s.solver.steps_per_period = run.integer("steps_per_period", 2000, 1, 1'000'000'000);
  s.periods = run.integer("periods", 20, 1, 100'000'000);
  s.max_periods = run.integer("max_periods", 1000, 1, 100'000'000);
  s.samples = run.integer("samples_per_period", 20, 1, 100'000);
  s.queue.restitution = run.number("restitution", 0.0);
  for (std::size_t i = 0; i < parts.size(); ++i) read_part(parts[i], i, f.config, s.queue);
  // flags override the config
  if (f.method) s.solver.method = parse_method(*f.method);
  if (f.periods) s.periods = *f.periods;
  if (f.max_periods) s.max_periods = *f.max_periods;
  if (f.steps_per_period) s.solver.steps_per_period = *f.steps_per_period;
  if (f.samples_per_period) s.samples = *f.samples_per_period;
  if (f.restitution) s.queue.restitution = *f.restitution;
  return s;
}

namespace {

json numbers(const std::vector<double>& v) {
  json a = json::array();
  for (const double x : v) a.push_back(number_or_null(x));
  return a;
}

std::string trajectory_csv(const std::vector<double>& times,
                           const std::vector<std::vector<double>>& positions) {
  std::ostringstream o;
  o << "t";
  const std::size_t n = positions.empty() ? 0 : positions[0].size();
  for (std::size_t i = 0; i < n; ++i) o << ",x" << i;
  o << "\n";
  for (std::size_t k = 0; k < times.size(); ++k) {
    o << csv_number(times[k]);
    for (const double x : positions[k]) o << "," << csv_number(x);
    o << "\n";
  }
  return o.str();
}

void check_flags(const PartsFlags& f) {
  if (f.frequency && !(std::isfinite(*f.frequency) && *f.frequency > 0))
    throw InvalidParameter("--frequency", *f.frequency, "must be > 0 [Hz]");
  require_report_paths(f.out, {"csv", f.csv});
}

void run_parts_simulate(const PartsFlags& f) {
  check_flags(f);
  const PartsSetup s = read_parts_config(f);
  const ThreePhaseProfile profile(s.table);
  std::optional<FrictionField> field;
  if (s.step_position) field = FrictionField::steps({*s.step_position}, {1.0, s.c_mu});
  const RowRun r = row_run(profile, s.queue, field ? &*field : nullptr, s.periods, s.solver, s.samples);
  json j;
  j["method"] = to_string(s.solver.method);
  j["steps_per_period"] = s.solver.method == Method::exact ? json(nullptr) : json(s.solver.steps_per_period);
  j["periods"] = s.periods;
  j["parts"] = s.queue.parts.size();
  j["x"] = numbers(r.x);
  j["v"] = numbers(r.v);
  j["mean_velocity"] = numbers(r.mean_velocity);
  j["queue_velocity"] = number_or_null(r.queue_velocity);
  j["clusters"] = r.clusters;
  j["pitch"] = number_or_null(r.pitch);
  j["throughput_per_period"] = number_or_null(r.throughput_per_period);
  j["parts_per_minute"] =
      f.frequency ? number_or_null(r.throughput_per_period * 60.0 * *f.frequency) : json(nullptr);
  j["collisions"] = s.solver.method == Method::exact ? json(r.collisions) : json(nullptr);
  j["separations"] = s.solver.method == Method::exact ? json(r.separations) : json(nullptr);
  TextTable t;
  t.row("parts", std::to_string(s.queue.parts.size()));
  t.row("method", table_text(j["method"]));
  t.row("queue velocity [-]", table_text(j["queue_velocity"]));
  t.row("clusters (rear to front)", j["clusters"].dump());
  t.row("pitch [-]", table_text(j["pitch"]));
  t.row("throughput [parts per period]", table_text(j["throughput_per_period"]));
  t.row("throughput [parts per minute]", table_text(j["parts_per_minute"]));
  deliver_report_with_file(j, t.str(), f.as_json, f.out, {"csv", f.csv},
                           trajectory_csv(r.times, r.positions));
}

void run_parts_stop(const PartsFlags& f) {
  check_flags(f);
  const PartsSetup s = read_parts_config(f);
  if (!s.step_position)
    throw InvalidParameter("friction.step_position", "missing", "a stopping run needs the friction step (in " + f.config + ")");
  const ThreePhaseProfile profile(s.table);
  const FrictionField field = FrictionField::steps({*s.step_position}, {1.0, s.c_mu});
  const RowStop r = row_stop(profile, s.queue, field, s.max_periods, s.solver, s.samples);
  json j;
  j["method"] = to_string(s.solver.method);
  j["steps_per_period"] = s.solver.method == Method::exact ? json(nullptr) : json(s.solver.steps_per_period);
  j["stopped"] = r.stopped;
  j["stop_time"] = number_or_null(r.stop_time);
  j["periods"] = r.periods;
  j["x"] = numbers(r.x);
  j["process_time"] = numbers(r.process_time);
  j["gaps"] = numbers(r.gaps);
  j["accumulated"] = r.accumulated;
  j["error"] = numbers(r.error);
  j["step_position"] = *s.step_position;
  j["collisions"] = s.solver.method == Method::exact ? json(r.collisions) : json(nullptr);
  j["separations"] = s.solver.method == Method::exact ? json(r.separations) : json(nullptr);
  TextTable t;
  t.row("parts", std::to_string(s.queue.parts.size()));
  t.row("method", table_text(j["method"]));
  t.row("stopped", r.stopped ? "yes" : "no (max periods reached)");
  t.row("stop time [-]", table_text(j["stop_time"]));
  t.row("end positions [-]", j["x"].dump());
  t.row("positioning errors [-]", j["error"].dump());
  t.row("gaps [-]", j["gaps"].dump());
  t.row("accumulated behind the first part", r.accumulated ? "yes" : "no");
  deliver_report_with_file(j, t.str(), f.as_json, f.out, {"csv", f.csv},
                           trajectory_csv(r.times, r.positions));
}

void add_common(CLI::App* sub, PartsFlags& f) {
  sub->add_option("--config", f.config,
                  "the queue: [table] (three-phase profile), [friction], [run] and one "
                  "[[parts]] table per part or group of parts (docs/rows.md)")
      ->required()
      ->type_name("FILE");
  sub->add_option("--method", f.method, "exact (default) or time-stepping (Moreau)");
  sub->add_option("--steps-per-period", f.steps_per_period, "Moreau's steps per period (2000)");
  sub->add_option("--samples-per-period", f.samples_per_period,
                  "trajectory samples per period in the CSV (20)");
  sub->add_option("--restitution", f.restitution, "Newton's e between parts, in [0, 1] (0)");
  sub->add_flag("--json", f.as_json, "print the report as JSON (default: a table)");
  sub->add_option("--out", f.out, "write the JSON report to FILE (nothing printed)")
      ->type_name("FILE")
      ->group("Output");
  sub->add_option("--csv", f.csv, "write the sampled trajectories (t, x0, x1, ...) to FILE")
      ->type_name("FILE")
      ->group("Output");
}

}  // namespace

void add_parts_command(CLI::App& app) {
  CLI::App* parts = app.add_subcommand(
      "parts",
      "A queue of parts on the table (docs/rows.md): parts that push, collide and stop "
      "together, solved exactly (event-driven, closed-form arcs) or by Moreau's time stepping");
  parts->require_subcommand(1);
  auto f = std::make_shared<PartsFlags>();
  CLI::App* sim = parts->add_subcommand(
      "simulate",
      "Convey the queue for --periods periods: each part's end state and mean velocity, the "
      "clusters of touching parts, the throughput at the queue's pitch");
  add_common(sim, *f);
  sim->add_option("--periods", f->periods, "periods to run (20)");
  sim->add_option("--frequency", f->frequency,
                  "the table's frequency [Hz]: adds the throughput in parts per minute");
  sim->callback([f] { run_parts_simulate(*f); });
  auto g = std::make_shared<PartsFlags>();
  CLI::App* stop = parts->add_subcommand(
      "stop",
      "Run the queue until it stops at the friction step ([friction] step_position, c_mu): "
      "each part's end position, process time and positioning error, the gaps, whether the "
      "queue accumulates behind the first part");
  add_common(stop, *g);
  stop->add_option("--max-periods", g->max_periods, "periods before the queue is reported as not stopped (1000)");
  stop->callback([g] { run_parts_stop(*g); });
  add_parts_montecarlo_command(*parts);
}

}  // namespace selfalign::cli
