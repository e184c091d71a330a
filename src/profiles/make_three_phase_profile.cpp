#include "selfalign/profiles/make_three_phase_profile.hpp"

#include <cmath>

namespace selfalign {

bool three_phase_is_physical(const ThreePhaseParameters& p, double jerk) {
  if (std::isinf(jerk) && jerk > 0) return solve_three_phase(p).physical;
  return solve_jerk_limited_three_phase(with_jerk(p, jerk)).physical;
}

std::unique_ptr<TableProfile> make_three_phase_profile(const ThreePhaseParameters& p,
                                                       double jerk) {
  if (std::isinf(jerk) && jerk > 0) return std::make_unique<ThreePhaseProfile>(p);
  return std::make_unique<JerkLimitedThreePhaseProfile>(with_jerk(p, jerk));
}

}  // namespace selfalign
