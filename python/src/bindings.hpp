#pragma once
// The Python module selfalign._selfalign: one bind function per area of the library, each in
// its own file (errors.cpp, units.cpp, ...). Thin: parse arguments, call the library, convert
// results to NumPy; no physics here.

#include <pybind11/pybind11.h>

#include "int_enum.hpp"

namespace selfalign {
struct RowQueue;
struct SimulateConfig;
}  // namespace selfalign

namespace selfalign::python {

namespace py = pybind11;

void bind_errors(py::module_& m);        // InvalidParameter -> selfalign.InvalidParameter
void bind_units(py::module_& m);         // Scales
void bind_friction(py::module_& m);      // FrictionLaw, FrictionMap and its kinds, FrictionField
void bind_profiles(py::module_& m);      // TableProfile, piecewise-constant, Fourier, sampled
void bind_three_phase(py::module_& m);   // ThreePhase*, JerkLimitedThreePhase*
void bind_simulate(py::module_& m);      // ObjectState, Method, SimulationOptions, simulate
void bind_solvers(py::module_& m);       // exact solver (arcs), time stepping, PeriodMap
void bind_steady_state(py::module_& m);  // StickSlipCase, predict_case, steady_state
void bind_floquet(py::module_& m);       // floquet_multipliers
void bind_convergence(py::module_& m);   // velocity_convergence
void bind_sweep(py::module_& m);         // grids, families, sweeps
void bind_stopping(py::module_& m);      // stick positions, stopping runs
void bind_positioning(py::module_& m);   // positioning accuracy and surfaces
void bind_optimize(py::module_& m);      // profile optimisation (Sect. 4.4.2)
void bind_design(py::module_& m);        // design_process: SI limits -> recommended profile
void bind_uncertainty(py::module_& m);   // distributions, Monte Carlo, worst case, design_robust
void bind_planar(py::module_& m);        // contact patches, planar fields, rigid-part runs (issue 13)
void bind_parameters(py::module_& m);    // the parameter view: model_parameters, with_parameters
void bind_feeder(py::module_& m);        // the vibratory feeder: drive, onsets, runs (issue 23)
void bind_rows(py::module_& m);          // queues of 1-D parts: RowPart, RowQueue, row_run, row_stop (issue 24)
void bind_row_monte_carlo(py::module_& m);  // row_monte_carlo, RowMonteCarloResult (after rows, uncertainty)
void bind_measured_motion(py::module_& m);  // read_measured_motion (issue 25)
void bind_identification(py::module_& m);   // identify, Identification (issue 25)
/// A `queue` argument: a RowQueue, or a list of RowPart (restitution 0); TypeError otherwise (rows.cpp).
RowQueue to_row_queue(const py::handle& queue);

/// A model config from a dict of config keys (the keys of `selfalign simulate`'s config files;
/// arrays as lists), as model_parameters takes it (parameters.cpp). Throws InvalidParameter.
SimulateConfig config_of(const py::dict& d);

/// Rules for every class bound above (classes.cpp): an object whose __init__ was not called
/// raises TypeError when used; pickling under every protocol, or a TypeError. Called last.
void finish_classes(py::module_& m);

}  // namespace selfalign::python
