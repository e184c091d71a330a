#pragma once
// Internal: the contact core's row stage (issue 24, docs/rows.md): the 1-D parts of a model
// with part contacts (core::PartContact). One Moreau step of the sliders:
//   per slider  its level at the step's midpoint, its free velocity v* (the 1-D Moreau step's:
//               the table's velocity increment along e1, gravity's pull) and its impulse bounds
//               (static to hold, kinetic forward and backward; per unit mass)
//   contacts    active where the gap at the step's midpoint is <= 0; Newton's target for the
//               relative velocity -e min(gap', 0)
//   chains      the sliders linked by active contacts, rear to front: one chain problem each
//               (core/chain_problem.hpp, static above kinetic: exact stick, no threshold);
//               a slider in no chain takes the 1-D Moreau step itself (moreau_slider_step),
//               so parts that do not touch move bit for bit as they do alone
//   integrate   x_{k+1} = x_k + h ((1 - theta) x'_k + theta x'_{k+1})
// Rigid bodies are not part of it (the core steps them as before).

#include "selfalign/core/model.hpp"
#include "selfalign/core/state.hpp"
#include "selfalign/simulate/motion_observer.hpp"

namespace selfalign::detail {

using core::BodyState;
using core::Model;
using core::PartContact;
using core::SliderBody;
using core::State;

// A 1-D part's step inputs: its level at the step's midpoint and its velocity without friction
// v* = x' - (y'(t_{k+1}) - y'(t_k)) (+ gravity's pull along e1).
struct SliderInputs {
  double level = 0, v_free = 0;
};
SliderInputs slider_inputs(const Model& model, const SliderBody& b, const PlanarTablePose& tb,
                           const PlanarTablePose& tb1, const core::StepLoads& loads,
                           double h, double x, double v);

// A lone 1-D part's step: its inputs, the 1-D Moreau projection (moreau_slider_step), the theta
// update; the step as the 1-D stepper's piece to the observer, if any.
void slider_step(const Model& model, const SliderBody& b, double h, double th,
                 const PlanarTablePose& tb, const PlanarTablePose& tb1,
                 const core::StepLoads& loads, double t1, int index, BodyState& st,
                 MotionObserver* observer);

// The step of slider `index` as the 1-D stepper's piece (t0 = t1 - h, as that stepper forms it).
void report_slider_step(MotionObserver& observer, double t1, double h, int index, double x,
                        double v, double x1, double v1);

// The checks of Model::part_contacts (validate(Model) calls it).
void validate_part_contacts(const Model& model);

// Sizes the row workspace and links each body to its contacts (make_state); throws
// InvalidParameter naming "poses[i]" where two parts of a contact overlap.
void prepare_row(const Model& model, State& state);

// One Moreau step of every SliderBody of the model (rigid bodies untouched): `loads[i]` is body
// i's step loads (after its normal stage); `tb`, `tb1` the table at t_k and t_{k+1}. Reports
// each slider's step to the observer as the core's slider step does, in body order.
void row_step(const Model& model, State& state, double t1, const PlanarTablePose& tb,
              const PlanarTablePose& tb1, const core::StepLoads* loads,
              MotionObserver* observer);

}  // namespace selfalign::detail
