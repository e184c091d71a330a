#pragma once
/// \file make_three_phase_profile.hpp
/// The one factory of the three-phase family: the paper's jump accelerations (Sect. 4.4.3,
/// three_phase.hpp) when the jerk limit is +inf, ramps at |y'''| = jerk otherwise
/// (jerk_limited_three_phase.hpp). Every caller that holds "accelerations plus a jerk limit"
/// (design, robust design, sweeps, positioning, config readers) builds its profile here.

#include <memory>

#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {

/// The jerk-limited parameters of (p, jerk).
inline JerkLimitedThreePhaseParameters with_jerk(const ThreePhaseParameters& p,
                                                 double jerk) noexcept {
  return {p.period, p.stroke, p.a2, p.a3, jerk};
}

/// Whether the family has a profile for (p, jerk) (not case 0), without building one.
/// Validates p and jerk (> 0, +inf allowed) as the profiles' constructors do.
bool three_phase_is_physical(const ThreePhaseParameters& p, double jerk);

/// ThreePhaseProfile(p) for jerk = +inf, JerkLimitedThreePhaseProfile(with_jerk(p, jerk))
/// otherwise. Throws InvalidParameter as those constructors do (misuse, or case 0).
std::unique_ptr<TableProfile> make_three_phase_profile(const ThreePhaseParameters& p,
                                                       double jerk);

}  // namespace selfalign
