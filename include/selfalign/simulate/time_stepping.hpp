#pragma once
/// \file time_stepping.hpp
/// Moreau's time-stepping method (Sect. 4.1) for eq. (6) with any TableProfile, FrictionMap and
/// Coulomb law.
///
/// One step from t_k to t_{k+1} = t_k + h:
///   x_M      = x_k + (h/2) x'_k                              (midpoint: where friction is read)
///   x'_{k+1} = x'_k - (y'(t_{k+1}) - y'(t_k)) - h m(x_M) s,  s ∈ Sign(x'_{k+1})
///   x_{k+1}  = x_k + h ((1 - theta) x'_k + theta x'_{k+1})   (theta-method)
/// The table enters through its exact velocity increment (the impulse of y'' over the step), so
/// acceleration switches inside a step are integrated exactly. For one degree of freedom the
/// set-valued velocity equation has the closed-form solution (a projection, no fixed-point
/// iteration): with v* = x'_k - Δy' and P = h m(x_M),
///   |v*| <= P  ->  x'_{k+1} = 0 (stick);   otherwise  x'_{k+1} = v* - P sign(v*).
/// With static coefficient s above the kinetic k_sigma (friction_law.hpp) the projection
/// uses the static bound P_s = h s m(x_M) for sticking and the kinetic impulse
/// P_k = h k_sigma m(x_M), sigma = sign(v*), for sliding:
///   from rest or reversing (x'_k = 0 or sign v* != sign x'_k): stick iff |v*| <= P_s;
///   sliding on (sign v* = sign x'_k):                           stop  iff |v*| <= P_k;
///   otherwise x'_{k+1} = v* - P_k sigma.
/// The scheme stays first order (tests/test_friction_law.cpp measures it); for s = k it is the
/// projection above, term for term. A velocity-dependent law (Stribeck, viscous) takes its
/// speed-dependent part explicitly, at the step's start: sliding on, P_k = h mu_sigma(|x'_k|)
/// m(x_M) + h c |x'_k| (stop iff |v*| <= P_k); from rest or reversing, the stick test as above
/// and P_k = h mu_sigma(0) m(x_M). Still first order; the set-valued stick stays implicit.

#include <cstddef>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/simulate/motion_observer.hpp"
#include "selfalign/simulate/object_state.hpp"

namespace selfalign {

struct TimeSteppingOptions {
  double step = 1e-4;   ///< step size h [-], > 0
  double theta = 0.5;   ///< theta of the position update, in [0, 1]
};

/// Throws InvalidParameter unless 0 < step and 0 <= theta <= 1.
void validate(const TimeSteppingOptions& options);

/// Mutable state of the stepper. Step times are t0 + k h (no accumulated rounding).
struct TimeSteppingState {
  ObjectState object;        ///< t, x, x' [-]
  double t0 = 0;             ///< time of step 0 [-]
  long long step_index = 0;  ///< k
  double table_velocity = 0; ///< y'(t_k) [-]
  bool stick = false;        ///< whether the last step ended in stick
};

/// Starts a stepper at an object state.
TimeSteppingState make_time_stepping_state(const TableProfile& profile, const ObjectState& object);

/// Advances by `steps` steps under `law`; calls observer->on_motion (if any) with each completed
/// step (end = ArcEnd::time_step, arc = nullptr). Allocates nothing.
void advance_time_stepping(const TableProfile& profile, const FrictionMap& friction,
                           const FrictionLaw& law, const TimeSteppingOptions& options,
                           TimeSteppingState& state, long long steps,
                           MotionObserver* observer = nullptr);
/// The same under the paper's law (static = kinetic = 1).
inline void advance_time_stepping(const TableProfile& profile, const FrictionMap& friction,
                                  const TimeSteppingOptions& options, TimeSteppingState& state,
                                  long long steps, MotionObserver* observer = nullptr) {
  advance_time_stepping(profile, friction, FrictionLaw{}, options, state, steps, observer);
}

}  // namespace selfalign
