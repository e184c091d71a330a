#pragma once
/// \file motion_observer.hpp
/// The one observer interface of every stepper (issue 21): the 1-D steppers and the contact
/// core's staged step (core/step.hpp) alike.
///
/// Every 1-D stepper (simulate/stepper.hpp) hands the motion it computes to a MotionObserver,
/// one piece at a time and in time order:
///   exact, smooth exact   one piece per arc, with the arc itself (its closed form: shape,
///                         transition matrix, ...) as the optional payload
///   slip integrator       one piece per stick or slip interval (no closed form), and the
///                         crossings of watched positions (on_crossing)
///   time-stepping         one piece per time step (end = ArcEnd::time_step, no closed form)
/// An observer that needs the closed form (saltation matrices, arc lists) reads `arc` and is
/// given to the closed-form steppers only (PeriodMap::arcs() checks); every other observer
/// (census, stopping, positioning, convergence, reach) works with any stepper.
///
/// The contact core's step (core::step) hands the same observer each 1-D part's time step as a
/// piece (its `body` the part's index in the model; a SliderBody moves as the 1-D time-stepping
/// stepper moves the part, piece for piece), then the whole state after the step (on_step:
/// every body's pose, twist and contact mode, the table's pose): what the planar analyses and
/// run driver observe. An observer overrides what it reads; the rest do nothing.

#include <algorithm>
#include <cstdint>
#include <limits>

namespace selfalign {

struct Arc;
namespace core {
struct State;
}

/// What ended a piece of the motion.
enum class ArcEnd : std::uint8_t {
  acceleration_switch,  ///< the table acceleration's segment ended
  velocity_zero,        ///< x' reached 0 (the stick/slip decision follows)
  friction_boundary,    ///< x reached the end of a friction piece (e.g. x_mu or x_mu + w)
  horizon,              ///< the requested end time
  stick_break,          ///< |y''| reached the static bound s m(x) inside a segment (finite jerk)
  time_step,            ///< one step of Moreau's time-stepping scheme ended
  part_contact          ///< two parts of a row collided (the exact row solver)
};

/// One piece of the motion: a stick, or a slip in one direction, from t0 to t1.
struct MotionInterval {
  double t0 = 0, t1 = 0;      ///< start and end time [-]
  double x0 = 0, xd0 = 0;     ///< state at t0 [-]
  double x1 = 0, xd1 = 0;     ///< state at t1 [-]
  /// +1 forward slip, -1 backward slip, 0 stick. A time step's direction is that of x' at its
  /// end (0: the step ended at rest).
  std::int8_t direction = 0;
  ArcEnd end = ArcEnd::horizon;
  /// The body the piece moves: its index in a contact-core model (core::step); 0 for the 1-D
  /// steppers' one part.
  std::int32_t body = 0;
};

/// The one observer interface of the steppers (1-D and the contact core).
class MotionObserver {
 public:
  virtual ~MotionObserver() = default;
  /// The next piece of a 1-D motion. `arc` is its closed form when the stepper has one (exact
  /// and smooth-exact solvers: then `piece` is `*arc`), nullptr otherwise.
  virtual void on_motion(const MotionInterval& piece, const Arc* arc) {
    (void)piece, (void)arc;
  }
  /// A watched position crossed at `time` by the slip in `direction` (+1, -1) that the next
  /// on_motion call closes (slip integrator, asked to watch positions).
  virtual void on_crossing(double position, double time, int direction) {
    (void)position, (void)time, (void)direction;
  }
  /// A step of the contact core ended (core::step): `state` holds every body after it (after
  /// the on_motion calls of its 1-D parts' pieces for the step).
  virtual void on_step(const core::State& state) { (void)state; }
};

/// The farthest forward the motion reached: x is monotone on every piece (each ends at every
/// velocity zero; a time step is one straight move), so the ends of the pieces bound it.
struct Reach final : MotionObserver {
  double x;  ///< the largest x seen so far [-]
  explicit Reach(double x0 = -std::numeric_limits<double>::infinity()) : x(x0) {}
  void on_motion(const MotionInterval& piece, const Arc*) override {
    x = std::max({x, piece.x0, piece.x1});
  }
};

}  // namespace selfalign
