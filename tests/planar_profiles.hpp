#pragma once
// The two table motions the planar point-contact tests drive along x and y.

#include "selfalign/profiles/three_phase.hpp"

namespace selfalign::testing_support {

inline const ThreePhaseProfile kPaper({1.0, 0.084, 3.0, 0.9});  // Sect. 7.2
inline const ThreePhaseProfile kCross({0.7, 0.05, 2.2, 1.4});   // a second, different motion

}  // namespace selfalign::testing_support
