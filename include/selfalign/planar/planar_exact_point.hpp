#pragma once
/// \file planar_exact_point.hpp
/// The exact event-driven solver for a point contact on a table moving in the plane (issue 13):
/// piecewise-constant table accelerations along both directions, a uniform friction level m,
/// isotropic Coulomb friction (static s >= kinetic k). Between acceleration switches every arc
/// is in closed form (docs/planar.md): rest while |A| <= s m; a straight slip along the drive
/// F = -A from rest (and whenever u is parallel to F); otherwise the classical turning slip,
/// V = C w^K / sin(phi), w = tan(phi/2), K = k m / |F|, with time and position closed-form in w,
/// and the stick event |u| -> 0 reached in finite time for K > 1 (a sign-change detector never
/// sees it: in 2-D the stick set has codimension 2). The state at a switch solves one monotone
/// scalar equation in w (safeguarded Newton) to round-off.

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/planar/planar_field.hpp"
#include "selfalign/planar/planar_table_motion.hpp"

namespace selfalign {

struct PlanarExactState {
  double t = 0;
  double x = 0, y = 0;    ///< position relative to the table [-]
  double ux = 0, uy = 0;  ///< relative velocity [-]
};

/// Advances to t_end (>= state.t). Both profiles of the motion must have piecewise-constant
/// acceleration (PiecewisePolynomialProfile without jerk); the law isotropic and
/// velocity-independent. Returns the number of arcs. Throws InvalidParameter otherwise.
long long advance_planar_exact_point(const PlanarTableMotion& motion,
                                     const UniformPlanarField& field, const FrictionLaw& law,
                                     PlanarExactState& state, double t_end);

}  // namespace selfalign
