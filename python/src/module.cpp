// PYBIND11_MODULE: the order matters only where a signature names a type bound elsewhere
// (base classes and argument types are bound first so docstrings show their Python names).
#include "bindings.hpp"

PYBIND11_MODULE(_selfalign, m) {
  using namespace selfalign::python;
  m.doc() =
      "selfalign: vibrational self-alignment of a rigid object on a periodically moving table\n"
      "with Coulomb stick-slip friction (Hunnekens, Fey, Shukla & Nijmeijer, Nonlinear Dynamics\n"
      "2010). Everything is dimensionless (Sect. 3.2) unless stated; Scales converts to SI.";
  bind_errors(m);
  bind_units(m);
  bind_friction(m);
  bind_profiles(m);
  bind_three_phase(m);
  bind_simulate(m);
  bind_solvers(m);
  bind_steady_state(m);
  bind_floquet(m);
  bind_convergence(m);
  bind_sweep(m);
  bind_stopping(m);
  bind_positioning(m);
  bind_optimize(m);
  bind_design(m);
  bind_uncertainty(m);
  bind_planar(m);
  bind_parameters(m);
  bind_feeder(m);
  bind_rows(m);
  bind_row_monte_carlo(m);
  bind_measured_motion(m);
  bind_identification(m);
  finish_classes(m);
}
