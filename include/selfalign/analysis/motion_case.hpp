#pragma once
/// \file motion_case.hpp
/// The motion cases of Table 1 (Sect. 5.1), found two independent ways:
///  - a priori from (Δt, Δy, y2'', y3'') alone: the decision rules of the paper's flow chart
///    (Fig. 8, missing from the text), derived in docs/motion-cases.md;
///  - a posteriori from the arcs of one simulated steady-state period (MotionCensus).

#include <cstdint>
#include <string>

#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/simulate/exact.hpp"

namespace selfalign {

/// Table 1, plus the non-physical case 0 (Sect. 5.1).
enum class StickSlipCase : int {
  non_physical = 0,         ///< case 0: no three-phase profile with this stroke exists
  stick_slip_forward = 1,   ///< case 1: stick-slip with x' >= 0 (desirable)
  stick_slip_backward = 2,  ///< case 2: stick-slip with x' <= 0 (undesirable)
  general_stick_slip = 3,   ///< case 3: stick-slip in both directions
  slip_slip = 4,            ///< case 4: never sticks
  pure_stick = 5            ///< case 5: no relative motion
};

/// "stick-slip x' >= 0", ... (Table 1's descriptions).
std::string describe(StickSlipCase c);

/// A priori case of the three-phase profile (Fig. 8). With a = y2'', b = y3'' and the
/// interval lengths T1 = t1, T2 = t2 - t1, T3 = t3 - t2 of solve_three_phase:
///   not physical                  -> 0
///   a <= 1, b <= 1                -> 5 (|y''| <= 1 throughout: the object never slips)
///   a >  1, b <= 1                -> 1
///   a <= 1, b >  1                -> 2
///   a >  1, b >  1: with the object at rest at t1, it stops in [t2, t3] after
///     tau_s = (a - 1) T2 / (1 + b) and slides back to x'(t3) = -(b - 1)(T3 - tau_s);
///     |x'(t3)| < T1 (it stops again before t1)  -> 3, otherwise -> 4.
/// Throws InvalidParameter on misuse (non-positive or NaN parameters).
StickSlipCase predict_case(const ThreePhaseParameters& p);
/// The same from p's solved profile r = solve_three_phase(p) (a sweep solves it once per cell).
StickSlipCase predict_case(const ThreePhaseParameters& p, const ThreePhaseSolution& r);

/// What kinds of motion the pieces of a time window contain (feed it a steady-state period),
/// from any stepper: arcs, the integrator's intervals, or time steps. A time step ending at
/// x' = 0 counts as a stick only when the step before also did: a slip reversal can land one
/// step on x' = 0 (|v*| <= h m while the velocity crosses zero), which is no stick of the
/// response.
struct MotionCensus final : MotionObserver {
  int stick = 0;     ///< stick pieces of positive length (time-stepping: runs of x' = 0)
  int forward = 0;   ///< forward-slip pieces (x' > 0)
  int backward = 0;  ///< backward-slip pieces (x' < 0)
  /// The window's classes in time order, consecutive repeats merged: 0 stick, +1, -1 slip.
  std::string sequence;
  void on_motion(const MotionInterval& piece, const Arc* arc) override;
  /// A new window begins (PeriodMap calls it for each period): the run of time steps at
  /// x' = 0 starts afresh.
  void begin_window() noexcept { zero_steps_ = 0; }
  /// Table 1 case of the window: 5 only stick, 4 no stick, 1 no backward, 2 no forward, else 3.
  StickSlipCase motion_case() const;
  /// The window's stick/slip sequence as a cyclic pattern (a period: the first class merged
  /// with the last when equal), rotated to start at a stick where there is one, else at a forward slip: e.g.
  /// "stick,forward", "stick,forward,backward", "forward,backward", "stick,forward,stick,
  /// backward" (a pattern Table 1 has no name for: two sticks a period, possible with
  /// static > kinetic or finite jerk). Empty for an empty window.
  std::string pattern() const;

 private:
  int zero_steps_ = 0;  // consecutive time steps that ended at x' = 0
};

}  // namespace selfalign
