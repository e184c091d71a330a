#include "selfalign/robust/distribution.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include <boost/math/special_functions/erf.hpp>

#include "selfalign/error.hpp"
#include "selfalign/overloaded.hpp"

namespace selfalign {
namespace {

// Standard normal CDF and its inverse (Boost.Math: erfc and erfc_inv, accurate in the tails).
double phi(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }
double phi_inverse(double p) { return -std::sqrt(2.0) * boost::math::erfc_inv(2 * p); }

void require_bounds(const std::string& name, double lower, double upper, bool allow_infinite) {
  if (std::isnan(lower) || (!allow_infinite && !std::isfinite(lower)))
    throw InvalidParameter(name + ".lower", lower, "must be a finite number");
  if (std::isnan(upper) || (!allow_infinite && !std::isfinite(upper)))
    throw InvalidParameter(name + ".upper", upper, "must be a finite number");
  if (!(lower < upper))
    throw InvalidParameter(name + ".upper", upper,
                           "must be > lower = " + format_number(lower));
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) parts.push_back(item);
  return parts;
}

}  // namespace

void validate(const std::string& name, const Distribution& d) {
  std::visit(Overloaded{
                 [](const Known&) {},
                 [&](const Normal& n) {
                   require_finite(name + ".mean", n.mean);
                   require_moderate(name + ".mean", n.mean);
                   require_non_negative(name + ".sd", n.sd);
                   require_bounds(name, n.lower, n.upper, true);
                   if (!(n.lower <= n.mean && n.mean <= n.upper))
                     throw InvalidParameter(name + ".lower", n.lower,
                                            "the bounds [" + format_number(n.lower) + ", " +
                                                format_number(n.upper) +
                                                "] must contain the mean " +
                                                format_number(n.mean));
                 },
                 [&](const Uniform& u) { require_bounds(name, u.lower, u.upper, false); },
                 [&](const Interval& i) { require_bounds(name, i.lower, i.upper, false); },
                 [&](const Samples& s) {
                   if (s.values.empty())
                     throw InvalidParameter(name + ".samples", "[]",
                                            "must hold at least one value");
                   for (double v : s.values) require_finite(name + ".samples", v);
                 },
             },
             d);
}

double nominal(const Distribution& d, double known) {
  return std::visit(
      Overloaded{
          [&](const Known&) { return known; },
          [](const Normal& n) { return n.mean; },
          [](const Uniform& u) { return 0.5 * (u.lower + u.upper); },
          [](const Interval& i) { return 0.5 * (i.lower + i.upper); },
          [](const Samples& s) {
            return std::accumulate(s.values.begin(), s.values.end(), 0.0) /
                   static_cast<double>(s.values.size());
          },
      },
      d);
}

double quantile(const Distribution& d, double u, double known) {
  return std::visit(
      Overloaded{
          [&](const Known&) { return known; },
          [&](const Normal& n) {
            if (n.sd == 0) return n.mean;
            // Truncation by the inverse CDF restricted to [Phi(a), Phi(b)] (exact, no
            // rejection, so one u gives one value).
            const double pa = std::isinf(n.lower) ? 0.0 : phi((n.lower - n.mean) / n.sd);
            const double pb = std::isinf(n.upper) ? 1.0 : phi((n.upper - n.mean) / n.sd);
            const double p = std::clamp(pa + u * (pb - pa), 1e-300, 1 - 1e-16);
            return std::clamp(n.mean + n.sd * phi_inverse(p), n.lower, n.upper);
          },
          [&](const Uniform& r) { return r.lower + u * (r.upper - r.lower); },
          [&](const Interval& r) { return r.lower + u * (r.upper - r.lower); },
          [&](const Samples& s) {
            std::vector<double> v = s.values;
            std::sort(v.begin(), v.end());
            const auto k = std::min(v.size() - 1, static_cast<std::size_t>(u * v.size()));
            return v[k];
          },
      },
      d);
}

std::pair<double, double> box(const Distribution& d, double known, double sigmas) {
  return std::visit(
      Overloaded{
          [&](const Known&) { return std::pair{known, known}; },
          [&](const Normal& n) {
            return std::pair{std::isinf(n.lower) ? n.mean - sigmas * n.sd : n.lower,
                             std::isinf(n.upper) ? n.mean + sigmas * n.sd : n.upper};
          },
          [](const Uniform& r) { return std::pair{r.lower, r.upper}; },
          [](const Interval& r) { return std::pair{r.lower, r.upper}; },
          [](const Samples& s) {
            const auto [lo, hi] = std::minmax_element(s.values.begin(), s.values.end());
            return std::pair{*lo, *hi};
          },
      },
      d);
}

bool is_uncertain(const Distribution& d) { return !std::holds_alternative<Known>(d); }

std::string describe(const Distribution& d) {
  return std::visit(
      Overloaded{
          [](const Known&) { return std::string("known"); },
          [](const Normal& n) {
            std::string s = "normal(mean=" + format_number(n.mean) + ", sd=" + format_number(n.sd);
            if (!std::isinf(n.lower) || !std::isinf(n.upper))
              s += ", lower=" + format_number(n.lower) + ", upper=" + format_number(n.upper);
            return s + ")";
          },
          [](const Uniform& r) {
            return "uniform(" + format_number(r.lower) + ", " + format_number(r.upper) + ")";
          },
          [](const Interval& r) {
            return "interval(" + format_number(r.lower) + ", " + format_number(r.upper) + ")";
          },
          [](const Samples& s) { return "samples(n=" + std::to_string(s.values.size()) + ")"; },
      },
      d);
}

Distribution parse_distribution(const std::string& name, const std::string& text) {
  const auto colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  const std::vector<std::string> args =
      colon == std::string::npos ? std::vector<std::string>{} : split(text.substr(colon + 1));
  const auto count = [&](std::size_t lo, std::size_t hi) {
    if (args.size() < lo || args.size() > hi)
      throw InvalidParameter(name, text,
                             "must be normal:MEAN,SD[,LOWER,UPPER], uniform:LOWER,UPPER, "
                             "interval:LOWER,UPPER, samples:V1,V2,... or known");
  };
  Distribution d;
  if (kind == "known") {
    count(0, 0);
    d = Known{};
  } else if (kind == "normal") {
    if (args.size() != 4) count(2, 2);
    Normal n;
    n.mean = parse_number(name + ".mean", args[0]);
    std::string sd = args[1];
    const bool percent = !sd.empty() && sd.back() == '%';
    if (percent) sd.pop_back();
    n.sd = parse_number(name + ".sd", sd);
    if (percent) n.sd = std::abs(n.mean) * n.sd / 100;  // "5%" of 0.2 is 0.01 exactly
    if (args.size() == 4) {
      n.lower = parse_number(name + ".lower", args[2]);
      n.upper = parse_number(name + ".upper", args[3]);
    }
    d = n;
  } else if (kind == "uniform" || kind == "interval") {
    count(2, 2);
    const double lo = parse_number(name + ".lower", args[0]);
    const double hi = parse_number(name + ".upper", args[1]);
    d = kind == "uniform" ? Distribution(Uniform{lo, hi}) : Distribution(Interval{lo, hi});
  } else if (kind == "samples") {
    Samples s;
    for (const std::string& a : args) s.values.push_back(parse_number(name + ".samples", a));
    d = s;
  } else {
    count(1, 0);  // always throws: unknown kind
  }
  validate(name, d);
  return d;
}

}  // namespace selfalign
