#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <variant>

#include "../planar/rigid_body_step.hpp"
#include "outline_stage.hpp"
#include "row_stage.hpp"
#include "selfalign/core/model.hpp"
#include "selfalign/core/state.hpp"
#include "selfalign/core/step.hpp"
#include "selfalign/error.hpp"
#include "selfalign/overloaded.hpp"

namespace selfalign::core {

namespace {

// Moreau-Jean's normal stage of one body (Gravity::flight, core/model.hpp): the free normal
// velocity relative to the table w - h g cos(incline) - Δz' (`weight` = h g cos(incline),
// `dvz` = Δz'); the contact is active where the height at the step's midpoint is <= 0 and that
// velocity is below Newton's target -e min(w, 0) (e = Gravity::restitution; 0: plastic), then
// the impulse P brings it to the target; the height moves by the theta rule. Returns the step's
// loads with this body's normal impulse per unit weight P / g.
detail::StepLoads normal_contact(double h, double th, double weight, double dvz, double g,
                                 double e, const detail::StepLoads& loads, BodyState& b) {
  const double w = b.normal_velocity;
  const double w_free = w - weight - dvz;
  const double target = -e * std::min(w, 0.0);
  const bool active = b.height + 0.5 * h * w <= 0 && w_free < target;
  const double w1 = active ? target : w_free;
  detail::StepLoads out = loads;
  out.load = active ? (target - w_free) / g : 0.0;
  b.height += h * ((1 - th) * w + th * w1);
  if (active && b.height < 0) b.height = 0;  // it ends the step on the table
  b.normal_velocity = w1;
  return out;
}

}  // namespace

double part_gap(const Model& model, const PartContact& c, double x_rear, double x_front) {
  return (x_front - std::get<SliderBody>(model.bodies[static_cast<std::size_t>(c.front)]).length) -
         x_rear;
}

double slider_level(const Model& model, const SliderBody& b, double x) {
  const double ex = model.motion.e1_x, ey = model.motion.e1_y;
  const double w = std::holds_alternative<UniformFootprint>(b.footprint)
                       ? std::get<UniformFootprint>(b.footprint).width
                       : 0.0;
  return std::visit(
      Overloaded{
          [](const UniformPlanarField& u) { return u.level; },
          [&](const AxisField& a) {
            // The axis position of the point x e1: d(x) = c x - n . origin, c = n . e1; the
            // footprint's window [x - w, x] maps to [d(x - w), d(x)] (eq. 7: the average).
            const double nx = std::cos(a.angle), ny = std::sin(a.angle);
            const double c = nx * ex + ny * ey, offset = nx * a.origin_x + ny * a.origin_y;
            const double d = c * x - offset;
            if (w == 0.0 || c == 0.0) return a.field(d);
            const double d0 = c * (x - w) - offset;
            return std::max(0.0, a.field.integral(std::min(d0, d), std::max(d0, d)) /
                                     (std::abs(c) * w));
          },
          [&](const auto&) { return planar_level(model.field, x * ex, x * ey); },  // a point
      },
      model.field);
}

void validate(const Model& m) {
  if (m.bodies.empty()) throw InvalidParameter("bodies", "none", "needs at least one body");
  validate(m.motion);
  if (m.gravity) {
    const Gravity& g = *m.gravity;
    if (!(g.g > 0 && g.g <= 1e50)) throw InvalidParameter("gravity.g", g.g, "must be in (0, 1e50]");
    if (!(g.incline >= 0 && g.incline < std::numbers::pi / 2))
      throw InvalidParameter("gravity.incline", g.incline, "must be in [0, pi/2) rad");
    require_unit_vector("gravity.downhill", g.downhill_x, g.downhill_y);
    if (!(g.restitution >= 0 && g.restitution <= 1))
      throw InvalidParameter("gravity.restitution", g.restitution, "must be in [0, 1]");
  } else if (m.motion.normal) {
    throw InvalidParameter("motion.normal", m.motion.normal->kind(),
                           "the table's normal motion changes the normal load: give the model "
                           "gravity (Model::gravity)");
  }
  validate(m.field);
  validate(m.options);
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    const std::string name = "bodies[" + std::to_string(i) + "]";
    try {
      std::visit(Overloaded{[](const RigidBody& b) {
                              validate(b.part);
                              require_planar_law(b.law);
                              if (!(b.mass > 0 && b.mass <= 1e50))
                                throw InvalidParameter("mass", b.mass, "must be in (0, 1e50]");
                              validate(b.outline);
                            },
                            [&m](const SliderBody& b) {
                              if (const auto* u = std::get_if<UniformFootprint>(&b.footprint)) {
                                require_positive_moderate("footprint", u->width);
                                if (!std::holds_alternative<UniformPlanarField>(m.field) &&
                                    !std::holds_alternative<AxisField>(m.field))
                                  throw InvalidParameter(
                                      "footprint", "uniform",
                                      "a 1-D part's uniform footprint averages a uniform or "
                                      "axis field (give it a point footprint on this field)");
                              }
                              if (!(b.mass > 0 && b.mass <= 1e50))
                                throw InvalidParameter("mass", b.mass, "must be in (0, 1e50]");
                              if (!(b.length >= 0 && b.length <= 1e50))
                                throw InvalidParameter("length", b.length, "must be in [0, 1e50]");
                              if (m.motion.rotation)
                                throw InvalidParameter("motion", "turning",
                                                       "a 1-D part needs a table that does not "
                                                       "turn (it moves along e1)");
                            }},
                 m.bodies[i]);
    } catch (const InvalidParameter& e) {
      throw InvalidParameter(name + "." + e.name(), e.value(), e.allowed());
    }
  }
  detail::validate_part_contacts(m);
  detail::validate_outline_contacts(m);
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
    if (const auto* rigid = std::get_if<RigidBody>(&model.bodies[i])) {
      s.contacts[i].resize(rigid->part.patch.size());
    } else {  // a 1-D part: x along e1 and x' only; at rest it starts stuck (as the 1-D stepper)
      const std::string at = "[" + std::to_string(i) + "]";
      if (poses[i].y != 0 || poses[i].angle != 0)
        throw InvalidParameter("poses" + at, "y or angle set",
                               "a 1-D part has one coordinate, x (y and angle 0)");
      if (twists[i].uy != 0 || twists[i].omega != 0)
        throw InvalidParameter("twists" + at, "uy or omega set",
                               "a 1-D part has one velocity, ux (uy and omega 0)");
      b.mode = b.twist.ux == 0 ? PatchMode::stick : PatchMode::slip;
    }
  }
  detail::prepare_row(model, s);
  detail::check_outline_overlap(model, s);
  return s;
}

