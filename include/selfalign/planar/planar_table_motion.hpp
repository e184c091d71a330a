#pragma once
/// \file planar_table_motion.hpp
/// The table's motion in its plane: translation along two directions and an in-plane rotation,
/// each any table profile (profiles/), with its pose, twist and common period. Every planar
/// solver (the point steppers, the exact point solver, the rigid part) and analysis takes it;
/// it does not belong to any one of them. Also the planar solvers' common friction-law check.

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/profiles/table_profile.hpp"

namespace selfalign {

/// The table's planar motion: displacement T(t) = first(t) e1 + second(t) e2 with unit vectors
/// e1, e2 (defaults: the x and y axes), and optionally an in-plane rotation by the angle
/// psi(t) = rotation(t) [rad] about the table's origin (which moves with T). A null profile
/// does not move the table along its direction. The point-contact solvers (planar_point.hpp
/// and planar_exact_point.hpp) refuse a rotating table; the rigid part (planar_rigid.hpp) takes it.
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

}  // namespace selfalign
