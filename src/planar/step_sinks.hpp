#pragma once
// Internal: what the planar analyses share (planar_analysis.cpp, planar_steady_state.cpp): the
// per-step observers (the stick/pivot/slip census, and the range of the mean friction level
// under the patch, level_under_patch, over the steps seen) and the check of a run's status.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "selfalign/planar/planar_analysis.hpp"

namespace selfalign::detail {

// The analyses run one body (advance_planar_rigid): bodies[0] of the core's state.
struct CensusSink : MotionObserver {
  PlanarCensus census;
  void on_step(const core::State& s) override { census.add(s.bodies[0].mode); }
};

struct LevelSink : MotionObserver {
  const PlanarField& field;
  const ContactPatch& patch;
  CensusSink* census = nullptr;  // also counts the steps' modes when given
  double lo = INFINITY, hi = -INFINITY;
  LevelSink(const PlanarField& f, const ContactPatch& p) : field(f), patch(p) {}
  void on_step(const core::State& s) override {
    const double level = level_under_patch(field, patch, s.bodies[0].pose);
    lo = std::min(lo, level);
    hi = std::max(hi, level);
    if (census) census->on_step(s);
  }
};

// A number in three significant digits, for messages.
inline std::string compact(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// A run fails (a study keeps its cell with this message; the steady state throws it) when the
// core's checks found its state or the table's motion outside the finite numbers: inputs near
// overflow, or a profile that returns NaN (the step's stick test is false for NaN, so such a
// run would otherwise report a stop, or a steady state with no drift).
inline void require_finite(const PlanarRigidState& s) {
  if (s.status != core::StepStatus::ok)
    throw std::runtime_error("the state or the table motion left the finite numbers at t = " +
                             compact(s.t));
}

}  // namespace selfalign::detail
