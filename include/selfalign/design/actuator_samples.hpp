#pragma once
/// \file actuator_samples.hpp
/// One period of a designed table motion sampled for a motion controller, in SI: a whole
/// number n = round(period x rate) of samples at t_i = i period / n, i = 0 .. n-1 (no repeated
/// endpoint: played in a loop, the sample after the last is the first), so the rate becomes
/// n / period (reported beside the requested one); position, velocity, acceleration, jerk and,
/// for a given moving mass, the actuator's inertial force m y''.

#include <limits>
#include <vector>

#include "selfalign/design/process_design.hpp"

namespace selfalign {

struct ActuatorSamples {
  double requested_rate = 0;  ///< [Hz]
  double sample_rate = 0;     ///< n / period [Hz]
  long long samples_per_period = 0;
  double moving_mass = std::numeric_limits<double>::quiet_NaN();  ///< [kg]; NaN: no force
  std::vector<double> t;      ///< [s]
  std::vector<double> y;      ///< [m]
  std::vector<double> y_dot;  ///< [m/s]
  std::vector<double> y_ddot; ///< [m/s^2]
  /// [m/s^3]: +-jerk on the ramps of a jerk-limited profile; 0 on a jump profile's plateaus
  /// (its jerk is impulsive at the switches).
  std::vector<double> y_dddot;
  std::vector<double> force;  ///< m y'' [N]; empty without a moving mass
};

/// Samples the recommended profile of a feasible design. rate [Hz] > 0 with at most 1e7
/// samples a period; moving_mass [kg] > 0, or NaN for none. Throws InvalidParameter.
ActuatorSamples actuator_samples(const DesignRequest& request, const DesignResult& design,
                                 double rate,
                                 double moving_mass = std::numeric_limits<double>::quiet_NaN());

}  // namespace selfalign
