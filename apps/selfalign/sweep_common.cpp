#include "sweep_common.hpp"

#include "selfalign/io/summary_json.hpp"

#include <charconv>
#include <cmath>
#include <iostream>
#include <variant>

#include "selfalign/error.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/io/profile_analyses.hpp"
#include "selfalign/overloaded.hpp"
#include "report.hpp"

namespace selfalign::cli {
namespace {

const char kRangeForm[] = "must be LO:HI:N with numbers LO, HI and a whole number N in [1, 1e7]";

// The whole of `text` as a number of type T (C locale).
template <class T>
bool parse_whole(std::string_view text, T& out) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc{} && end == text.data() + text.size();
}

}  // namespace

GridRange parse_grid_range(const std::string& name, const std::string& text) {
  GridRange r;
  r.text = text;
  const std::size_t first = text.find(':');
  const std::size_t second = first == std::string::npos ? first : text.find(':', first + 1);
  if (second == std::string::npos || text.find(':', second + 1) != std::string::npos)
    throw InvalidParameter(name, text, kRangeForm);
  const std::string_view all(text);
  if (!parse_whole(all.substr(0, first), r.lo) ||
      !parse_whole(all.substr(first + 1, second - first - 1), r.hi) ||
      !parse_whole(all.substr(second + 1), r.n) || r.n < 1 || r.n > kMaxGridPoints)
    throw InvalidParameter(name, text, kRangeForm);
  return r;
}

std::vector<double> positive_grid(const std::string& name, const GridRange& range, bool log,
                                  const std::string& what) {
  if (!(range.lo > 0 && range.hi > 0 && range.lo <= kMaxMagnitude && range.hi <= kMaxMagnitude))
    throw InvalidParameter(name, range.text, what + " must be > 0 (LO and HI in (0, 1e50])");
  return log ? log_grid(range.lo, range.hi, range.n) : linear_grid(range.lo, range.hi, range.n);
}

nlohmann::json grid_json(const GridRange& range) {
  return {{"lo", range.lo}, {"hi", range.hi}, {"n", range.n}};
}

nlohmann::json case_counts(const std::vector<StickSlipCase>& cases) {
  nlohmann::json counts;
  for (int c = 0; c <= 5; ++c) counts[std::to_string(c)] = 0;
  for (StickSlipCase c : cases) {
    auto& n = counts[std::to_string(static_cast<int>(c))];
    n = n.get<int>() + 1;
  }
  return counts;
}

std::shared_ptr<SweepFlags> add_sweep_flags(CLI::App& command,
                                            std::initializer_list<std::string_view> swept,
                                            std::vector<std::string_view> keep) {
  auto flags = std::make_shared<SweepFlags>();
  std::vector<KeyFlag> overrides = {
      {"out", "CSV file of the results (default: standard output); a path ending in .npy: the "
              "same columns as a NumPy structured array (numpy.load)"},
      {"summary", "summary JSON file, - for stdout (default: <out without extension>"
                  ".summary.json when out is given, else none)"}};
  for (std::string_view key : swept) overrides.push_back({key, ""});
  overrides = without_groups(std::move(overrides), {"profile"},
                             {"period", "stroke", "a2", "a3", "jerk"});
  flags->config = add_config_flags(command, without_uniform_table_keys(overrides, keep));
  command.add_option("--threads", flags->threads,
                     "worker threads, >= 0; 0: all cores (more are capped at the cores)")
      ->type_name("INT")
      ->group("Sweep");
  command.add_flag("--quiet", flags->quiet, "no progress bar (drawn only when stderr is a "
                                            "terminal)")
      ->group("Sweep");
  command.add_flag("--log", flags->log, "log-spaced grid values (default: linear)")
      ->group("Sweep");
  return flags;
}

ProfileModel sweep_model(const SimulateConfig& config) {
  SimulateConfig three_phase = config;
  three_phase.profile = "three-phase";
  return build_profile_model(three_phase, NonPhysicalProfile::allow);
}

SweepOptions sweep_options(const SweepFlags& flags, ProgressBar& bar, const ProfileModel& model) {
  SweepOptions o = sweep_options_of(model);
  o.threads = flags.threads;
  o.progress = [&bar](std::size_t done, std::size_t total) { bar.update(done, total); };
  return o;
}

std::unique_ptr<ProgressBar> sweep_progress_bar(const SweepFlags& flags) {
  return std::make_unique<ProgressBar>(std::cerr, !flags.quiet && stderr_is_terminal());
}