long long step(const Model& model, State& s, long long steps, MotionObserver* observer) {
  validate(model);
  const std::size_t n = model.bodies.size();
  if (s.bodies.size() != n || s.contacts.size() != n)
    throw InvalidParameter("state", std::to_string(s.bodies.size()) + " bodies",
                           "must be made by make_state for this model (" + std::to_string(n) +
                               " bodies)");
  const double h = model.options.step, th = model.options.theta;
  // loads: the paper's constant normal load (impulse h per unit weight), or gravity on the
  // incline with the table's normal motion (Gravity): the part of the stage fixed over the run
  detail::StepLoads loads{h};
  double g = 0, pressing = 0;
  if (model.gravity) {
    const Gravity& gr = *model.gravity;
    g = gr.g;
    pressing = h * std::cos(gr.incline);
    const double pull = h * gr.g * std::sin(gr.incline);
    loads.gx = pull * gr.downhill_x, loads.gy = pull * gr.downhill_y;
    loads.pulled = true;
  }
  const bool flight = model.gravity && model.gravity->flight;  // Moreau-Jean's normal stage
  const bool rows = !model.part_contacts.empty();
  const bool outlines = !model.outline_contacts.empty();
  s.loads.resize(n);
  long long taken = 0;
  for (; taken < steps && s.status == StepStatus::ok; ++taken) {
    // kinematics, once for every body
    const double t1 = s.t0 + static_cast<double>(s.step_index + 1) * h;
    const PlanarTablePose tb1 = table_pose(model.motion, t1);
    // loads: the step's normal impulse per unit weight; negative: the table falls away faster
    // than gravity, the bodies lift off (no flight phase yet: the run stops before this step)
    if (model.gravity && !flight) {
      loads.load = pressing + (tb1.vz - s.table.vz) / g;
      if (loads.load < 0) {
        s.status = StepStatus::lift_off;
        s.failed_body = -1;
        break;
      }
    }
    // per body its loads: Moreau-Jean's unilateral normal contact (Gravity::flight) gives
    // each body its own normal impulse; otherwise the step's
    for (std::size_t i = 0; i < n; ++i)
      s.loads[i] = flight ? normal_contact(h, th, pressing * g, tb1.vz - s.table.vz, g,
                                           model.gravity->restitution, loads, s.bodies[i])
                          : loads;
    // the body stages, block by block: rigid bodies in contact with each other are coupled by
    // the outline stage, touching 1-D parts by the row stage; a body alone takes its own step
    if (outlines) {
      detail::outline_step(model, s, s.table, tb1, s.loads.data());
    } else {
      for (std::size_t i = 0; i < n; ++i)
        if (const auto* b = std::get_if<RigidBody>(&model.bodies[i]))
          detail::rigid_body_step(model.field, b->law, b->part, h, th, s.table, tb1, s.loads[i],
                                  s.bodies[i], s.contacts[i]);
    }
    if (rows) {
      detail::row_step(model, s, t1, s.table, tb1, s.loads.data(), observer);
    } else {
      for (std::size_t i = 0; i < n; ++i)
        if (const auto* b = std::get_if<SliderBody>(&model.bodies[i]))
          detail::slider_step(model, *b, h, th, s.table, tb1, s.loads[i], t1,
                              static_cast<int>(i), s.bodies[i], observer);
    }
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
