#pragma once
// Internal: what both drive families of the exact feeder solver share (feeder_exact.cpp for
// piecewise-constant drives, feeder_smooth_exact.cpp for smooth ones): the track's constants,
// the landing (Newton restitution with a Coulomb-bounded tangential impulse) and the census.

#include <cmath>

#include "selfalign/analysis/feeder_exact.hpp"
#include "../simulate/arc_events.hpp"  // time_resolution

namespace selfalign::detail {

// Per unit mass: g cos(theta), g sin(theta), and the friction bound per unit of normal load and
// of coefficient (m / g).
struct FeederConstants {
  double gc, gs, per_load;
  const FrictionLaw* law;
  double restitution;
  explicit FeederConstants(const FeederTrack& k)
      : gc(k.g * std::cos(k.incline)),
        gs(k.g * std::sin(k.incline)),
        per_load(k.level / k.g),
        law(&k.law),
        restitution(k.restitution) {}
  double static_bound(double n) const { return law->static_coefficient() * per_load * n; }
  // The kinetic friction per unit mass opposing a slip in direction sigma under load n.
  double kinetic(int sigma, double n) const { return law->kinetic(sigma) * per_load * n; }
};

// The landing at time t (w < 0 the rate of approach, n the normal load there): Newton's
// restitution, P = -(1 + e) w, the rate leaves as -e w; the tangential impulse is
// Coulomb-bounded by the kinetic cone, as on the sliding arcs (the static coefficient holds a
// part at rest, it does not stop a sliding one): the part stops (u = 0) if |u| <= k m P / g,
// else u loses k m P / g. A part that arrives at rest relative to the track (u = 0) needs no
// tangential impulse and stays at rest. A rebound that would last under 64 roundings of t
// under a positive load is the accumulation point of the bounces: the contact closes (w = 0).
// Returns true when the part flies on.
inline bool feeder_landing(const FeederConstants& c, double t, double n, double& u, double& w,
                           FeederExactStatistics& stats) {
  const double P = (1 + c.restitution) * std::max(0.0, -w);
  ++stats.landings;
  const int sigma = u > 0 ? 1 : -1;
  if (std::abs(u) <= c.kinetic(sigma, P)) {
    u = 0;
    ++stats.stick_landings;
  } else {
    u -= sigma * c.kinetic(sigma, P);
  }
  w = c.restitution * std::max(0.0, -w);
  if (w > 0 && n > 0 && 2 * w / n <= 64 * time_resolution(t)) w = 0;
  if (w > 0) ++stats.rebounds;
  return w > 0;
}

inline void record_census(FeederExactStatistics& stats, FeederMode mode, double duration) {
  (mode == FeederMode::stick   ? stats.stick_time
   : mode == FeederMode::slip  ? stats.slip_time
                               : stats.flight_time) += duration;
}

inline void record_lift_off(FeederExactStatistics& stats, double t) {
  ++stats.lift_offs;
  if (std::isnan(stats.first_lift_off)) stats.first_lift_off = t;
}

inline void record_slip_start(FeederExactStatistics& stats, double t, int sigma) {
  if (std::isnan(stats.first_slip)) stats.first_slip = t, stats.first_slip_direction = sigma;
}

// The smooth drive family (feeder_smooth_exact.cpp); the track is validated.
void advance_feeder_smooth(const FeederTrack& track, FeederExactState& state, double t_end,
                           FeederExactStatistics& statistics);

}  // namespace selfalign::detail
