#pragma once
// Internal: what both drive families of the exact feeder solver share (feeder_exact.cpp for
// piecewise-constant drives, feeder_smooth_exact.cpp for smooth ones): the track's constants,
// the landing (Newton restitution with a Coulomb-bounded tangential impulse) and the census.

#include <algorithm>
#include <cmath>

#include "selfalign/analysis/feeder_exact.hpp"
#include "../simulate/arc_events.hpp"  // time_resolution, parabolic_reach
#include "selfalign/special_values.hpp"

namespace selfalign::detail {

// Per unit mass: g cos(theta), g sin(theta); the friction bound per unit of normal load, of
// coefficient and of level (1 / g); the level along the track.
struct FeederConstants {
  double gc, gs, inv_g;
  const FrictionLaw* law;
  double restitution;
  const PiecewiseAffineFriction* field;
  double level;
  /// The smallest height the family resolves [-]: the smooth family's h carries the rounding
  /// of z_T(t) - z_T(t0) (set by it: 64 roundings of the normal stroke); 0 where h is exact.
  double height_resolution = 0;
  explicit FeederConstants(const FeederTrack& k)
      : gc(k.g * std::cos(k.incline)),
        gs(k.g * std::sin(k.incline)),
        inv_g(1 / k.g),
        law(&k.law),
        restitution(k.restitution),
        field(k.field),
        level(k.level) {}
  // The static bound s m n / g and the kinetic friction k_sigma m n / g on level m, load n.
  double static_bound(double n, double m) const {
    return law->static_coefficient() * m * inv_g * n;
  }
  double kinetic(int sigma, double n, double m) const { return law->kinetic(sigma) * m * inv_g * n; }
  // The level of the piece holding x (a stick, a landing; right-continuous).
  double level_at(double x) const { return field ? field->bound(x) : level; }
  // The piece a slip in direction sigma from x runs on (moving left from a boundary: the piece
  // below it): its level and the boundary ahead (+-inf: none).
  struct SlipPiece {
    double m, boundary;
  };
  SlipPiece slip_piece(double x, int sigma) const {
    if (!field) return {level, sigma * kInf};
    const auto pieces = field->pieces();
    std::size_t i = field->piece_index(x);
    if (sigma < 0 && i > 0 && x == pieces[i].begin) --i;
    return {pieces[i].bound_at_begin, sigma > 0 ? pieces[i].end : pieces[i].begin};
  }
};

// The landing at time t and place x (w < 0 the rate of approach, n the normal load there): Newton's
// restitution, P = -(1 + e) w, the rate leaves as -e w; the tangential impulse is
// Coulomb-bounded by the kinetic cone, as on the sliding arcs (the static coefficient holds a
// part at rest, it does not stop a sliding one): the part stops (u = 0) if |u| <= k m P / g,
// else u loses k m P / g. A part that arrives at rest relative to the track (u = 0) needs no
// tangential impulse and stays at rest. Under a positive load a rebound that would last under
// 64 roundings of t, or rise less than the height the family resolves (w^2 / 2n below
// height_resolution: below it the computed height is rounding noise, which would feed the
// bounces instead of letting them die out), is the accumulation point of the bounces: the
// contact closes (w = 0). Returns true when the part flies on.
inline bool feeder_landing(const FeederConstants& c, double t, double x, double n, double& u,
                           double& w, FeederExactStatistics& stats) {
  const double P = (1 + c.restitution) * std::max(0.0, -w);
  ++stats.landings;
  const int sigma = u > 0 ? 1 : -1;
  const double stop = c.kinetic(sigma, P, c.level_at(x));
  if (std::abs(u) <= stop) {
    u = 0;
    ++stats.stick_landings;
  } else {
    u -= sigma * stop;
  }
  w = c.restitution * std::max(0.0, -w);
  if (w > 0 && n > 0 &&
      (2 * w / n <= 64 * time_resolution(t) || w * w <= 2 * n * c.height_resolution))
    w = 0;
  if (w > 0) ++stats.rebounds;
  return w > 0;
}

// An arc of `duration` in `mode` that ended at t_end.
inline void record_census(FeederExactStatistics& stats, FeederMode mode, double duration,
                          double t_end) {
  (mode == FeederMode::stick   ? stats.stick_time
   : mode == FeederMode::slip  ? stats.slip_time
                               : stats.flight_time) += duration;
  if (mode != FeederMode::stick && duration > 0) stats.last_motion = t_end;
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