SweepPaths resolve_sweep_paths(const SimulateConfig& config) {
  SweepPaths paths;
  if (!config.out && !config.summary) return paths;  // CSV to stdout, no summary
  if (!config.out && *config.summary == "-")
    throw InvalidParameter("summary", "-",
                           "cannot share standard output with the CSV: give --out FILE.csv");
  const OutputPaths resolved = resolve_output_paths(config);
  paths.csv = resolved.trajectory;
  paths.summary_to_stdout = resolved.summary_to_stdout();
  if (!paths.summary_to_stdout) paths.summary = resolved.summary;
  return paths;
}

void CellTable::numbers(std::string name, std::vector<double> values) {
  columns_.push_back({std::move(name), std::move(values)});
}
void CellTable::integers(std::string name, std::vector<std::int64_t> values) {
  columns_.push_back({std::move(name), std::move(values)});
}
void CellTable::words(std::string name, std::vector<std::string> values) {
  columns_.push_back({std::move(name), std::move(values)});
}

std::string csv_of(const NpyRecords& table) {
  const std::vector<NpyField>& fields = table.fields();
  std::string out;
  for (const NpyField& f : fields) out += (out.empty() ? "" : ",") + f.name;
  out += '\n';
  for (std::size_t r = 0; r < table.rows(); ++r) {
    for (std::size_t k = 0; k < fields.size(); ++k) {
      if (k > 0) out += ',';
      switch (fields[k].kind) {
        case NpyKind::float64: out += csv_number(table.number(r, k)); break;
        case NpyKind::int64: out += std::to_string(table.integer(r, k)); break;
        case NpyKind::bytes: out += table.word(r, k); break;
      }
    }
    out += '\n';
  }
  return out;
}

void write_sweep_outputs(const SweepPaths& paths, const NpyRecords& table, nlohmann::json summary,
                         const ProfileModel& model) {
  const bool npy = paths.csv && paths.csv->size() > 4 &&
                   paths.csv->compare(paths.csv->size() - 4, 4, ".npy") == 0;
  const std::string csv = npy ? std::string() : csv_of(table);
  const std::string_view content = npy ? table.file() : std::string_view(csv);
  summary["csv_file"] = paths.csv ? nlohmann::json(*paths.csv) : nlohmann::json(nullptr);
  summary["format"] = npy ? "npy" : "csv";
  summary["law"] = law_json(model.law, model.output_units(), model.scales.mu());
  // Every cell's solver, unless the sweep said (accelerations: "closed form"): the exact ones,
  // or the slip integrator under a Stribeck/viscous law.
  if (!summary.contains("method"))
    summary["method"] = model.law.velocity_dependent() ? "integrator" : "exact";
  const std::string summary_text = summary.dump(2) + "\n";
  AtomicFileSet files;
  if (paths.csv) files.add(*paths.csv, content, "out");
  if (paths.summary) files.add(*paths.summary, summary_text, "summary");
  files.commit();
  if (!paths.csv) std::cout << content << std::flush;
  if (paths.summary_to_stdout) std::cout << summary_text << std::flush;
}

void add_acceleration_range_flags(CLI::App& command, std::string& a2_range,
                                  std::string& a3_range) {
  command
      .add_option("--a2-range", a2_range,
                  "y2'' grid LO:HI:N (N values, LO, HI > 0). Unit: [-], SI [m/s^2]")
      ->type_name("LO:HI:N")
      ->required()
      ->group("Sweep");
  command
      .add_option("--a3-range", a3_range,
                  "y3'' grid LO:HI:N (N values, LO, HI > 0). Unit: [-], SI [m/s^2]")
      ->type_name("LO:HI:N")
      ->required()
      ->group("Sweep");
}

AccelerationGrid acceleration_grid(const ProfileModel& model, const std::string& a2_range,
                                   const std::string& a3_range, bool log) {
  AccelerationGrid g;
  g.r2 = parse_grid_range("a2-range", a2_range);
  g.r3 = parse_grid_range("a3-range", a3_range);
  if (static_cast<double>(g.r2.n) * g.r3.n > kMaxGridPoints)
    throw InvalidParameter("a2-range, a3-range", a2_range + ", " + a3_range,
                           "the grid has N2 x N3 cells, at most 1e7");
  g.a2 = positive_grid("a2-range", g.r2, log, "y2''");
  g.a3 = positive_grid("a3-range", g.r3, log, "y3''");
  for (double v : g.a2) g.a2_model.push_back(model.to_model_units(Dimension::acceleration, v));
  for (double v : g.a3) g.a3_model.push_back(model.to_model_units(Dimension::acceleration, v));
  return g;
}

}  // namespace selfalign::cli
