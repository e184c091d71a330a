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
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/simulate/time_stepping.hpp"

namespace selfalign {

/// The table's planar motion: displacement T(t) = first(t) e1 + second(t) e2 with unit vectors
/// e1, e2 (defaults: the x and y axes), and optionally an in-plane rotation by the angle
/// psi(t) = rotation(t) [rad] about the table's origin (which moves with T). A null profile
/// does not move the table along its direction. The point-contact solvers (this file and
/// planar_exact_point.hpp) refuse a rotating table; the rigid part (planar_rigid.hpp) takes it.
struct PlanarTableMotion {
  const TableProfile* first = nullptr;
  double e1_x = 1, e1_y = 0;
  const TableProfile* second = nullptr;
  double e2_x = 0, e2_y = 1;
  const TableProfile* rotation = nullptr;
};

/// The table's pose and twist at one time: T, T', psi, psi'.
struct PlanarTablePose {
  double x = 0, y = 0, vx = 0, vy = 0, angle = 0, rate = 0;
};
PlanarTablePose table_pose(const PlanarTableMotion& motion, double t);

/// The common period of the motion's profiles (the longest one; shorter periods must divide it
/// to 1e-9, else InvalidParameter naming "period"). Throws when no profile is given.
double planar_period(const PlanarTableMotion& motion);

/// Throws InvalidParameter unless each direction given is a unit vector (to 1e-12).
void validate(const PlanarTableMotion& motion);

/// Throws InvalidParameter naming "law" unless isotropic (kinetic_forward = kinetic_backward)
/// and velocity-independent: the planar solvers' friction law.
void require_planar_law(const FrictionLaw& law);

/// The table velocity Y'(t) [-].
void table_velocity(const PlanarTableMotion& motion, double t, double& vx, double& vy);

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
