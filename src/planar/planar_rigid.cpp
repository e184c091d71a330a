#include "selfalign/planar/planar_rigid.hpp"

#include <cmath>

#include "selfalign/error.hpp"
#include "rigid_body_step.hpp"

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

PlanarTwist world_twist(const PlanarRigidState& s) {
  const double c = std::cos(s.table.angle), sn = std::sin(s.table.angle);
  const double rx = c * s.pose.x - sn * s.pose.y, ry = sn * s.pose.x + c * s.pose.y;
  return {s.table.vx - s.table.rate * ry + c * s.twist.ux - sn * s.twist.uy,
          s.table.vy + s.table.rate * rx + sn * s.twist.ux + c * s.twist.uy,
          s.table.rate + s.twist.omega};
}

void advance_planar_rigid(const PlanarTableMotion& motion, const PlanarField& field,
                          const FrictionLaw& law, const RigidPart& part,
                          const TimeSteppingOptions& o, PlanarRigidState& st, long long steps,
                          PlanarStepSink* sink) {
  validate(o);
  validate(motion);
  validate(field);
  validate(part);
  require_planar_law(law);
  std::vector<PatchContact> contacts(part.patch.size());
  for (long long step = 0; step < steps; ++step) {
    // kinematics: the table at t_{k+1}; then the body's stages (rigid_body_step.hpp)
    const double t1 = st.t0 + static_cast<double>(st.step_index + 1) * o.step;
    const PlanarTablePose tb1 = table_pose(motion, t1);
    detail::rigid_body_step(field, law, part, o.step, o.theta, st.table, tb1, st, contacts);
    st.table = tb1;
    st.t = t1;
    ++st.step_index;
    if (sink) sink->on_step(st);
  }
}

}  // namespace selfalign
