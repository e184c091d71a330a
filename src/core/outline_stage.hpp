#pragma once
// Internal: the contact core's outline stage (issue 24, docs/rows.md section 10): the rigid
// bodies of a model with outline contacts (core::OutlineContact: discs and convex polygons).
// One Moreau step of the rigid bodies:
//   per body    rigid_body_prepare: its patch contacts and free relative twist at the midpoint
//   contacts    each contact's manifold at the midpoint poses (planar/outline.hpp); active
//               where its smallest gap is <= 0, with its points of gap <= kManifoldSlop
//   coupling    block Gauss-Seidel over the active contacts: each body's patch problem solved
//               exactly (PatchImpulseSolver: exact stick) for the impulses of its contacts,
//               then each contact's points (one or two) solved together exactly for their
//               impulses (free-body Delassus block, Coulomb's law, normal >= 0 with Newton's
//               target -e min(u_n, 0) or the speculative one; by enumeration of the points'
//               modes); until no impulse changes by more than kOutlineTolerance of the
//               largest (or kOutlineSweeps sweeps)
//   integrate   rigid_body_integrate
// A body in no active contact takes rigid_body_step itself (bit for bit as alone).

#include "selfalign/core/model.hpp"
#include "selfalign/core/state.hpp"
#include "selfalign/core/step_loads.hpp"

namespace selfalign::detail {

inline constexpr double kOutlineTolerance = 1e-12;  // above the rounding limit cycles (~2e-14)
inline constexpr int kOutlineSweeps = 10000;

// The checks of Model::outline_contacts (validate(Model) calls it).
void validate_outline_contacts(const core::Model& model);

// Throws InvalidParameter naming "poses[b]" where the outlines of a contact overlap at the
// start (by more than 1e-12 of their size: rounding).
void check_outline_overlap(const core::Model& model, const core::State& state);

// One Moreau step of every RigidBody of the model (sliders untouched); `loads[i]` body i's.
void outline_step(const core::Model& model, core::State& state, const PlanarTablePose& tb,
                  const PlanarTablePose& tb1, const core::StepLoads* loads);

}  // namespace selfalign::detail
