#pragma once
// examples/queue.toml written out (docs/rows.md section 8): three parts with gaps reach a step
// to level 4 on the paper's Sect. 7.2 table; the tests that run the example through the CLI
// compare against the library on this process.

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/robust/row_monte_carlo.hpp"

namespace selfalign::testing_support {

inline RowProcess example_queue() {
  RowProcess p;
  p.table = {1.0, 0.084, 3.0, 0.9};
  p.step_position = 1.5;
  p.c_mu = 4.0;
  p.queue.parts = {{0.25, 1.0, FrictionLaw(1.1, 0.8), 0.0, 0.0},
                   {0.25, 1.0, FrictionLaw(1.2, 1.0), 0.375, 0.0},
                   {0.25, 1.0, FrictionLaw(1.2, 1.0), 0.75, 0.0}};
  return p;
}

}  // namespace selfalign::testing_support
