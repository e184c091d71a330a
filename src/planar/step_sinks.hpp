#pragma once
// Internal: the per-step observers the planar analyses share (planar_analysis.cpp,
// planar_steady_state.cpp): the stick/pivot/slip census, and the range of the mean friction
// level under the patch (level_under_patch) over the steps seen.

#include <algorithm>
#include <cmath>

#include "selfalign/planar/planar_analysis.hpp"

namespace selfalign::detail {

struct CensusSink : PlanarStepSink {
  PlanarCensus census;
  void on_step(const PlanarRigidState& s) override { census.add(s.mode); }
};

struct LevelSink : PlanarStepSink {
  const PlanarField& field;
  const ContactPatch& patch;
  CensusSink* census = nullptr;  // also counts the steps' modes when given
  double lo = INFINITY, hi = -INFINITY;
  LevelSink(const PlanarField& f, const ContactPatch& p) : field(f), patch(p) {}
  void on_step(const PlanarRigidState& s) override {
    const double level = level_under_patch(field, patch, s.pose);
    lo = std::min(lo, level);
    hi = std::max(hi, level);
    if (census) census->on_step(s);
  }
};

}  // namespace selfalign::detail
