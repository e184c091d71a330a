// The analyses of a config's table motion: io/profile_analyses.hpp.
#include "selfalign/io/profile_analyses.hpp"

namespace selfalign {

std::optional<SteadyState> steady_state_of(const ProfileModel& model) {
  if (!model.profile) return std::nullopt;
  SteadyStateOptions options;
  options.integrator = model.integrator;  // Stribeck or viscous laws
  return steady_state(*model.profile, model.law, options);
}

SweepOptions sweep_options_of(const ProfileModel& model) {
  SweepOptions o;
  o.law = model.law;
  o.steady.integrator = model.integrator;  // Stribeck or viscous laws
  if (model.jerk) o.jerk = *model.jerk;
  return o;
}

}  // namespace selfalign
