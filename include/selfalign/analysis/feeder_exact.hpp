#pragma once
/// \file feeder_exact.hpp
/// The exact event-driven feeder solver (issue 23, item 3, first part): a 1-D part on a track
/// inclined by theta whose accelerations along the track, a_x(t), and along its normal, a_z(t),
/// are piecewise constant (PiecewisePolynomialProfile without jerk), with a uniform friction
/// level, a Coulomb law (static >= kinetic, direction-dependent kinetic coefficients), lift-off
/// and plastic landing (docs/feeder.md). On each window between switches of either profile every
/// quantity is constant, so every arc is a parabola in closed form:
///   contact (h = 0):  normal load per unit mass n = g cos(theta) + a_z; the needed friction
///                     f = a_x + g sin(theta); stick (u = 0 exactly) while |f| <= s m n / g,
///                     else slip u' = -f - sigma k_sigma m n / g, its stop at u = 0 in closed
///                     form; n < 0 lifts the part off (at the window's start: n is constant);
///   flight:           h'' = -n (the part falls with g cos(theta), the track accelerates by
///                     a_z), u' = -f (no friction); landing at the first root of the quadratic
///                     h(t) = 0, in closed form (the stable root formula);
///   landing:          plastic (restitution 0): the normal impulse per unit mass P = -h' and a
///                     Coulomb-bounded tangential impulse: the part sticks if |u| <= s m P / g,
///                     else u loses k m P / g.
/// u is the velocity relative to the track along it, x the position on the track, h the height
/// above it and w = h'. Units: the model's (g = 1 / mu_1 in the paper's); theta > 0 rises along +x.

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign {

/// The track: its piecewise-constant accelerations (borrowed; null: none along that direction),
/// gravity, incline, uniform friction level and law.
struct FeederTrack {
  const TableProfile* along = nullptr;   ///< x(t) along the track
  const TableProfile* normal = nullptr;  ///< z(t) along its normal
  double g = 1;                          ///< [-], > 0
  double incline = 0;                    ///< theta [rad], in (-pi/2, pi/2)
  double level = 1;                      ///< m [-], > 0
  FrictionLaw law;                       ///< Coulomb (no Stribeck, no viscous term)
};

/// Throws InvalidParameter naming "along"/"normal" (not piecewise-constant acceleration), "g",
/// "incline", "level" or "law" (velocity-dependent).
void validate(const FeederTrack& track);

/// contact_stick, contact_slip or flight.
enum class FeederMode { stick, slip, flight };
/// "stick", "slip", "flight".
const char* feeder_mode_name(FeederMode mode) noexcept;

struct FeederExactState {
  double t = 0;
  double x = 0, u = 0;  ///< position on the track and velocity relative to it [-]
  double h = 0, w = 0;  ///< height above the track and its rate [-] (0 in contact)
  FeederMode mode = FeederMode::stick;
};

/// What the solver did (accumulated over calls).
struct FeederExactStatistics {
  long long arcs = 0, lift_offs = 0, landings = 0, stick_landings = 0;
};

/// Advances to t_end (>= state.t, finite). A state in contact (h = 0, w = 0) with u = 0 sticks
/// or starts to slip as the window decides; a state with h > 0 flies. Throws as validate(track)
/// and InvalidParameter naming "t_end" or "state" (h < 0, or non-finite values).
void advance_feeder_exact(const FeederTrack& track, FeederExactState& state, double t_end,
                          FeederExactStatistics* statistics = nullptr);

}  // namespace selfalign
