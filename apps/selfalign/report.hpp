#pragma once
// Formatting shared by the analysis subcommands: numbers for CSV and JSON, unit labels and a
// two-column table for human-readable output, and delivering a JSON report.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/io/simulate_config.hpp"
#include "selfalign/io/summary_json.hpp"
#include "selfalign/io/unit_system.hpp"

namespace selfalign::cli {

/// The value as a JSON number, or null for NaN and ±inf (JSON has neither): the library's
/// (io/summary_json.hpp).
using selfalign::number_or_null;


/// A CSV field: shortest text that reads back as the same double; "nan", "inf", "-inf".
std::string csv_number(double value);

/// "[-]" in dimensionless runs; in SI runs the unit of `d` ("s", "m", "m/s", "m/s^2"; "[-]"
/// for Dimension::none).
std::string unit_label(UnitSystem units, Dimension d);

/// A two-column text table: labels padded to a common width.
class TextTable {
 public:
  void row(std::string label, std::string value) {
    rows_.emplace_back(std::move(label), std::move(value));
  }
  std::string str() const;

 private:
  std::vector<std::pair<std::string, std::string>> rows_;
};

/// A JSON value as table text: numbers round-trip, null as "-", strings unquoted.
std::string table_text(const nlohmann::json& value);

/// Delivers a JSON report: to the file `out` when given (atomically; nothing printed; "-" is
/// standard output), else to stdout as JSON (as_json) or as the human-readable `table`. Throws
/// InvalidParameter for an empty path, a directory, an input file or a file that cannot be
/// written.
void deliver_report(const nlohmann::json& report, const std::string& table, bool as_json,
                    const std::optional<std::string>& out);

/// An extra output file beside the JSON report (design's --profile-csv, montecarlo's
/// --runs-csv): its flag, path and content.
struct ExtraFile {
  const char* flag;  ///< without dashes, e.g. "runs-csv"
  std::optional<std::string> path;
};

/// Checks, before any work, that --out and the extra file are writable paths of different
/// files, neither an input (require_output_path, io/run_files.hpp). Throws InvalidParameter
/// naming the flag.
void require_report_paths(const std::optional<std::string>& out, const ExtraFile& extra);

/// Writes the extra file (when extra.path) and the report to `out` together (AtomicFileSet);
/// otherwise as deliver_report.
void deliver_report_with_file(const nlohmann::json& report, const std::string& table,
                              bool as_json, const std::optional<std::string>& out,
                              const ExtraFile& extra, const std::string& content);

/// Where a command whose --out is a CSV (stop, accuracy, accumulation) writes: the CSV to
/// `out` (or none); the JSON report to `summary`, by default <out without extension>
/// .summary.json beside the CSV, or to stdout: as JSON with --json or --summary -, as the
/// table when neither out nor summary is given.
struct ReportPaths {
  std::optional<std::string> csv;     ///< none: no CSV; "-": standard output
  std::optional<std::string> report;  ///< none: standard output (when report_written)
  bool report_as_json = false;        ///< on standard output: JSON (else the table)
  bool report_written = true;         ///< false: no report (out = "-" took standard output)
};

/// Resolves and checks the paths before any work is done (resolve_output_paths). --json with
/// --summary FILE is misuse. Throws InvalidParameter.
ReportPaths resolve_report_paths(const SimulateConfig& config, bool as_json);

/// Writes the CSV (when paths.csv) and the report with "csv_file" added, committed together
/// (AtomicFileSet); then prints the report to stdout when it goes there.
void deliver_csv_and_report(const ReportPaths& paths, const std::string& csv,
                            nlohmann::json report, const std::string& table);

}  // namespace selfalign::cli
