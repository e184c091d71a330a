#pragma once
/// \file method.hpp
/// The 1-D solution methods: the closed set the stepper dispatcher (stepper.hpp) chooses from.

#include <string>

namespace selfalign {

enum class Method {
  exact,         ///< event-driven closed form (exact.hpp): piecewise-polynomial y'' (degree <= 1), piecewise-affine m(x)
  time_stepping, ///< Moreau time-stepping (time_stepping.hpp): any profile and friction map
  integrator     ///< exact sticks, slips by Odeint's dopri5 with event location (slip_integrator.hpp): velocity-dependent laws
};

/// Parses "exact", "time-stepping" or "integrator"; throws InvalidParameter("method", ...) otherwise.
Method parse_method(const std::string& text);
std::string to_string(Method method);

}  // namespace selfalign
