#pragma once
// Internal: one Moreau step of one rigid body on the table, the stages after the table's
// kinematics (planar_rigid.hpp for the scheme):
//   contacts    the patch's points at the midpoint pose, their field level read on the table
//   loads       each point's normal impulse: its load fraction of the step's normal impulse
//               (StepLoads: h for the paper's constant load; with core::Gravity
//               h cos(incline) + Δz'/g), and gravity's impulse along the incline
//   impulse     the friction impulse of the patch (PatchImpulseSolver, exact stick)
//   integrate   pose and twist at t_{k+1}
// The body stages of the contact core's step (src/core/contact_core.cpp, N bodies on one
// table); advance_planar_rigid runs the core on a model of one body, so a body of an N-body
// model moves bit for bit as it does alone.

#include <array>
#include <cmath>
#include <span>

#include "selfalign/friction/friction_law.hpp"
#include "selfalign/planar/patch_impulse.hpp"
#include "selfalign/core/step_loads.hpp"
#include "selfalign/planar/planar_field.hpp"
#include "selfalign/planar/planar_rigid.hpp"

namespace selfalign::detail {

// The loads stage's result for one step (core/step_loads.hpp).
using StepLoads = core::StepLoads;

// One rigid body's step in stages, so that bodies in contact with each other (core::
// OutlineContact) can exchange impulses between the impulse and the integrate stages:
//   rigid_body_prepare    contacts and loads at the midpoint pose, the free relative twist
//   rigid_body_solve      the patch's friction impulse (PatchImpulseSolver: exact stick) for
//                         the free twist plus an external impulse per unit mass (world axes)
//   rigid_body_integrate  pose and twist at t_{k+1}
// rigid_body_step runs them in a row with no external impulse.
struct RigidStage {
  std::array<double, 3> rel{};  // the free relative twist (v_x, v_y, omega), world axes
  double xm = 0, ym = 0;        // the centre's world position at the step's midpoint
  double am = 0;                // the body's world angle at the step's midpoint
  std::size_t n = 0;
  double inertia = 0;
  PlanarTwist u;                // the relative twist at t_k, table axes
  bool flying = false;          // no normal impulse: no friction
};

// BodyState has pose, twist, mode, pivot, sweeps, newton_steps and solver as PlanarRigidState.
// `tb` is the table at t_k, `tb1` at t_{k+1}; `contacts` a workspace of patch.size() entries.
template <class BodyState>
RigidStage rigid_body_prepare(const PlanarField& field, const FrictionLaw& law,
                              const RigidPart& part, double h, const PlanarTablePose& tb,
                              const PlanarTablePose& tb1, const StepLoads& loads,
                              const BodyState& st, std::span<PatchContact> contacts) {
  RigidStage g;
  const double j = part.inertia;
  g.inertia = j;
  const double s = law.static_coefficient(), k = law.kinetic_forward();
  const std::size_t n = part.patch.size();
  g.n = n;
  const PlanarTwist u = st.twist;
  g.u = u;
  // the body's world twist at t_k (world_twist of planar_rigid.hpp)
  const double c_t = std::cos(tb.angle), s_t = std::sin(tb.angle);
  const double rx = c_t * st.pose.x - s_t * st.pose.y, ry = s_t * st.pose.x + c_t * st.pose.y;
  PlanarTwist v{tb.vx - tb.rate * ry + c_t * u.ux - s_t * u.uy,
                tb.vy + tb.rate * rx + s_t * u.ux + c_t * u.uy, tb.rate + u.omega};
  if (loads.pulled) v.ux += loads.gx, v.uy += loads.gy;  // gravity's impulse: the free twist
  // contacts: midpoint poses on the table, of the table, in the world
  const double xi = st.pose.x + 0.5 * h * u.ux, eta = st.pose.y + 0.5 * h * u.uy;
  const double phi = st.pose.angle + 0.5 * h * u.omega;
  const double psi = tb.angle + 0.5 * h * tb.rate;
  const double cp = std::cos(psi), sp = std::sin(psi);
  const double xm = tb.x + 0.5 * h * tb.vx + cp * xi - sp * eta;
  const double ym = tb.y + 0.5 * h * tb.vy + sp * xi + cp * eta;
  g.xm = xm, g.ym = ym, g.am = psi + phi;
  const double cf = std::cos(phi), sf = std::sin(phi);
  const double ca = std::cos(psi + phi), sa = std::sin(psi + phi);
  for (std::size_t i = 0; i < n; ++i) {
    const ContactPoint& r = part.patch[i];
    const double level = planar_level(field, xi + cf * r.x - sf * r.y, eta + sf * r.x + cf * r.y);
    // loads: the point's load fraction of the step's normal impulse
    contacts[i] = {ca * r.x - sa * r.y, sa * r.x + ca * r.y, loads.load * s * level * r.load,
                   loads.load * k * level * r.load};
  }
  // impulse: the table's twist at t_{k+1} about X_M, the free relative twist
  const double tvx = tb1.vx - tb1.rate * (ym - tb1.y), tvy = tb1.vy + tb1.rate * (xm - tb1.x);
  g.rel = {v.ux - tvx, v.uy - tvy, v.omega - tb1.rate};
  // sliding on (the free relative twist keeps the previous one's direction): kinetic bounds
  // for the stick test too, as the 1-D and point schemes
  const double pvx = c_t * u.ux - s_t * u.uy, pvy = s_t * u.ux + c_t * u.uy;
  const bool sliding_on = st.mode != PatchMode::stick &&
                          g.rel[0] * pvx + g.rel[1] * pvy + j * g.rel[2] * u.omega > 0;
  if (sliding_on)
    for (std::size_t i = 0; i < n; ++i) contacts[i].stick_bound = contacts[i].slip_bound;
  g.flying = loads.load == 0;
  return g;
}

// The patch's impulse for the free relative twist `rel` (the stage's, plus any impulse from
// other bodies); in flight (core::Gravity::flight: no normal impulse) the free twist.
template <class BodyState>
PatchImpulseResult rigid_body_solve(const RigidStage& g, const std::array<double, 3>& rel,
                                    BodyState& st, std::span<PatchContact> contacts) {
  PatchImpulseResult r;
  if (g.flying) r.twist = rel, r.mode = PatchMode::slip;
  else r = st.solver.solve(contacts.first(g.n), g.inertia, rel);
  return r;
}

template <class BodyState>
void rigid_body_integrate(double h, double th, const PlanarTablePose& tb1, const RigidStage& g,
                          const PatchImpulseResult& r, BodyState& st) {
  const PlanarTwist u = g.u;
  const double c1 = std::cos(tb1.angle), s1 = std::sin(tb1.angle);
  const PlanarTwist u1{c1 * r.twist[0] + s1 * r.twist[1], -s1 * r.twist[0] + c1 * r.twist[1],
                       r.twist[2]};
  st.pose.x += h * ((1 - th) * u.ux + th * u1.ux);
  st.pose.y += h * ((1 - th) * u.uy + th * u1.uy);
  st.pose.angle += h * ((1 - th) * u.omega + th * u1.omega);
  st.twist = u1;
  st.mode = r.mode, st.pivot = r.pivot;
  st.sweeps += r.sweeps, st.newton_steps += r.newton_steps;
}

template <class BodyState>
void rigid_body_step(const PlanarField& field, const FrictionLaw& law, const RigidPart& part,
                     double h, double th, const PlanarTablePose& tb, const PlanarTablePose& tb1,
                     const StepLoads& loads, BodyState& st, std::span<PatchContact> contacts) {
  const RigidStage g = rigid_body_prepare(field, law, part, h, tb, tb1, loads, st, contacts);
  rigid_body_integrate(h, th, tb1, g, rigid_body_solve(g, g.rel, st, contacts), st);
}

}  // namespace selfalign::detail
