#pragma once
// Every arc an exact solver delivers, in order (an ArcSink for the tests).

#include <vector>

#include "selfalign/simulate/exact.hpp"

namespace selfalign::testing_support {

struct ArcList final : ArcSink {
  std::vector<Arc> arcs;
  void on_arc(const Arc& a) override { arcs.push_back(a); }
};

}  // namespace selfalign::testing_support
