#include "selfalign/planar/planar_rigid.hpp"

#include <cmath>

#include "selfalign/error.hpp"

namespace selfalign {

void validate(const RigidPart& part) {
  require_positive_moderate("inertia", part.inertia);
  validate(part.patch);
}

PlanarRigidState make_planar_rigid_state(const PlanarTableMotion& motion, double t,
                                         const PlanarPose& pose, const PlanarTwist& twist) {
  validate(motion);
  require_moderate("t0", t);
  for (double v : {pose.x, pose.y, pose.angle}) require_moderate("pose", v);
  for (double v : {twist.ux, twist.uy, twist.omega}) require_moderate("twist", v);
  PlanarRigidState s;
  s.t0 = s.t = t;
  s.table = table_pose(motion, t);
  s.pose = pose, s.twist = twist;
  s.mode = twist.ux == 0 && twist.uy == 0 && twist.omega == 0 ? PatchMode::stick : PatchMode::slip;
  return s;
}

PlanarPose world_pose(const PlanarTablePose& table, const PlanarPose& pose) {
  const double c = std::cos(table.angle), sn = std::sin(table.angle);
  return {table.x + c * pose.x - sn * pose.y, table.y + sn * pose.x + c * pose.y,
          table.angle + pose.angle};
}

PlanarPose world_pose(const PlanarRigidState& s) { return world_pose(s.table, s.pose); }

PlanarTwist world_twist(const PlanarTablePose& table, const PlanarPose& pose,
                        const PlanarTwist& twist) {
  const double c = std::cos(table.angle), sn = std::sin(table.angle);
  const double rx = c * pose.x - sn * pose.y, ry = sn * pose.x + c * pose.y;
  return {table.vx - table.rate * ry + c * twist.ux - sn * twist.uy,
          table.vy + table.rate * rx + sn * twist.ux + c * twist.uy, table.rate + twist.omega};
}

PlanarTwist world_twist(const PlanarRigidState& s) { return world_twist(s.table, s.pose, s.twist); }

void advance_planar_rigid(const PlanarTableMotion& motion, const PlanarField& field,
                          const FrictionLaw& law, const RigidPart& part,
                          const TimeSteppingOptions& o, PlanarRigidState& st, long long steps,
                          MotionObserver* observer) {
  // Checked here too, so that errors name the part's own parameters (the core's name the body).
  validate(o);
  validate(motion);
  validate(field);
  validate(part);
  require_planar_law(law);
  // The part as the one body of a core model, its state as the core's: one staged step.
  const core::Model model{motion, field, {core::RigidBody{part, law}}, o};
  core::State s;
  s.t0 = st.t0, s.t = st.t, s.step_index = st.step_index, s.table = st.table;
  s.bodies.push_back({st.pose, st.twist, st.mode, st.pivot, st.sweeps, st.newton_steps,
                      std::move(st.solver)});
  s.contacts.assign(1, std::vector<PatchContact>(part.patch.size()));
  s.status = st.status;
  core::step(model, s, steps, observer);
  st.status = s.status;
  core::BodyState& b = s.bodies[0];
  st.t = s.t, st.step_index = s.step_index, st.table = s.table;
  st.pose = b.pose, st.twist = b.twist, st.mode = b.mode, st.pivot = b.pivot;
  st.sweeps = b.sweeps, st.newton_steps = b.newton_steps;
  st.solver = std::move(b.solver);
}

}  // namespace selfalign
