#pragma once
// Test helper: the observed order of Moreau's time-stepping against the exact solver, as
// tests/test_time_stepping.cpp measures it (the RMS error of x over K grid phases, which
// removes the lottery of where each stick/slip event falls inside its step).
#include <cmath>
#include <vector>

#include "selfalign/analysis/period_map.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/simulate/time_stepping.hpp"

namespace selfalign::testing_support {

/// RMS over `phases` start phases of |x_stepping - x_exact| after `duration`, from rest.
inline double moreau_rms_error(const TableProfile& profile, const FrictionLaw& law,
                               double duration, double h, int phases = 8) {
  const UniformFriction friction;
  const PeriodMap exact(profile, friction, law);  // an exact solver: piecewise polynomial or smooth
  double sum_sq = 0;
  for (int j = 0; j < phases; ++j) {
    const double t0 = h * (j + 0.5) / phases;
    const double x_exact = exact.start({t0, 0, 0}).advance_to(t0 + duration).x;
    TimeSteppingState ts = make_time_stepping_state(profile, {t0, 0, 0});
    advance_time_stepping(profile, friction, law, {h, 0.5}, ts, std::llround(duration / h));
    sum_sq += std::pow(ts.object.x - x_exact, 2);
  }
  return std::sqrt(sum_sq / phases);
}

}  // namespace selfalign::testing_support
