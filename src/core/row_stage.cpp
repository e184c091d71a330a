#include "row_stage.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <variant>

#include "../planar/rigid_body_step.hpp"
#include "../simulate/moreau_slider_step.hpp"
#include "selfalign/error.hpp"

namespace selfalign::detail {

using core::BodyState;
using core::Model;
using core::PartContact;
using core::SliderBody;
using core::State;

namespace {

std::string contact_name(std::size_t j) { return "part_contacts[" + std::to_string(j) + "]"; }

const SliderBody& slider(const Model& model, int i) {
  return std::get<SliderBody>(model.bodies[static_cast<std::size_t>(i)]);
}


}  // namespace

SliderInputs slider_inputs(const Model& model, const SliderBody& b, const PlanarTablePose& tb,
                           const PlanarTablePose& tb1, const core::StepLoads& loads,
                           double h, double x, double v) {
  const PlanarTableMotion& motion = model.motion;
  const double yd = motion.e1_x * tb.vx + motion.e1_y * tb.vy;
  const double yd1 = motion.e1_x * tb1.vx + motion.e1_y * tb1.vy;
  SliderInputs in;
  in.level = core::slider_level(model, b, x + 0.5 * h * v);
  in.v_free = v - (yd1 - yd);
  if (loads.pulled) in.v_free += motion.e1_x * loads.gx + motion.e1_y * loads.gy;
  return in;
}

void slider_step(const Model& model, const SliderBody& b, double h, double th,
                 const PlanarTablePose& tb, const PlanarTablePose& tb1,
                 const core::StepLoads& loads, double t1, int index, BodyState& st,
                 MotionObserver* observer) {
  const double x = st.pose.x, v = st.twist.ux;
  const SliderInputs in = slider_inputs(model, b, tb, tb1, loads, h, x, v);
  const SliderCoefficients c(b.law);
  double x1;
  const double v1 = b.law.velocity_dependent()
                        ? moreau_slider_step<true>(b.law, c, h, th, in.level,
                                                                      x, v, in.v_free, x1,
                                                                      loads.load)
                        : moreau_slider_step<false>(b.law, c, h, th, in.level,
                                                                       x, v, in.v_free, x1,
                                                                       loads.load);
  st.pose.x = x1;
  st.twist.ux = v1;
  st.mode = v1 == 0 ? PatchMode::stick : PatchMode::slip;
  if (observer) report_slider_step(*observer, t1, h, index, x, v, x1, v1);
}

void report_slider_step(MotionObserver& observer, double t1, double h, int index, double x,
                        double v, double x1, double v1) {
  const auto direction = static_cast<std::int8_t>(v1 > 0 ? 1 : v1 < 0 ? -1 : 0);
  observer.on_motion({t1 - h, t1, x, v, x1, v1, direction, ArcEnd::time_step, index}, nullptr);
}

void validate_part_contacts(const Model& model) {
  const std::size_t n = model.bodies.size();
  std::vector<int> behind(n, -1), ahead(n, -1);
  for (std::size_t j = 0; j < model.part_contacts.size(); ++j) {
    const PartContact& pc = model.part_contacts[j];
    const std::string name = contact_name(j);
    for (const int i : {pc.rear, pc.front})
      if (i < 0 || static_cast<std::size_t>(i) >= n)
        throw InvalidParameter(name, std::to_string(i),
                               "indexes a body: must be in [0, " + std::to_string(n) + ")");
    if (pc.rear == pc.front)
      throw InvalidParameter(name, std::to_string(pc.rear), "rear and front must differ");
    for (const int i : {pc.rear, pc.front}) {
      const std::string body = "bodies[" + std::to_string(i) + "]";
      const auto* s = std::get_if<SliderBody>(&model.bodies[static_cast<std::size_t>(i)]);
      if (!s)
        throw InvalidParameter(name, body,
                               "links 1-D parts (SliderBody) only: contacts between planar "
                               "parts are not built yet");
      if (!(s->length > 0 && s->length <= 1e50))
        throw InvalidParameter(body + ".length", s->length, "a part in a row must be in (0, 1e50]");
      if (s->law.velocity_dependent())
        throw InvalidParameter(body + ".law", "velocity-dependent",
                               "a part in a row needs a velocity-independent law");
    }
    if (!(pc.restitution >= 0 && pc.restitution <= 1))
      throw InvalidParameter(name + ".restitution", pc.restitution, "must be in [0, 1]");
    auto& a = ahead[static_cast<std::size_t>(pc.rear)];
    auto& b = behind[static_cast<std::size_t>(pc.front)];
    if (a >= 0 || b >= 0)
      throw InvalidParameter(name, std::to_string(pc.rear) + " -> " + std::to_string(pc.front),
                             "each part touches at most one part ahead and one behind");
    a = static_cast<int>(j);
    b = static_cast<int>(j);
  }
  // no cycle: from every part, walking ahead ends within n steps
  for (std::size_t i = 0; i < n; ++i) {
    int at = static_cast<int>(i);
    for (std::size_t k = 0; k <= n && ahead[static_cast<std::size_t>(at)] >= 0; ++k) {
      if (k == n)
        throw InvalidParameter(contact_name(static_cast<std::size_t>(ahead[i])), "a cycle",
                               "the contacts must form rows (rear to front), not a ring");
      at = model.part_contacts[static_cast<std::size_t>(ahead[static_cast<std::size_t>(at)])].front;
    }
  }
}

void prepare_row(const Model& model, State& state) {
  const std::size_t n = model.bodies.size();
  core::RowWork& w = state.row;
  w.behind.assign(n, -1);
  w.ahead.assign(n, -1);
  w.chained.assign(n, 0);
  w.active.assign(model.part_contacts.size(), 0);
  w.x0.assign(n, 0);
  w.v0.assign(n, 0);
  for (std::size_t j = 0; j < model.part_contacts.size(); ++j) {
    const PartContact& pc = model.part_contacts[j];
    w.ahead[static_cast<std::size_t>(pc.rear)] = static_cast<int>(j);
    w.behind[static_cast<std::size_t>(pc.front)] = static_cast<int>(j);
    const double g = core::part_gap(model, pc, state.bodies[static_cast<std::size_t>(pc.rear)].pose.x,
                         state.bodies[static_cast<std::size_t>(pc.front)].pose.x);
    if (!(g >= 0))
      throw InvalidParameter("poses[" + std::to_string(pc.front) + "]", g,
                             "overlaps part " + std::to_string(pc.rear) +
                                 " behind it: the gap (x - length) - x_rear must be >= 0");
  }
}

void row_step(const Model& model, State& s, double t1, const PlanarTablePose& tb,
              const PlanarTablePose& tb1, const core::StepLoads* loads,
              MotionObserver* observer) {
  const double h = model.options.step, th = model.options.theta;
  const std::size_t n = model.bodies.size();
  core::RowWork& w = s.row;
  for (std::size_t i = 0; i < n; ++i) {
    w.x0[i] = s.bodies[i].pose.x;
    w.v0[i] = s.bodies[i].twist.ux;
    w.chained[i] = 0;
  }
  // contacts: active where the gap at the step's midpoint is <= 0
  bool any = false;
  for (std::size_t j = 0; j < model.part_contacts.size(); ++j) {
    const PartContact& pc = model.part_contacts[j];
    const auto r = static_cast<std::size_t>(pc.rear), f = static_cast<std::size_t>(pc.front);
    const double g = core::part_gap(model, pc, w.x0[r], w.x0[f]) + 0.5 * h * (w.v0[f] - w.v0[r]);
    w.active[j] = g <= 0;
    if (w.active[j]) w.chained[r] = w.chained[f] = 1, any = true;
  }
  // sliders in no chain: the 1-D Moreau step itself
  for (std::size_t i = 0; i < n; ++i)
    if (const auto* b = std::get_if<SliderBody>(&model.bodies[i]); b && !w.chained[i])
      slider_step(model, *b, h, th, tb, tb1, loads[i], t1, static_cast<int>(i), s.bodies[i],
                  nullptr);
  // chains: from each chained part with no active contact behind it, forward
  for (std::size_t i = 0; any && i < n; ++i) {
    if (!w.chained[i]) continue;
    const auto active = [&w](int j) { return j >= 0 && w.active[static_cast<std::size_t>(j)]; };
    if (active(w.behind[i])) continue;  // not the chain's rear part
    w.bodies.clear();
    w.parts.clear();
    w.chain_friction.clear();
    w.c.clear();
    int at = static_cast<int>(i);
    for (;;) {
      const auto k = static_cast<std::size_t>(at);
      const SliderBody& b = slider(model, at);
      const SliderInputs in = slider_inputs(model, b, tb, tb1, loads[k], h, w.x0[k], w.v0[k]);
      const SliderCoefficients c(b.law);
      const double load = loads[k].load;
      core::ChainFriction fr;
      fr.hold = load * (c.s * in.level);
      fr.forward = load * (c.kf * in.level);
      fr.backward = load * (c.kb * in.level);
      const double v = w.v0[k];
      fr.sliding_on = (v > 0 && in.v_free > 0) ? 1 : (v < 0 && in.v_free < 0) ? -1 : 0;
      w.bodies.push_back(at);
      w.parts.push_back({b.mass, in.v_free, 0, 0});
      w.chain_friction.push_back(fr);
      const int ja = w.ahead[k];
      if (!active(ja)) break;
      const PartContact& pc = model.part_contacts[static_cast<std::size_t>(ja)];
      const double rate = w.v0[static_cast<std::size_t>(pc.front)] - v;
      w.c.push_back(-pc.restitution * std::min(rate, 0.0));
      at = pc.front;
    }
    w.v.resize(w.bodies.size());
    core::solve_chain_static_kinetic(w.parts, w.chain_friction, w.c, w.v, w.chain);
    for (std::size_t q = 0; q < w.bodies.size(); ++q) {
      const auto k = static_cast<std::size_t>(w.bodies[q]);
      BodyState& st = s.bodies[k];
      const double v1 = w.v[q];
      st.pose.x = w.x0[k] + h * ((1 - th) * w.v0[k] + th * v1);
      st.twist.ux = v1;
      st.mode = v1 == 0 ? PatchMode::stick : PatchMode::slip;
    }
  }
  if (observer)
    for (std::size_t i = 0; i < n; ++i)
      if (std::holds_alternative<SliderBody>(model.bodies[i]))
        report_slider_step(*observer, t1, h, static_cast<int>(i), w.x0[i], w.v0[i],
                           s.bodies[i].pose.x, s.bodies[i].twist.ux);
}

}  // namespace selfalign::detail
