#pragma once
/// \file model.hpp
/// The contact core's model (issue 21, first slice): immutable and runtime-sized, in the
/// spirit of MuJoCo's mjModel. Bodies on one moving table: each a rigid part (inertia, contact
/// patch in the body frame) with the friction law of its surface pair with the table; the
/// table's planar motion (planar_table_motion.hpp) and friction field (planar_field.hpp); the
/// time step. The number of bodies is a runtime value. What is not here yet: the normal
/// motion, gravity and incline (the feeder issue), part-part contacts (the several-parts
/// issue), the parameter view, and the 1-D part as a body (the 1-D solvers stay the exact
/// specialisations they are).

#include <vector>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/planar/planar_field.hpp"
#include "selfalign/planar/rigid_part.hpp"
#include "selfalign/planar/planar_table_motion.hpp"
#include "selfalign/simulate/time_stepping.hpp"

namespace selfalign::core {

/// One body on the table.
struct Body {
  RigidPart part;       ///< inertia j = I/(m L^2) [-] and contact patch (body frame)
  FrictionLaw law{};    ///< body-table law: isotropic, velocity-independent (planar solvers)
};

struct Model {
  PlanarTableMotion motion;                 ///< borrowed profiles: they must outlive the model
  PlanarField field = UniformPlanarField{};
  std::vector<Body> bodies;                 ///< N >= 1, a runtime value
  TimeSteppingOptions options;              ///< Moreau's step h [-] and theta
};

/// Throws InvalidParameter naming the first invalid part ("bodies" when there are none;
/// "bodies[i].inertia", "bodies[i].law" for body i).
void validate(const Model& model);

}  // namespace selfalign::core
