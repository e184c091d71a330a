#include "selfalign/design/feeder_drive.hpp"

#include <cmath>
#include <numbers>

#include "../analysis/parallel_cells.hpp"
#include "selfalign/analysis/feeder.hpp"
#include "selfalign/error.hpp"

namespace selfalign {
namespace {

void validate(const FeederDriveOptions& o) {
  require_feeder_track(o.incline, o.mu_static, o.mu_kinetic, o.g, o.period);
  require_positive_moderate("target_speed", o.target_speed);
  if (!(o.max_flight_angle >= 0 && o.max_flight_angle <= 2 * std::numbers::pi))
    throw InvalidParameter("max_flight_angle", o.max_flight_angle, "must be in [0, 2 pi] rad");
  if (o.vibration_angles.empty())
    throw InvalidParameter("vibration_angles", "empty", "needs at least one angle");
  for (const double a : o.vibration_angles) require_feeder_angle("vibration_angles", a);
  require_positive_moderate("k_max", o.k_max);
  if (!(o.k_samples >= 2 && o.k_samples <= 10000))
    throw InvalidParameter("k_samples", o.k_samples, "must be in [2, 10000]");
  if (!(o.k_tolerance >= 1e-15 && o.k_tolerance <= 0.1))
    throw InvalidParameter("k_tolerance", o.k_tolerance, "must be in [1e-15, 0.1]");
  if (!(o.periods >= 1 && o.periods <= 100000))
    throw InvalidParameter("periods", static_cast<double>(o.periods), "must be in [1, 1e5]");
  if (!(o.restitution >= 0 && o.restitution <= 1))
    throw InvalidParameter("restitution", o.restitution, "must be in [0, 1]");
  if (o.threads < 0) throw InvalidParameter("threads", o.threads, "must be >= 0");
}

// The least machine number at one vibration angle (header).
FeederDriveCandidate least_drive(const FeederDriveOptions& o, double psi) {
  FeederDriveCandidate c;
  c.vibration_angle = psi;
  const FeederOnsets on = feeder_onsets(psi, o.incline, o.mu_static);
  const double w = 2 * std::numbers::pi / o.period;
  const FrictionLaw law(o.mu_static, o.mu_kinetic);
  const bool grounded = o.max_flight_angle == 0;
  double cap = o.k_max;
  if (grounded && on.lift_off < cap) cap = on.lift_off;
  // below the forward onset the part is held or slides backward: no forward conveying
  const double low = on.forward_slip > 0 ? on.forward_slip : cap * 1e-3;
  if (!(low < cap)) {
    c.reason = std::isinf(on.forward_slip)
                   ? "the drive never slips the part forward at this angle"
                   : grounded ? "the part would lift off before it slips forward"
                              : "the forward slip needs a machine number above k_max";
    return c;
  }
  struct Probe {
    bool ok;
    FeederRun run;
  };
  const auto probe = [&](double K) {
    const FeederTable table({K * o.g / (w * w), o.period, psi, o.incline, o.g});
    Probe p{false, feeder_run_exact(table, law, o.g, o.periods, o.restitution)};
    p.ok = p.run.velocity >= o.target_speed;
    return p;
  };
  double lo = low, hi = NAN;
  Probe at{};
  for (int i = 1; i < o.k_samples; ++i) {
    const double K = low * std::pow(cap / low, static_cast<double>(i) / (o.k_samples - 1));
    at = probe(K);
    if (at.ok) {
      hi = K;
      break;
    }
    lo = K;
  }
  if (std::isnan(hi)) {
    c.reason = grounded ? "no machine number up to the lift-off onset (or k_max) reaches the "
                          "target speed"
                        : "no machine number up to k_max reaches the target speed";
    return c;
  }
  while (hi - lo > o.k_tolerance * hi) {
    const double mid = 0.5 * (lo + hi);
    const Probe p = probe(mid);
    if (p.ok) {
      hi = mid, at = p;
    } else {
      lo = mid;
    }
  }
  // The flight bound at the least K that reaches the speed: the flight grows with K, so a larger
  // K would fly longer still.
  const double flight = std::isnan(at.run.flight_angle) ? 0.0 : at.run.flight_angle;
  if (grounded ? at.run.lifted_off : flight > o.max_flight_angle) {
    c.reason = "the least machine number that reaches the target speed (" + format_number(hi) +
               ") flies " + format_number(flight) + " rad a period, beyond the bound";
    return c;
  }
  c.feasible = true;
  c.machine_number = hi;
  c.amplitude = hi * o.g / (w * w);
  c.throw_number = hi * std::sin(psi) / std::cos(o.incline);
  c.speed = at.run.velocity;
  c.flight_angle = std::isnan(at.run.flight_angle) ? 0.0 : at.run.flight_angle;
  return c;
}

}  // namespace

FeederDriveDesign design_feeder_drive(const FeederDriveOptions& o) {
  validate(o);
  FeederDriveDesign d;
  d.candidates.resize(o.vibration_angles.size());
  SweepOptions so;
  so.threads = o.threads;
  so.progress = o.progress;
  detail::parallel_cells(
      d.candidates.size(), so,
      [&](std::size_t i) { d.candidates[i] = least_drive(o, o.vibration_angles[i]); },
      [&](std::size_t i, const std::string& why) {  // a failed run: infeasible, with the reason
        d.candidates[i] = FeederDriveCandidate{};
        d.candidates[i].vibration_angle = o.vibration_angles[i];
        d.candidates[i].reason = why;
      });
  for (const FeederDriveCandidate& c : d.candidates)
    if (c.feasible && (!d.feasible || c.machine_number < d.best.machine_number))
      d.feasible = true, d.best = c;
  if (!d.feasible) d.best.reason = "no vibration angle reaches the target speed";
  return d;
}

}  // namespace selfalign
