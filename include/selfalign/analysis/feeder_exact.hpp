#pragma once
/// \file feeder_exact.hpp
/// The exact event-driven feeder solver (issue 23, item 3): a 1-D part on a track inclined by
/// theta whose table moves along the track, x_T(t), and along its normal, z_T(t), with a
/// uniform friction level, a Coulomb law (static >= kinetic, direction-dependent kinetic
/// coefficients), lift-off, flight and landing with Newton restitution e (docs/feeder.md).
/// Per unit mass: the normal load n = g cos(theta) + z_T'', the friction the track must supply
/// to hold the part f = x_T'' + g sin(theta), the bound s m n / g (m the level).
///   contact (h = 0):  stick (u = 0 exactly) while |f| <= s m n / g; else slip
///                     u' = -f - sigma k_sigma m n / g until u = 0; n < 0 lifts the part off;
///   flight:           h'' = -n (the part falls with g cos(theta), the track accelerates by
///                     z_T''), u' = -f (no friction); landing at the first root of h;
///   landing:          Newton restitution: the normal impulse per unit mass P = -(1 + e) h'
///                     (the rate leaves as -e h') and a tangential impulse bounded by the
///                     kinetic cone, as on the sliding arcs: the part stops if
///                     |u| <= k m P / g, else u loses k m P / g. With e > 0 the
///                     bounces shorten geometrically under a positive load; once a bounce would
///                     last under 64 roundings of t the contact closes (the accumulation point).
/// Two drive families, each in closed form (both directions of one family):
///   piecewise-constant accelerations (PiecewisePolynomialProfile without jerk): every arc a
///     parabola, every event a closed-form root (the stable quadratic root for a landing);
///   smooth motions (Fourier series: the classic sinusoidal drive, two-frequency drives; any
///     SmoothMotion): every arc closed-form in the motion (u = u0 - (x_T'(t) - x_T'(t0)) - ...,
///     h likewise with z_T), every event (a stick break, a velocity zero, a lift-off n = 0, a
///     landing h = 0) isolated by the safe steps of the smooth 1-D solver, the certified scan
///     (smooth_exact.hpp): no root is stepped over, and the scan converges onto each.
/// u is the velocity relative to the track along it, x the position on the track, h the height
/// above it and w = h'. Units: the model's (g = 1 / mu_1 in the paper's); theta > 0 rises along +x.

#include <cmath>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign {

/// The track: its motion along it and along its normal (borrowed; null: none along that
/// direction; both piecewise-constant accelerations or both smooth), gravity, incline, uniform
/// friction level, law and the landing's restitution.
struct FeederTrack {
  const TableProfile* along = nullptr;   ///< x(t) along the track
  const TableProfile* normal = nullptr;  ///< z(t) along its normal
  double g = 1;                          ///< [-], > 0
  double incline = 0;                    ///< theta [rad], in (-pi/2, pi/2)
  double level = 1;                      ///< m [-], > 0 (where `field` is null)
  FrictionLaw law;                       ///< Coulomb (no Stribeck, no viscous term)
  double restitution = 0;                ///< Newton's e at a landing [-], in [0, 1]; 0: plastic
  /// The friction level along the track m(x) (borrowed; null: the uniform `level`), piecewise
  /// constant: a friction step without a transition width, e.g. FieldFriction(FrictionField::
  /// steps({x_mu}, {m1, m2}), PointFootprint{}).piecewise_affine(). A slip that reaches a
  /// boundary is an event (closed form on piecewise-constant drives, the certified scan on
  /// smooth ones); a stick or a landing takes the level of the piece holding x (right-continuous).
  const PiecewiseAffineFriction* field = nullptr;
};

/// Throws InvalidParameter naming "along"/"normal" (neither piecewise-constant acceleration nor
/// smooth, or one of each), "g", "incline", "level", "law" (velocity-dependent),
/// "restitution" (outside [0, 1]) or "field" (a sloped piece, or a level <= 0 or beyond 1e50).
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
  long long rebounds = 0;  ///< landings after which the part flies on (e > 0)
  /// Time spent held, sliding and off the track [-].
  double stick_time = 0, slip_time = 0, flight_time = 0;
  /// The first lift-off and the first slip from rest (with its direction, +1 forward along +x
  /// or -1) recorded into these statistics; NaN and 0 when none.
  double first_lift_off = NAN, first_slip = NAN;
  int first_slip_direction = 0;
  /// The end of the last slip or flight recorded (NaN: none): where a part comes to rest, the
  /// instant it stopped.
  double last_motion = NAN;
};

/// Advances to t_end (>= state.t, finite). A state in contact (h = 0, w = 0) with u = 0 sticks
/// or starts to slip as the window decides; a state with h > 0 flies. Throws as validate(track)
/// and InvalidParameter naming "t_end" or "state" (h < 0, or non-finite values).
void advance_feeder_exact(const FeederTrack& track, FeederExactState& state, double t_end,
                          FeederExactStatistics* statistics = nullptr);

}  // namespace selfalign
