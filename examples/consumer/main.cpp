// Steady-state displacement per period of the paper's case-1 setting, with the exact solver.
#include <cstdio>

#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/simulate/exact.hpp"

int main() {
  using namespace selfalign;
  const ThreePhaseProfile profile({/*period*/ 1.0, /*stroke*/ 0.084, /*a2*/ 3.0, /*a3*/ 0.9});
  const UniformFriction friction;
  const ExactSetup setup{*profile.piecewise_polynomial(), *friction.piecewise_affine()};
  ExactState state = make_exact_state(setup, {0.0, 0.0, 0.0});
  advance_exact(setup, state, 10.0);
  std::printf("x(10) = %.12f\n", state.object.x);
  return state.object.x > 0 ? 0 : 1;
}
