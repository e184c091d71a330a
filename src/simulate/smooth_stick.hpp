#pragma once
// The end of a stick under a smooth table motion: the first time after t at which y'' leaves
// [-ms, ms] (ms = s m, the static bound), found by the safe steps of smooth_exact.hpp on both
// margins ms - y'' and ms + y'' (their second derivatives are bounded by Y4 = snap_bound()).
// Shared by the exact smooth solver and the slip integrator (slip_integrator.hpp).

#include "selfalign/profiles/table_profile.hpp"

namespace selfalign::detail {

struct StickEnd {
  double t;       ///< the break time, or t_end when the stick lasts to the horizon
  int direction;  ///< the slip that follows: -1 when y'' reached +ms, +1 when -ms; 0 at t_end
};

StickEnd smooth_stick_end(const SmoothMotion& motion, double ms, double t, double t_end);

}  // namespace selfalign::detail
