#pragma once
/// \file final_stick.hpp
/// The one stopping criterion of every stepper (issue 21): stuck for a whole table period.
///
/// The table's motion repeats every period Δt. A part that has been at rest on the table
/// through a whole period (at its end at the same place on the table, at rest, at the same
/// phase as at its start) repeats that period for ever, the motion being deterministic: it is
/// stuck for good, and its process time T_p is the start of that final stick. This holds for
/// every stepper: the exact 1-D solvers (there, stuck through a period at x is eq. (40) at x,
/// s m(x) >= |y''| at every phase), the slip integrator, and Moreau's time-stepping of the 1-D
/// part and of the contact core's bodies (a step that ends at rest is a stick: the step's
/// friction impulse held the part, and the same step of every later period holds it again).
///
/// FinalStick observes a run through the one observer interface (motion_observer.hpp) and keeps
/// when the current stick began:
///   1-D pieces   a piece that ends moving (direction != 0: a slip arc, the integrator's slip
///                interval, a time step ending with x' != 0) ends where any stick that follows
///                begins: since = piece.t1;
///   core steps   a step after which the watched body (or any body) is not in stick: since =
///                the step's end.
/// The 1-D stopping run (stopping.hpp) proves a stop sooner where the paper has the closed
/// form (eq. 40 at the first rest, eqs. 59, 60 for accumulation) and falls back on this
/// criterion elsewhere; the planar stop (planar_analysis.hpp) uses it alone. Both take T_p from
/// it.

#include "selfalign/core/state.hpp"
#include "selfalign/simulate/motion_observer.hpp"

namespace selfalign {

class FinalStick final : public MotionObserver {
 public:
  /// A run from time t0; `body`: the contact-core body watched (its pieces and its mode), -1
  /// (the default) for every piece and every body (a 1-D stepper's one part: any).
  explicit FinalStick(double t0, int body = -1) noexcept : since_(t0), body_(body) {}
  /// When the current stick began: the end of the last piece or step that ended moving (the
  /// run's start when none has) [-].
  double since() const noexcept { return since_; }
  /// Whether the part has been stuck through the whole window after `window_start` (the time of
  /// the look one table period before this one, as the run formed it): nothing ended moving
  /// after it.
  bool stuck_since(double window_start) const noexcept { return since_ <= window_start; }

  void on_motion(const MotionInterval& piece, const Arc*) override {
    if (piece.direction != 0 && (body_ < 0 || piece.body == body_)) since_ = piece.t1;
  }
  void on_step(const core::State& state) override {
    for (std::size_t i = 0; i < state.bodies.size(); ++i)
      if ((body_ < 0 || static_cast<int>(i) == body_) &&
          state.bodies[i].mode != PatchMode::stick)
        since_ = state.t;
  }

 private:
  double since_;
  int body_;
};

}  // namespace selfalign
