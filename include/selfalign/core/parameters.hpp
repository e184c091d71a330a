#pragma once
/// \file parameters.hpp
/// The named parameter view of a contact-core model (issue 21, item 1): the numbers a Model
/// is made of, by name, and `with_parameters(model, values)`, the same model with some of them
/// changed (a new Model; the one given is not touched). Values are in the model's units ([-]:
/// lengths in L, accelerations in mu_1 g, friction coefficients and levels in units of mu_1;
/// angles [rad]). The parameters of a model:
///   bodies[i].law   static, kinetic (a rigid body's law is isotropic: kinetic sets both
///                   directions); a 1-D part's also kinetic_backward, and its speed
///                   dependence: stribeck_velocity (NaN: none; a value adds the decay),
///                   stribeck_exponent (with a decay), viscous
///   bodies[i]       inertia (a rigid body: j = I / (m L^2)); width (a 1-D part with a uniform
///                   footprint)
///   field           its kind's numbers: level (uniform); origin_x, origin_y, angle, width,
///                   c_mu (half-plane step; a strip also half_width); centre_x, centre_y,
///                   angle, half_length, half_width, width, c_mu (rectangular pocket);
///                   centre_x, centre_y, radius, width, c_mu (circular pocket); origin_x,
///                   origin_y, angle, dx, dy, levels[k] (grid); origin_x, origin_y, angle and per
///                   node positions[k], with levels[k] where the node is continuous (a ramp's)
///                   or left[k], right[k] where the field jumps (axis)
///   gravity         g, incline (a model with gravity)
/// The table's motion is borrowed (its profiles are the caller's) and the step is a solver
/// setting: neither is a parameter here. The 1-D config's view (io/parameter_view.hpp) and the
/// planar config's (io/planar_config.hpp) name the numbers of a config file; this one names the
/// model's, with the same ModelParameter and ParameterValues (model_parameter.hpp).

#include <vector>

#include "selfalign/core/model.hpp"
#include "selfalign/model_parameter.hpp"

namespace selfalign::core {

/// The model's parameters in the order above (group: "law", "body", "field", "gravity"; unit
/// "[-]" or "[rad]").
std::vector<ModelParameter> model_parameters(const Model& model);

/// A new model: `model` with these values, applied in order, then checked as a whole (the laws
/// rebuilt, an axis field's nodes re-validated, validate(Model)), so that values that are only
/// consistent together (a kinetic coefficient above the static one until the static is raised)
/// may be given in any order. Throws InvalidParameter naming the parameter when the name is not
/// one of the model's (with the closest name, if any), a value is not finite (NaN is allowed
/// only for stribeck_velocity: no decay), or the new model is invalid (naming its part).
Model with_parameters(const Model& model, const ParameterValues& values);

}  // namespace selfalign::core
