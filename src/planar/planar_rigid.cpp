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

PlanarPose world_pose(const PlanarRigidState& s) {
  const double c = std::cos(s.table.angle), sn = std::sin(s.table.angle);
  return {s.table.x + c * s.pose.x - sn * s.pose.y, s.table.y + sn * s.pose.x + c * s.pose.y,
          s.table.angle + s.pose.angle};
}

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
  const double h = o.step, th = o.theta, j = part.inertia;
  const double s = law.static_coefficient(), k = law.kinetic_forward();
  const std::size_t n = part.patch.size();
  std::vector<PatchContact> contacts(n);
  for (long long step = 0; step < steps; ++step) {
    const PlanarTablePose tb = st.table;
    const double t1 = st.t0 + static_cast<double>(st.step_index + 1) * h;
    const PlanarTablePose tb1 = table_pose(motion, t1);
    const PlanarTwist u = st.twist;
    const PlanarTwist v = world_twist(st);
    // midpoint poses: on the table, of the table, in the world
    const double xi = st.pose.x + 0.5 * h * u.ux, eta = st.pose.y + 0.5 * h * u.uy;
    const double phi = st.pose.angle + 0.5 * h * u.omega;
    const double psi = tb.angle + 0.5 * h * tb.rate;
    const double cp = std::cos(psi), sp = std::sin(psi);
    const double xm = tb.x + 0.5 * h * tb.vx + cp * xi - sp * eta;
    const double ym = tb.y + 0.5 * h * tb.vy + sp * xi + cp * eta;
    const double cf = std::cos(phi), sf = std::sin(phi);
    const double ca = std::cos(psi + phi), sa = std::sin(psi + phi);
    for (std::size_t i = 0; i < n; ++i) {
      const ContactPoint& r = part.patch[i];
      const double level = planar_level(field, xi + cf * r.x - sf * r.y, eta + sf * r.x + cf * r.y);
      contacts[i] = {ca * r.x - sa * r.y, sa * r.x + ca * r.y, h * s * level * r.load,
                     h * k * level * r.load};
    }
    // the table's twist at t_{k+1} about X_M
    const double tvx = tb1.vx - tb1.rate * (ym - tb1.y), tvy = tb1.vy + tb1.rate * (xm - tb1.x);
    const std::array<double, 3> rel{v.ux - tvx, v.uy - tvy, v.omega - tb1.rate};
    // sliding on (the free relative twist keeps the previous one's direction): kinetic bounds
    // for the stick test too, as the 1-D and point schemes
    const double c0 = std::cos(tb.angle), s0 = std::sin(tb.angle);
    const double pvx = c0 * u.ux - s0 * u.uy, pvy = s0 * u.ux + c0 * u.uy;
    const bool sliding_on = st.mode != PatchMode::stick &&
                            rel[0] * pvx + rel[1] * pvy + j * rel[2] * u.omega > 0;
    if (sliding_on)
      for (auto& c : contacts) c.stick_bound = c.slip_bound;
    const PatchImpulseResult r = st.solver.solve(contacts, j, rel);
    const double c1 = std::cos(tb1.angle), s1 = std::sin(tb1.angle);
    const PlanarTwist u1{c1 * r.twist[0] + s1 * r.twist[1], -s1 * r.twist[0] + c1 * r.twist[1],
                         r.twist[2]};
    st.pose.x += h * ((1 - th) * u.ux + th * u1.ux);
    st.pose.y += h * ((1 - th) * u.uy + th * u1.uy);
    st.pose.angle += h * ((1 - th) * u.omega + th * u1.omega);
    st.twist = u1;
    st.table = tb1;
    st.t = t1;
    ++st.step_index;
    st.mode = r.mode, st.pivot = r.pivot;
    st.sweeps += r.sweeps, st.newton_steps += r.newton_steps;
    if (sink) sink->on_step(st);
  }
}

}  // namespace selfalign
