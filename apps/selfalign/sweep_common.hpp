#pragma once
// The parts every `selfalign sweep` subcommand shares: grid ranges "LO:HI:N", the common flags
// (config keys, --threads, --quiet, --log), the library's sweep options with a progress bar,
// and writing the CSV with its JSON summary. The subcommands are cmd_sweep_*.cpp.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "config_flags.hpp"
#include "progress_bar.hpp"
#include "selfalign/analysis/sweep.hpp"
#include "selfalign/io/npy.hpp"
#include "selfalign/io/simulate_model.hpp"

namespace selfalign::cli {

/// A grid "LO:HI:N": N values from LO to HI inclusive, in the run's unit system.
struct GridRange {
  std::string text;  ///< as typed
  double lo = 0, hi = 0;
  int n = 0;
};

/// Parses "LO:HI:N" (numbers LO, HI in C-locale; a whole number N >= 1). Throws
/// InvalidParameter(name, text, ...) otherwise.
GridRange parse_grid_range(const std::string& name, const std::string& text);

/// The grid's values, linear or log-spaced (library linear_grid / log_grid). LO and HI must be
/// in (0, 1e50] (every swept quantity is positive; kMaxMagnitude bounds every input):
/// throws InvalidParameter(name, text, "<what> must be > 0 ...").
std::vector<double> positive_grid(const std::string& name, const GridRange& range, bool log,
                                  const std::string& what);

/// {"lo", "hi", "n"} of a range.
nlohmann::json grid_json(const GridRange& range);

/// Number of results per Table 1 case, {"0": n0, ..., "5": n5}.
nlohmann::json case_counts(const std::vector<StickSlipCase>& cases);

/// The CSV `status` column of a cell: "ok", or "failed" when it could not be computed (its
/// numbers are then nan and the summary's "failures" says why).
inline const char* cell_status(const std::string& failure) {
  return failure.empty() ? "ok" : "failed";
}

/// The summary's account of cells that could not be computed: {"count": n, "first": [up to
/// kShownFailures of {..where(cell).., "failure": message}]}. One failing cell never aborts a
/// sweep; this is where it is reported.
template <class Cell, class Where>
nlohmann::json failures_json(const std::vector<Cell>& cells, const Where& where) {
  constexpr std::size_t kShownFailures = 10;  // enough to diagnose, short enough to read
  nlohmann::json first = nlohmann::json::array();
  std::size_t count = 0;
  for (const Cell& c : cells) {
    if (c.failure.empty()) continue;
    if (count++ < kShownFailures) {
      nlohmann::json j = where(c);
      j["failure"] = c.failure;
      first.push_back(std::move(j));
    }
  }
  return {{"count", count}, {"first", std::move(first)}};
}

/// Flags common to every sweep.
struct SweepFlags {
  std::shared_ptr<ConfigFlags> config;
  int threads = 0;
  bool quiet = false;
  bool log = false;
};

/// Adds the config-key flags (--out: the CSV) and --threads, --quiet, --log to `command`.
/// Only the keys a sweep reads get a flag: the three-phase profile's (the sweeps always run
/// three-phase profiles) except the `swept` ones, which the grid replaces, the law and the
/// scales; `keep` adds keys a sweep reads beyond those (positioning: width, c_mu).
std::shared_ptr<SweepFlags> add_sweep_flags(CLI::App& command,
                                            std::initializer_list<std::string_view> swept,
                                            std::vector<std::string_view> keep = {});

/// A (y2'', y3'') grid as given (the run's units) and in model units [-].
struct AccelerationGrid {
  GridRange r2, r3;                      // as parsed
  std::vector<double> a2, a3;            // as given (run's units)
  std::vector<double> a2_model, a3_model;  // dimensionless
};

/// Parses --a2-range / --a3-range (log-spaced when `log`) and converts them to model units.
AccelerationGrid acceleration_grid(const ProfileModel& model, const std::string& a2_range,
                                   const std::string& a3_range, bool log);

/// The (y2'', y3'') grid flags of the acceleration-plane sweeps: required --a2-range and
/// --a3-range (LO:HI:N), bound to the given strings.
void add_acceleration_range_flags(CLI::App& command, std::string& a2_range,
                                  std::string& a3_range);

/// The three-phase parameters of the config [-] with their unit system (the sweeps read Δt, Δy,
/// y2'', y3'' from them; --profile is ignored). A case-0 setting is not an error here.
ProfileModel sweep_model(const SimulateConfig& config);

/// The library's options: --threads, and progress reported to `bar`.
SweepOptions sweep_options(const SweepFlags& flags, ProgressBar& bar, const ProfileModel& model);

/// A progress bar on stderr, drawn when stderr is a terminal and --quiet was not given.
std::unique_ptr<ProgressBar> sweep_progress_bar(const SweepFlags& flags);

/// Where a sweep writes: the CSV to `out`, or stdout when not given; the summary to `summary`
/// (default <out without extension>.summary.json when out is given, else none; "-" for
/// stdout, which needs out).
struct SweepPaths {
  std::optional<std::string> csv;      ///< none: standard output
  std::optional<std::string> summary;  ///< none: not written
  bool summary_to_stdout = false;
};
/// Resolves and checks the paths (before any work is done). Throws InvalidParameter.
SweepPaths resolve_sweep_paths(const SimulateConfig& config);

/// A sweep's cells as named columns, built column by column (the smaller sweeps); records()
/// is the table every sweep writes.
class CellTable {
 public:
  void numbers(std::string name, std::vector<double> values);
  void integers(std::string name, std::vector<std::int64_t> values);
  void words(std::string name, std::vector<std::string> values);
  NpyRecords records() const { return npy_records(columns_); }

 private:
  std::vector<NpyColumn> columns_;
};

/// The table as CSV: the header (field names), then one line per row; numbers as csv_number
/// writes them, integers in decimal, words without their padding.
std::string csv_of(const NpyRecords& table);

/// Writes a sweep's table, one row per cell, and the summary: as CSV (csv_of; to standard
/// output without --out) or, for an --out path ending in ".npy", as the NumPy structured array
/// itself (io/npy.hpp: numbers float64 at full precision, flags and counts int64, the status
/// as bytes), readable by numpy.load without selfalign. The summary gains "csv_file" (the
/// table's path) and "format" ("csv" or "npy"); files are committed together (AtomicFileSet),
/// then standard output is written.
void write_sweep_outputs(const SweepPaths& paths, const NpyRecords& table, nlohmann::json summary,
                         const ProfileModel& model);

/// The sweep subcommands, added under `selfalign sweep` (cmd_sweep.cpp).
void add_sweep_accelerations_command(CLI::App& sweep);  // cmd_sweep_accelerations.cpp
enum class SweptParameter { period, stroke };
void add_sweep_family_command(CLI::App& sweep, SweptParameter swept);  // cmd_sweep_family.cpp
void add_sweep_positioning_command(CLI::App& sweep);  // cmd_sweep_positioning.cpp

}  // namespace selfalign::cli
