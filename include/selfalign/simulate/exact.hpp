#pragma once
/// \file exact.hpp
/// Exact event-driven solution of eq. (6) with a position-dependent friction level (eq. 38)
/// and a Coulomb law with static >= kinetic coefficients, for a table whose acceleration is
/// piecewise polynomial of degree <= 1 (constant or affine in time on each segment).
///
/// Between events the motion is one closed-form Arc (arc.hpp). Every event is located as a
/// root of a closed form:
///   - table segment ends: exact by construction;
///   - x' = 0: parabolic -x'/x'' (eq. 21); harmonic via atan2 (eq. 47, valid on all quadrants);
///     hyperbolic via atanh; under finite jerk, in the certified bracket between consecutive
///     zeros of x'' (src/simulate/arc_events.hpp), where x' is monotone;
///   - entering or leaving a friction piece (x_mu, x_mu + w): a root of the arc's quadratic,
///     cosine or exponential-quadratic, or under finite jerk in its certified bracket (x is
///     monotone until x' = 0);
///   - stick breaking inside a segment (finite jerk): |y''(t)| = s m(x), linear in t;
///   - at x' = 0 the set-valued law decides: stick if |y''| <= s m(x) (static coefficient s),
///     else slip in the direction of -y'' with the kinetic coefficient (eqs. 2, 6).
/// Between events x is monotone, so exactly one friction boundary can be next.

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/simulate/arc.hpp"

namespace selfalign {

/// The fixed system the exact solver integrates: a profile and a friction map, both borrowed
/// (they must outlive the setup), and the friction law (the paper's static = kinetic = 1 by
/// default).
struct ExactSetup {
  const PiecewisePolynomialProfile& profile;
  const PiecewiseAffineFriction& friction;
  FrictionLaw law{};
};

/// Mutable state of the exact solver: the object state plus where it is in the profile.
struct ExactState {
  ObjectState object;          ///< t, x, x' [-]
  std::size_t segment = 0;     ///< current acceleration segment
  long long period_index = 0;  ///< floor(t / Δt): segment times are period_index*Δt + begin
};

/// Places an object state in the profile (finds its period and segment). Throws
/// InvalidParameter for a non-finite state or |t| beyond 1e15 periods.
ExactState make_exact_state(const ExactSetup& setup, const ObjectState& object);

/// Advances state to time t_end (>= state.object.t), calling observer->on_motion(arc, &arc) (if
/// any) for every arc.
/// Returns the number of arcs computed. Allocates nothing. Throws InvalidParameter for an
/// infinite t_end, or a state whose segment / period_index do not hold its time (a state not
/// made by make_exact_state or advance_exact).
std::size_t advance_exact(const ExactSetup& setup, ExactState& state, double t_end,
                          MotionObserver* observer = nullptr);

}  // namespace selfalign
