#include <cmath>
#include <string>

#include "../planar/rigid_body_step.hpp"
#include "selfalign/core/model.hpp"
#include "selfalign/core/state.hpp"
#include "selfalign/core/step.hpp"
#include "selfalign/error.hpp"

namespace selfalign::core {

void validate(const Model& m) {
  if (m.bodies.empty()) throw InvalidParameter("bodies", "none", "needs at least one body");
  validate(m.motion);
  validate(m.field);
  validate(m.options);
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    const std::string name = "bodies[" + std::to_string(i) + "]";
    try {
      validate(m.bodies[i].part);
      require_planar_law(m.bodies[i].law);
    } catch (const InvalidParameter& e) {
      throw InvalidParameter(name + "." + e.name(), e.value(), e.allowed());
    }
  }
}

State make_state(const Model& model, double t, std::span<const PlanarPose> poses,
                 std::span<const PlanarTwist> twists) {
  validate(model);
  const std::size_t n = model.bodies.size();
  if (poses.size() != n)
    throw InvalidParameter("poses", std::to_string(poses.size()),
                           "needs one pose per body (" + std::to_string(n) + ")");
  if (twists.size() != n)
    throw InvalidParameter("twists", std::to_string(twists.size()),
                           "needs one twist per body (" + std::to_string(n) + ")");
  State s;
  s.t0 = s.t = t;
  s.bodies.resize(n);
  s.contacts.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    // One body's start is exactly a PlanarRigidState's (its checks and initial mode).
    const PlanarRigidState one = make_planar_rigid_state(model.motion, t, poses[i], twists[i]);
    s.table = one.table;
    BodyState& b = s.bodies[i];
    b.pose = one.pose;
    b.twist = one.twist;
    b.mode = one.mode;
    s.contacts[i].resize(model.bodies[i].part.patch.size());
  }
  return s;
}

long long step(const Model& model, State& s, long long steps, StepObserver* observer) {
  validate(model);
  const std::size_t n = model.bodies.size();
  if (s.bodies.size() != n || s.contacts.size() != n)
    throw InvalidParameter("state", std::to_string(s.bodies.size()) + " bodies",
                           "must be made by make_state for this model (" + std::to_string(n) +
                               " bodies)");
  const double h = model.options.step, th = model.options.theta;
  long long taken = 0;
  for (; taken < steps && s.status == StepStatus::ok; ++taken) {
    // kinematics, once for every body
    const double t1 = s.t0 + static_cast<double>(s.step_index + 1) * h;
    const PlanarTablePose tb1 = table_pose(model.motion, t1);
    // the body stages, block by block
    for (std::size_t i = 0; i < n; ++i)
      detail::rigid_body_step(model.field, model.bodies[i].law, model.bodies[i].part, h, th,
                              s.table, tb1, s.bodies[i], s.contacts[i]);
    // checks: the table's motion (a profile that returns NaN), then each body
    if (!(std::isfinite(tb1.x) && std::isfinite(tb1.y) && std::isfinite(tb1.angle) &&
          std::isfinite(tb1.vx) && std::isfinite(tb1.vy) && std::isfinite(tb1.rate))) {
      s.status = StepStatus::non_finite;
      s.failed_body = -1;
    }
    for (std::size_t i = 0; i < n && s.status == StepStatus::ok; ++i) {
      const BodyState& b = s.bodies[i];
      if (!(std::isfinite(b.pose.x) && std::isfinite(b.pose.y) && std::isfinite(b.pose.angle) &&
            std::isfinite(b.twist.ux) && std::isfinite(b.twist.uy) &&
            std::isfinite(b.twist.omega))) {
        s.status = StepStatus::non_finite;
        s.failed_body = static_cast<int>(i);
        break;
      }
    }
    s.table = tb1;
    s.t = t1;
    ++s.step_index;
    if (observer) observer->on_step(s);
  }
  return taken;
}

}  // namespace selfalign::core
