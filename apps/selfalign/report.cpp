#include "report.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "selfalign/error.hpp"
#include "selfalign/io/atomic_file.hpp"

namespace selfalign::cli {

std::string csv_number(double value) { return format_number(value); }

std::string unit_label(UnitSystem units, Dimension d) {
  if (units == UnitSystem::dimensionless) return "[-]";
  switch (d) {
    case Dimension::length: return "m";
    case Dimension::time: return "s";
    case Dimension::velocity: return "m/s";
    case Dimension::acceleration: return "m/s^2";
    case Dimension::jerk: return "m/s^3";
    case Dimension::rate: return "1/s";
    case Dimension::none: break;
  }
  return "[-]";
}

std::string TextTable::str() const {
  std::size_t width = 0;
  for (const auto& [label, value] : rows_) width = std::max(width, label.size());
  std::string text;
  for (const auto& [label, value] : rows_)
    text += label + std::string(width - label.size() + 2, ' ') + value + '\n';
  return text;
}

std::string table_text(const nlohmann::json& value) {
  if (value.is_null()) return "-";
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_float()) return format_number(value.get<double>());
  return value.dump();
}

void deliver_report(const nlohmann::json& report, const std::string& table, bool as_json,
                    const std::optional<std::string>& out) {
  const std::string text = report.dump(2) + "\n";
  if (out) {
    write_file_atomically(*out, text, "out");  // "-": standard output
    return;
  }
  std::cout << (as_json ? text : table) << std::flush;
}

void require_report_paths(const std::optional<std::string>& out, const ExtraFile& extra) {
  if (out) require_output_path("out", *out);
  if (extra.path) require_output_path(extra.flag, *extra.path);  // also: not the file of --out
}

void deliver_report_with_file(const nlohmann::json& report, const std::string& table,
                              bool as_json, const std::optional<std::string>& out,
                              const ExtraFile& extra, const std::string& content) {
  if (!extra.path) return deliver_report(report, table, as_json, out);
  AtomicFileSet files;
  files.add(*extra.path, content, extra.flag);
  if (out) files.add(*out, report.dump(2) + "\n", "out");
  files.commit();
  if (!out) deliver_report(report, table, as_json, std::nullopt);
}

ReportPaths resolve_report_paths(const SimulateConfig& config, bool as_json) {
  const OutputPaths resolved = resolve_output_paths(config);
  ReportPaths paths;
  paths.csv = resolved.trajectory;
  if (as_json && config.summary && !resolved.summary_to_stdout())
    throw InvalidParameter("summary", *config.summary,
                           "cannot be combined with --json (which prints the report)");
  const bool csv_to_stdout = paths.csv && *paths.csv == "-";
  if (csv_to_stdout && as_json)
    throw InvalidParameter("json", "given",
                           "cannot share standard output with out = -; give --summary FILE");
  if (!resolved.summary) paths.report_written = false;  // out = "-": the CSV has stdout
  if (!as_json && resolved.summary && !resolved.summary_to_stdout())
    paths.report = resolved.summary;
  paths.report_as_json = as_json || config.summary.has_value();
  return paths;
}

void deliver_csv_and_report(const ReportPaths& paths, const std::string& csv,
                            nlohmann::json report, const std::string& table) {
  report["csv_file"] = paths.csv ? nlohmann::json(*paths.csv) : nlohmann::json(nullptr);
  const std::string text = report.dump(2) + "\n";
  AtomicFileSet files;  // "-" is standard output, written after the files
  if (paths.csv) files.add(*paths.csv, csv, "out");
  if (paths.report) files.add(*paths.report, text, "summary");
  files.commit();
  if (!paths.report && paths.report_written)
    std::cout << (paths.report_as_json ? text : table) << std::flush;
}

}  // namespace selfalign::cli
