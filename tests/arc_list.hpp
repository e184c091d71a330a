#pragma once
// Every arc an exact solver delivers, in order (a MotionObserver for the tests).

#include <vector>

#include "selfalign/simulate/exact.hpp"

namespace selfalign::testing_support {

struct ArcList final : MotionObserver {
  std::vector<Arc> arcs;
  void on_motion(const MotionInterval&, const Arc* arc) override {
    const Arc& a = *arc;
    arcs.push_back(a);
  }
};

}  // namespace selfalign::testing_support
