#include "selfalign/robust/fragility.hpp"

#include <algorithm>
#include <cmath>

#include "selfalign/error.hpp"

namespace selfalign {
namespace {

std::string percent(double x) { return format_number(std::round(x * 1000) / 10) + "%"; }
std::string millimetres(double x) { return format_number(std::round(x * 1e6) / 1e3) + " mm"; }

}  // namespace

Fragility fragility(const DesignRequest& q, const Process& p, double level, int max_periods) {
  validate(q);
  validate(p);
  if (!(level > 0 && level < 1)) throw InvalidParameter("level", level, "must be in (0, 1)");
  Fragility f;
  f.level = level;
  const InputValues nominal = nominal_inputs(q, {});
  const double mu = nominal[0], c_mu = nominal[1], ratio = nominal[2];
  const double peak = std::max(p.a2, p.a3);
  f.stop_margin = 1 - peak / (ratio * c_mu * mu * q.gravity);
  f.motion_margin = p.a2 / (ratio * mu * q.gravity) - 1;
  const ProcessFamily family(q, p);
  f.end_nominal = run_process(family, nominal, max_periods).end_position;
  // Input k at its two examined values (factors on the nominal).
  const auto shifted = [&](std::size_t k, std::array<double, 2>& ends, double low, double high) {
    double shift = 0;
    for (int side = 0; side < 2; ++side) {
      InputValues v = nominal;
      v[k] *= side == 0 ? low : high;
      ends[side] = run_process(family, v, max_periods).end_position;
      shift = std::isnan(ends[side]) ? std::numeric_limits<double>::infinity()
                                     : std::max(shift, std::abs(ends[side] - f.end_nominal));
    }
    return shift;
  };
  f.end_shift_mu = shifted(0, f.end_mu, 1 - level, 1 + level);
  f.end_shift_c_mu = shifted(1, f.end_c_mu, 1 - level, 1 + level);
  f.end_shift_static = shifted(2, f.end_static, std::max(1 / ratio, 1 - level), 1 + level);
  f.assumes_equal_static = !q.mu_static || *q.mu_static == q.mu;

  const std::string at = percent(level);
  if (f.stop_margin < level)
    f.warnings.push_back(
        "stopping: the peak table acceleration is " + percent(1 - f.stop_margin) +
        " of mu_static c_mu g, so mu or c_mu " + percent(std::max(0.0, f.stop_margin)) +
        " lower and the part never stops for good (eq. 40)");
  if (f.motion_margin < level)
    f.warnings.push_back("motion: y2'' exceeds mu_static g by only " +
                         percent(f.motion_margin) +
                         "; mu that much higher and the part never leaves the start");
  const double band = q.tolerance > 0 ? q.tolerance : 1e-3 * q.width;
  const auto end_warning = [&](const char* name, double shift, const std::array<double, 2>& e) {
    if (std::isinf(shift)) {
      f.warnings.push_back(std::string("end position: with ") + name + " " + at + " " +
                           (std::isnan(e[0]) ? "lower" : "higher") + " the part never stops");
    } else if (shift > band) {
      f.warnings.push_back(std::string("end position: ") + name + " off by " + at +
                           " moves the end by up to " + millimetres(shift) + ", beyond the " +
                           (q.tolerance > 0 ? "tolerance " : "band ") + millimetres(band));
    }
  };
  end_warning("mu", f.end_shift_mu, f.end_mu);
  end_warning("c_mu", f.end_shift_c_mu, f.end_c_mu);
  if (!f.assumes_equal_static) end_warning("mu_static", f.end_shift_static, f.end_static);
  else {  // a plain warning: the design never considered a static coefficient
    const std::string effect =
        std::isinf(f.end_shift_static)
            ? "the part never stops"
            : "the end moves by " + millimetres(f.end_shift_static) +
                  (f.end_shift_static > band ? std::string(", beyond the ") +
                                                   (q.tolerance > 0 ? "tolerance " : "band ") +
                                                   millimetres(band)
                                             : std::string());
    f.warnings.push_back(
        "static friction: the design assumes mu_static = mu (no mu_static given); with "
        "mu_static only " + at + " above mu " + effect +
        ". Measure mu_static and give it, or design for its uncertainty (design --robust with "
        "--uncertain static_ratio=...)");
  }
  return f;
}

}  // namespace selfalign
