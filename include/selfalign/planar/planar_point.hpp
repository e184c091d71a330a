#pragma once
/// \file planar_point.hpp
/// Planar motion of a point contact (issue 13, first slice): a particle on a table that moves in
/// the plane, with isotropic Coulomb friction (static s >= kinetic k) over a planar friction
/// level m(x, y), by Moreau's time-stepping with the set-valued friction solved exactly.
///
/// One step from t_k to t_{k+1} = t_k + h, as the 1-D scheme (time_stepping.hpp) with vectors:
///   p_M      = p_k + (h/2) u_k                              (midpoint: where friction is read)
///   u_{k+1}  = u_k - (Y'(t_{k+1}) - Y'(t_k)) - h m(p_M) lambda,  lambda in the friction disc
///   p_{k+1}  = p_k + h ((1 - theta) u_k + theta u_{k+1})
/// with p the position relative to the table and u its velocity. For one contact point the
/// impulse balance is a projection onto a disc, in closed form (no iteration, no threshold):
/// with v* = u_k - ΔY' and the largest friction impulse P = h c m(p_M),
///   |v*| <= P  ->  u_{k+1} = 0 exactly (stick);   otherwise u_{k+1} = v* - h k m (v*/|v*|),
/// where c = k while sliding on (u_k != 0 and v* . u_k > 0) and c = s from rest or when the
/// velocity would turn back through zero (v* . u_k <= 0), as the 1-D scheme does. Along one
/// axis this is the 1-D scheme term for term. The friction impulse never adds kinetic energy:
/// |u_{k+1}| <= |v*|.

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/planar/planar_field.hpp"
#include "selfalign/planar/planar_table_motion.hpp"
#include "selfalign/simulate/time_stepping.hpp"

namespace selfalign {

/// State of the planar point stepper. Step times are t0 + k h.
struct PlanarPointState {
  double t0 = 0;
  long long step_index = 0;
  double t = 0;
  double x = 0, y = 0;    ///< position relative to the table [-]
  double ux = 0, uy = 0;  ///< relative velocity [-]
  double table_vx = 0, table_vy = 0;  ///< Y'(t_k)
  bool stick = false;     ///< the last step ended in stick (u = 0 exactly)
};

PlanarPointState make_planar_point_state(const PlanarTableMotion& motion, double t, double x,
                                         double y, double ux, double uy);

/// Advances `steps` steps. The law must be isotropic (kinetic_forward = kinetic_backward) and
/// velocity-independent; throws InvalidParameter naming `law` otherwise.
void advance_planar_point(const PlanarTableMotion& motion, const PlanarField& field,
                          const FrictionLaw& law, const TimeSteppingOptions& options,
                          PlanarPointState& state, long long steps);

}  // namespace selfalign
