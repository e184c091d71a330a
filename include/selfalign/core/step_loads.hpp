#pragma once
/// \file step_loads.hpp
/// The loads stage's result for one step of the contact core (core/step.hpp), per body: the
/// normal impulse per unit weight (h: the paper's constant normal load; with core::Gravity
/// h cos(incline) + Δz'/g, or Moreau-Jean's impulse P/g with flight), and gravity's impulse
/// per unit mass in the table's plane, world axes (applied only when `pulled`: the paper's
/// model adds nothing, not even a zero).

namespace selfalign::core {

struct StepLoads {
  double load = 0;
  double gx = 0, gy = 0;
  bool pulled = false;
};

}  // namespace selfalign::core
