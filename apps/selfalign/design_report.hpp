#pragma once
// Reading back a `selfalign design` report (cmd_design.cpp writes it) for `montecarlo --design`:
// the process it recommends and the request it was designed for, every key typed.

#include <optional>
#include <span>
#include <string>
#include <variant>

#include "selfalign/robust/process_uncertainty.hpp"

namespace selfalign::cli {

/// A request key of a design report ("request": {...}) and the montecarlo flag overriding it.
struct RequestKey {
  const char* key;   ///< e.g. "width_m"
  const char* flag;  ///< e.g. "--width"
  /// A number, or an optional coefficient (null in the report: not given, equal to mu).
  std::variant<double DesignRequest::*, std::optional<double> DesignRequest::*> field;
};
std::span<const RequestKey> design_request_keys();

/// What a design report holds that montecarlo evaluates.
struct DesignReport {
  Process process;        ///< profile.* and x_mu_m; jerk inf where the report has null
  DesignRequest request;  ///< request.*; mu_static, mu_backward empty where null
};

/// Reads the report at `path` (read_document, io/document.hpp: registered as the --design
/// input). Every key read must be there with its type: profile.period_s, stroke_m,
/// a2_m_per_s2, a3_m_per_s2 and x_mu_m numbers; profile.jerk_m_per_s3 a number or null (no jerk
/// limit); every request key a number (mu_static, mu_backward: or null). Throws
/// InvalidParameter naming the key (e.g. "profile.jerk_m_per_s3") and the file otherwise.
DesignReport read_design_report(const std::string& path);

}  // namespace selfalign::cli
