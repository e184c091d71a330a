#include "design_report.hpp"

#include <cmath>
#include <limits>

#include "selfalign/error.hpp"
#include "selfalign/io/document.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;

// A report nests 5 levels (robust.verification.end_position_histogram.edges_m); 8 leaves room
// for new sections.
const DocumentKind kDesignReport{"design", "--design", 8};

constexpr RequestKey kRequestKeys[] = {
    {"mass_kg", "--mass", &DesignRequest::mass},
    {"width_m", "--width", &DesignRequest::width},
    {"mu", "--mu", &DesignRequest::mu},
    {"c_mu", "--c-mu", &DesignRequest::c_mu},
    {"g_m_per_s2", "--g", &DesignRequest::gravity},
    {"mu_static", "--mu-static", &DesignRequest::mu_static},
    {"mu_backward", "--mu-backward", &DesignRequest::mu_backward},
    {"distance_m", "--distance", &DesignRequest::distance},
    {"tolerance_m", "--tolerance", &DesignRequest::tolerance},
};

// The typed keys of one section of the report; `section` prefixes the key in messages.
class Section {
 public:
  Section(const json& report, const char* section, const std::string& path)
      : path_(path), prefix_(section ? std::string(section) + "." : std::string()) {
    if (!section) {
      node_ = &report;
      return;
    }
    if (!report.contains(section) || !report[section].is_object())
      throw InvalidParameter(
          section, report.contains(section) ? document_value_text(report[section]) : "missing",
          "must be the table of a `selfalign design` report" + where());
    node_ = &report[section];
  }
  // A number; or null, read as `none`, where `null_means` says what null stands for.
  double number(const char* key, const char* null_means = nullptr,
                double none = std::numeric_limits<double>::quiet_NaN()) const {
    const std::string name = prefix_ + key;
    if (!node_->contains(key))
      throw InvalidParameter(name, "missing", "is required" + where());
    const json& v = (*node_)[key];
    if (v.is_number()) return v.get<double>();
    if (null_means && v.is_null()) return none;
    throw InvalidParameter(name, document_value_text(v),
                           std::string("must be a number") +
                               (null_means ? std::string(" or null (") + null_means + ")" : "") +
                               where());
  }

 private:
  std::string where() const { return " (in " + path_ + ", the --design report)"; }
  const json* node_ = nullptr;
  std::string path_, prefix_;
};

}  // namespace

std::span<const RequestKey> design_request_keys() { return kRequestKeys; }

DesignReport read_design_report(const std::string& path) {
  const json j = read_document(path, kDesignReport);
  if (!j.is_object())
    throw InvalidParameter("design", path, "must be the JSON report of `selfalign design`");
  const Section top(j, nullptr, path), profile(j, "profile", path), request(j, "request", path);
  DesignReport r;
  r.process.period = profile.number("period_s");
  r.process.stroke = profile.number("stroke_m");
  r.process.a2 = profile.number("a2_m_per_s2");
  r.process.a3 = profile.number("a3_m_per_s2");
  r.process.jerk = profile.number("jerk_m_per_s3", "no jerk limit",
                                  std::numeric_limits<double>::infinity());
  r.process.x_mu = top.number("x_mu_m");
  for (const RequestKey& k : kRequestKeys) {
    if (const auto* number = std::get_if<double DesignRequest::*>(&k.field)) {
      r.request.**number = request.number(k.key);
    } else {
      const double v = request.number(k.key, "not given: equal to mu");
      r.request.*std::get<std::optional<double> DesignRequest::*>(k.field) =
          std::isnan(v) ? std::nullopt : std::optional<double>(v);
    }
  }
  return r;
}

}  // namespace selfalign::cli
