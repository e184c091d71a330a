#pragma once
/// \file rigid_part.hpp
/// A rigid part for planar motion and where it is: its inertia and contact patch, its pose on
/// the table and its twist relative to the table (the contact core's body and body state are
/// made of these; planar_rigid.hpp describes the scheme).

#include "selfalign/planar/contact_patch.hpp"

namespace selfalign {

/// The part: its moment of inertia about the centre of mass per unit mass j = I/(m L^2) [-]
/// (> 0; r^2/2 for a uniform disc of radius r) and its contact patch.
struct RigidPart {
  double inertia = 0.5;
  ContactPatch patch = point_patch();
};

/// Throws InvalidParameter naming "inertia" (finite, > 0) or the patch's parameter.
void validate(const RigidPart& part);

/// A pose on the table: centre of mass in table coordinates and angle relative to the table.
struct PlanarPose {
  double x = 0, y = 0, angle = 0;
};

/// A twist relative to the table, in table axes: (u_x, u_y) of the centre of mass and the spin.
struct PlanarTwist {
  double ux = 0, uy = 0, omega = 0;
};

}  // namespace selfalign
