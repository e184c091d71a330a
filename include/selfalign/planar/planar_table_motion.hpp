#pragma once
/// \file planar_table_motion.hpp
/// The table's motion: translation along two directions in its plane and along its normal, and
/// an in-plane rotation, each any table profile (profiles/), with its pose, twist and common
/// period. Every planar
/// solver (the point steppers, the exact point solver, the rigid part) and analysis takes it;
/// it does not belong to any one of them. Also the planar solvers' common friction-law check.

#include <string>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/profiles/table_profile.hpp"

namespace selfalign {

/// The table's planar motion: displacement T(t) = first(t) e1 + second(t) e2 with unit vectors
/// e1, e2 (defaults: the x and y axes), and optionally an in-plane rotation by the angle
/// psi(t) = rotation(t) [rad] about the table's origin (which moves with T). A null profile
/// does not move the table along its direction. The point-contact solvers (planar_point.hpp
/// and planar_exact_point.hpp) refuse a rotating table; the rigid part (planar_rigid.hpp) takes it.
/// `normal` moves the table along its normal by z(t): it changes the bodies' normal load, so
/// only the contact core's model with gravity (core::Model::gravity, its loads stage) takes it;
/// every other solver refuses it (require_no_normal_motion).
struct PlanarTableMotion {
  const TableProfile* first = nullptr;
  double e1_x = 1, e1_y = 0;
  const TableProfile* second = nullptr;
  double e2_x = 0, e2_y = 1;
  const TableProfile* rotation = nullptr;
  const TableProfile* normal = nullptr;  ///< z(t) along the table's normal [-] (null: none)
};

/// The table's pose and twist at one time: T, T', psi, psi', and z, z' along its normal.
struct PlanarTablePose {
  double x = 0, y = 0, vx = 0, vy = 0, angle = 0, rate = 0;
  double z = 0, vz = 0;
};
PlanarTablePose table_pose(const PlanarTableMotion& motion, double t);

/// The common period of the motion's profiles (the longest one; shorter periods must divide it
/// to 1e-9, else InvalidParameter naming "period"). Throws when no profile is given.
double planar_period(const PlanarTableMotion& motion);

/// Throws InvalidParameter unless each direction given is a unit vector (to 1e-12).
void validate(const PlanarTableMotion& motion);

/// Throws InvalidParameter(name, |(x, y)|, ...) unless (x, y) is a unit vector (to 1e-12): the
/// one check of the table's directions and of core::Gravity's downhill direction.
void require_unit_vector(const std::string& name, double x, double y);

/// Throws InvalidParameter naming "normal" when the motion moves the table along its normal:
/// `solver` has no normal-load stage (only the contact core with gravity has).
void require_no_normal_motion(const PlanarTableMotion& motion, const char* solver);

/// Throws InvalidParameter naming "law" unless isotropic (kinetic_forward = kinetic_backward)
/// and velocity-independent: the planar solvers' friction law.
void require_planar_law(const FrictionLaw& law);

/// The table velocity Y'(t) [-].
void table_velocity(const PlanarTableMotion& motion, double t, double& vx, double& vy);

/// The largest change of the table's velocity over one of Moreau's steps,
/// max_k |Y'(t0 + k h) - Y'(t0 + (k - 1) h)| for k = 1 .. steps [-] (the times formed as the
/// steppers form them). A part at rest on the table is held through step k exactly when the
/// step's largest friction impulse h s m bounds that change, so with steps covering a period:
/// no part is ever held for a whole period where h s max m falls below it (planar_stop's
/// never-stops proof), and a part at rest where h s m(x) reaches it is held for good (the 1-D
/// time-stepped stopping run's eq. 40). The rotation is not read.
double largest_step_velocity_change(const PlanarTableMotion& motion, double t0, double h,
                                    long long steps);

}  // namespace selfalign
