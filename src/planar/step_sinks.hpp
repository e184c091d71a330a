#pragma once
// Internal: the per-step observers the planar analyses share (planar_analysis.cpp,
// planar_steady_state.cpp): the stick/pivot/slip census, and the range of the mean friction
// level under the patch (level_under_patch) over the steps seen.

#include <algorithm>
#include <cmath>

#include "selfalign/planar/planar_analysis.hpp"

namespace selfalign::detail {

// The analyses run one body (advance_planar_rigid): bodies[0] of the core's state.
struct CensusSink : core::StepObserver {
  PlanarCensus census;
  void on_step(const core::State& s) override { census.add(s.bodies[0].mode); }
};

struct LevelSink : core::StepObserver {
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

}  // namespace selfalign::detail
