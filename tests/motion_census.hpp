#pragma once
// Test support: what kinds of motion an exact solution contains over a time window.
#include "selfalign/simulate/exact.hpp"

namespace selfalign::testing_support {

struct MotionCensus final : ArcSink {
  int stick = 0, forward = 0, backward = 0, parabolic = 0, harmonic = 0, hyperbolic = 0;
  int velocity_zero = 0, boundary = 0;
  void on_arc(const Arc& a) override {
    if (a.kind == ArcKind::stick) ++stick;
    if (a.direction > 0) ++forward;
    if (a.direction < 0) ++backward;
    if (a.kind == ArcKind::parabolic) ++parabolic;
    if (a.kind == ArcKind::harmonic) ++harmonic;
    if (a.kind == ArcKind::hyperbolic) ++hyperbolic;
    if (a.end == ArcEnd::velocity_zero) ++velocity_zero;
    if (a.end == ArcEnd::friction_boundary) ++boundary;
  }
  /// Table 1 case read off the arcs (uniform friction, one steady period): 1 stick-slip x' >= 0,
  /// 2 stick-slip x' <= 0, 3 general stick-slip, 4 slip-slip, 5 pure stick.
  int table1_case() const {
    if (forward == 0 && backward == 0) return 5;
    if (stick == 0) return 4;
    if (backward == 0) return 1;
    if (forward == 0) return 2;
    return 3;
  }
};

}  // namespace selfalign::testing_support
