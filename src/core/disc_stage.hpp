#pragma once
// Internal: the contact core's disc stage (issue 24, docs/rows.md section 10): the rigid bodies
// of a model with disc contacts (core::DiscContact). One Moreau step of the rigid bodies:
//   per body    rigid_body_prepare: its patch contacts and free relative twist at the midpoint
//   contacts    active where the gap between the discs at the step's midpoint is <= 0
//   coupling    block Gauss-Seidel over the active contacts: each body's patch problem solved
//               exactly (PatchImpulseSolver: exact stick) for the impulses of its contacts,
//               then each contact's normal impulse projected on >= 0 (Newton's target
//               -e min(u_n, 0)) and its tangential one on the Coulomb interval; until no
//               impulse changes by more than kDiscTolerance of the largest (or kDiscSweeps)
//   integrate   rigid_body_integrate
// A body in no active contact takes rigid_body_step itself (bit for bit as alone).

#include "selfalign/core/model.hpp"
#include "selfalign/core/state.hpp"
#include "selfalign/core/step_loads.hpp"

namespace selfalign::detail {

inline constexpr double kDiscTolerance = 1e-12;  // above the rounding limit cycles (~2e-14)
inline constexpr int kDiscSweeps = 10000;

// The checks of Model::disc_contacts (validate(Model) calls it).
void validate_disc_contacts(const core::Model& model);

// Throws InvalidParameter naming "poses[b]" where the discs of a contact overlap at the start.
void check_disc_overlap(const core::Model& model, const core::State& state);

// One Moreau step of every RigidBody of the model (sliders untouched); `loads[i]` body i's.
void disc_step(const core::Model& model, core::State& state, const PlanarTablePose& tb,
               const PlanarTablePose& tb1, const core::StepLoads* loads);

}  // namespace selfalign::detail
