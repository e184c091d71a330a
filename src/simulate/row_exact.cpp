#include "selfalign/simulate/row_exact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <variant>

#include "selfalign/error.hpp"
#include "selfalign/overloaded.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// What the solver reads of the model, once per call: the profile, the friction pieces along
// e1 (boundaries in x, levels between), per body its mass and law, and the rows.
struct RowSetup {
  const PiecewisePolynomialProfile* profile = nullptr;
  std::vector<double> bounds, levels;  // levels.size() == bounds.size() + 1
  std::vector<double> mass, s, kf, kb;
  std::vector<int> ahead, behind;      // per body: contact index or -1
  std::vector<int> rears;              // bodies with no contact behind them
};

std::string body_name(std::size_t i) { return "bodies[" + std::to_string(i) + "]"; }

RowSetup read_setup(const core::Model& model) {
  core::validate(model);
  RowSetup r;
  const PlanarTableMotion& m = model.motion;
  if (m.second || m.rotation || m.normal)
    throw InvalidParameter("motion", "planar", "the exact row solver takes a table moving along e1 only");
  r.profile = m.first ? m.first->piecewise_polynomial() : nullptr;
  if (!r.profile || !r.profile->piecewise_constant())
    throw InvalidParameter("motion", m.first ? m.first->kind() : "none",
                           "the exact row solver needs a piecewise-constant acceleration "
                           "(three-phase, square wave); use Moreau's time stepping");
  if (model.gravity)
    throw InvalidParameter("gravity", "given", "the exact row solver takes the paper's constant normal load");
  std::visit(Overloaded{[&](const UniformPlanarField& u) { r.levels = {u.level}; },
                        [&](const AxisField& a) {
                          const double c = std::cos(a.angle) * m.e1_x + std::sin(a.angle) * m.e1_y;
                          if (!(c > 0) || !a.field.piecewise_constant())
                            throw InvalidParameter("field", "axis",
                                                   "the exact row solver needs steps increasing "
                                                   "along e1");
                          const double offset =
                              std::cos(a.angle) * a.origin_x + std::sin(a.angle) * a.origin_y;
                          const auto nodes = a.field.nodes();
                          r.levels.push_back(nodes.front().left);
                          for (const FieldNode& nd : nodes) {
                            r.bounds.push_back((nd.position + offset) / c);
                            r.levels.push_back(nd.right);
                          }
                        },
                        [](const auto&) {
                          throw InvalidParameter("field", "planar",
                                                 "the exact row solver takes a uniform field or "
                                                 "an axis field of steps");
                        }},
             model.field);
  const std::size_t n = model.bodies.size();
  r.ahead.assign(n, -1);
  r.behind.assign(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const auto* b = std::get_if<core::SliderBody>(&model.bodies[i]);
    if (!b || !std::holds_alternative<PointFootprint>(b->footprint))
      throw InvalidParameter(body_name(i), b ? "uniform footprint" : "rigid",
                             "the exact row solver takes 1-D parts with point footprints");
    if (b->law.velocity_dependent())
      throw InvalidParameter(body_name(i) + ".law", "velocity-dependent",
                             "the exact row solver takes Coulomb laws");
    r.mass.push_back(b->mass);
    r.s.push_back(b->law.static_coefficient());
    r.kf.push_back(b->law.kinetic_forward());
    r.kb.push_back(b->law.kinetic_backward());
  }
  for (std::size_t j = 0; j < model.part_contacts.size(); ++j) {
    r.ahead[static_cast<std::size_t>(model.part_contacts[j].rear)] = static_cast<int>(j);
    r.behind[static_cast<std::size_t>(model.part_contacts[j].front)] = static_cast<int>(j);
  }
  for (std::size_t i = 0; i < n; ++i)
    if (r.behind[i] < 0) r.rears.push_back(static_cast<int>(i));
  return r;
}

double gap_of(const core::Model& model, const RowExactState& s, int j) {
  const core::PartContact& pc = model.part_contacts[static_cast<std::size_t>(j)];
  return core::part_gap(model, pc, s.x[static_cast<std::size_t>(pc.rear)],
                        s.x[static_cast<std::size_t>(pc.front)]);
}

// The first tau >= 0 where alpha tau^2 + beta tau + gamma = 0 and `accept(tau)`; kNever if none.
template <class Accept>
double first_root(double alpha, double beta, double gamma, Accept accept) {
  double r1 = kNever, r2 = kNever;
  if (alpha == 0) {
    if (beta != 0) r1 = -gamma / beta;
  } else {
    const double disc = beta * beta - 4 * alpha * gamma;
    if (disc < 0) return kNever;
    const double q = -0.5 * (beta + std::copysign(std::sqrt(disc), beta));
    r1 = q / alpha;
    r2 = q != 0 ? gamma / q : r1;
  }
  if (r1 > r2) std::swap(r1, r2);
  for (const double r : {r1, r2})
    if (r >= 0 && r < kNever && accept(r)) return r;
  return kNever;
}

// The parts of one cluster (touching parts) starting at body `first`, rear to front, into
// s.chain; returns the contact ahead of the cluster's front part (-1: none).
int cluster_from(const core::Model& model, const RowSetup& r, RowExactState& s, int first) {
  s.chain.clear();
  int at = first;
  for (;;) {
    s.chain.push_back(at);
    const int j = r.ahead[static_cast<std::size_t>(at)];
    if (j < 0) return -1;
    if (!s.touching[static_cast<std::size_t>(j)]) return j;
    at = model.part_contacts[static_cast<std::size_t>(j)].front;
  }
}

// The mode of every cluster under table acceleration A: the chain problem at acceleration
// level (docs/rows.md). Resting clusters hold with their static bounds and break loose with
// their kinetic ones; moving clusters pull with their kinetic bounds against their motion.
// Touching parts whose front part accelerates away split.
void solve_modes(const core::Model& model, const RowSetup& r, RowExactState& s, double A) {
  for (const int rear : r.rears) {
    int at = rear;
    for (;;) {
      const int next = cluster_from(model, r, s, at);
      const std::size_t n = s.chain.size();
      s.parts.resize(n);
      s.friction.resize(n);
      s.c.assign(n - 1, 0.0);
      s.chain_v.resize(n);
      const double v = s.v[static_cast<std::size_t>(s.chain[0])];
      for (std::size_t q = 0; q < n; ++q) {
        const auto i = static_cast<std::size_t>(s.chain[q]);
        const double level = r.levels[s.piece[i]];
        core::ChainPart& p = s.parts[q];
        p.mass = r.mass[i];
        if (v == 0) {
          p.target = -A;
          s.friction[q] = {r.s[i] * level, r.kf[i] * level, r.kb[i] * level, 0};
        } else {
          p.target = v > 0 ? -A - r.kf[i] * level : -A + r.kb[i] * level;
          p.forward = p.backward = 0;
        }
      }
      if (v == 0) core::solve_chain_static_kinetic(s.parts, s.friction, s.c, s.chain_v, s.work);
      else core::solve_chain(s.parts, s.c, s.chain_v, s.work);
      for (std::size_t q = 0; q < n; ++q) {
        s.a[static_cast<std::size_t>(s.chain[q])] = s.chain_v[q];
        if (q + 1 < n && s.chain_v[q + 1] > s.chain_v[q]) {
          s.touching[static_cast<std::size_t>(r.ahead[static_cast<std::size_t>(s.chain[q])])] = 0;
          ++s.statistics.separations;
        }
      }
      if (next < 0) break;
      at = model.part_contacts[static_cast<std::size_t>(next)].front;
    }
  }
}

// The impact at contact j: Newton's law there (target relative velocity -e times the incoming
// one, plastic below the bounce resolution), plastic at the touching contacts of the two
// clusters, no friction impulse: the chain problem in the velocities without friction.
void impact(const core::Model& model, const RowSetup& r, RowExactState& s, int j,
            const RowExactOptions& o) {
  const core::PartContact& pc = model.part_contacts[static_cast<std::size_t>(j)];
  int first = pc.rear;  // the rear cluster's rear part
  for (int jb = r.behind[static_cast<std::size_t>(first)];
       jb >= 0 && s.touching[static_cast<std::size_t>(jb)];
       jb = r.behind[static_cast<std::size_t>(first)])
    first = model.part_contacts[static_cast<std::size_t>(jb)].rear;
  s.touching[static_cast<std::size_t>(j)] = 1;  // for the walk: both clusters as one chain
  const int next = cluster_from(model, r, s, first);
  (void)next;
  const std::size_t n = s.chain.size();
  s.parts.resize(n);
  s.c.assign(n - 1, 0.0);
  s.chain_v.resize(n);
  for (std::size_t q = 0; q < n; ++q) {
    const auto i = static_cast<std::size_t>(s.chain[q]);
    s.parts[q] = {r.mass[i], s.v[i], 0, 0};
    if (q + 1 < n && s.chain[q] == pc.rear) {
      const double incoming = std::max(s.v[i] - s.v[static_cast<std::size_t>(pc.front)], 0.0);
      s.c[q] = incoming > o.bounce_resolution ? pc.restitution * incoming : 0.0;
    }
  }
  core::solve_chain(s.parts, s.c, s.chain_v, s.work);
  for (std::size_t q = 0; q < n; ++q) {
    const auto i = static_cast<std::size_t>(s.chain[q]);
    s.v[i] = s.chain_v[q];
    if (q + 1 < n) {
      auto& t = s.touching[static_cast<std::size_t>(r.ahead[i])];
      const bool together = s.chain_v[q + 1] == s.chain_v[q];
      if (t && !together) ++s.statistics.separations;
      t = together ? 1 : 0;
    }
  }
  ++s.statistics.collisions;
}


}  // namespace

RowExactState make_row_exact_state(const core::Model& model, double t, std::span<const double> x,
                                   std::span<const double> v) {
  const RowSetup r = read_setup(model);
  const std::size_t n = model.bodies.size();
  if (x.size() != n) throw InvalidParameter("x", std::to_string(x.size()), "needs one position per body");
  if (v.size() != n) throw InvalidParameter("v", std::to_string(v.size()), "needs one velocity per body");
  RowExactState s;
  const double P = r.profile->period();
  if (!(std::isfinite(t) && std::abs(t / P) <= 1e15))
    throw InvalidParameter("t0", t, "must be within 1e15 table periods of 0");
  s.t = t;
  s.x.assign(x.begin(), x.end());
  s.v.assign(v.begin(), v.end());
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x[i])) throw InvalidParameter("x[" + std::to_string(i) + "]", x[i], "must be finite");
    if (!std::isfinite(v[i])) throw InvalidParameter("v[" + std::to_string(i) + "]", v[i], "must be finite");
    s.piece.push_back(static_cast<std::size_t>(
        std::upper_bound(r.bounds.begin(), r.bounds.end(), x[i]) - r.bounds.begin()));
  }
  s.touching.assign(model.part_contacts.size(), 0);
  for (std::size_t j = 0; j < model.part_contacts.size(); ++j) {
    const double g = gap_of(model, s, static_cast<int>(j));
    const core::PartContact& pc = model.part_contacts[j];
    if (!(g >= 0))
      throw InvalidParameter("x[" + std::to_string(pc.front) + "]", g,
                             "overlaps part " + std::to_string(pc.rear) +
                                 " behind it: the gap (x - length) - x_rear must be >= 0");
    s.touching[j] = g == 0 && v[static_cast<std::size_t>(pc.rear)] ==
                                  v[static_cast<std::size_t>(pc.front)];
  }
  s.period_index = static_cast<long long>(std::floor(t / P));
  if (t - static_cast<double>(s.period_index) * P >= P) ++s.period_index;
  s.segment = r.profile->segment_at(std::max(t - static_cast<double>(s.period_index) * P, 0.0));
  s.a.assign(n, std::numeric_limits<double>::quiet_NaN());  // every part anchors at the start
  s.t_anchor.assign(n, t);
  s.x_anchor = s.x;
  s.v_anchor = s.v;
  s.moved.assign(n, 1);
  s.zero_at.assign(n, kNever);
  s.cross_at.assign(n, kNever);
  s.direction.assign(n, 0);
  return s;
}

std::size_t advance_row_exact(const core::Model& model, RowExactState& s, double t_end,
                              MotionObserver* observer, const RowExactOptions& o) {
  const RowSetup r = read_setup(model);
  const std::size_t n = model.bodies.size();
  if (s.x.size() != n || s.touching.size() != model.part_contacts.size())
    throw InvalidParameter("state", std::to_string(s.x.size()) + " bodies",
                           "must be made by make_row_exact_state for this model");
  if (!std::isfinite(t_end)) throw InvalidParameter("t_end", t_end, "must be finite");
  if (!(o.bounce_resolution >= 0))
    throw InvalidParameter("bounce_resolution", o.bounce_resolution, "must be >= 0");
  const auto segs = r.profile->segments();
  const std::size_t nseg = segs.size();
  const double P = r.profile->period();
  double period_start = static_cast<double>(s.period_index) * P;
  std::size_t arcs = 0;
  std::vector<double> x0, v0;
  if (observer) x0.resize(n), v0.resize(n);
  while (s.t < t_end) {
    const double A = segs[s.segment].accel;
    s.previous_a = s.a;
    solve_modes(model, r, s, A);
    // anchors: a part whose acceleration or velocity changed starts its parabola here; the
    // others keep theirs (a lone part's arcs do not depend on the other parts' events)
    for (std::size_t i = 0; i < n; ++i)
      if (s.moved[i] || !(s.a[i] == s.previous_a[i])) {
        s.t_anchor[i] = s.t, s.x_anchor[i] = s.x[i], s.v_anchor[i] = s.v[i];
        s.moved[i] = 0;
      }
    // the next event, as an absolute time
    const double seg_end = period_start + (s.segment + 1 < nseg ? segs[s.segment + 1].begin : P);
    const bool to_switch = seg_end <= t_end;
    double next = to_switch ? seg_end : t_end;
    ArcEnd end = to_switch ? ArcEnd::acceleration_switch : ArcEnd::horizon;
    int contact = -1;
    for (std::size_t i = 0; i < n; ++i) {
      const double v = s.v_anchor[i], a = s.a[i], ta = s.t_anchor[i];
      s.zero_at[i] = v != 0 && a != 0 && (v > 0) != (a > 0) ? ta + -v / a : kNever;
      if (s.zero_at[i] < next) {
        next = s.zero_at[i];
        end = ArcEnd::velocity_zero;
      }
      s.cross_at[i] = kNever;
      const int d = v > 0 ? 1 : v < 0 ? -1 : a > 0 ? 1 : a < 0 ? -1 : 0;
      s.direction[i] = static_cast<signed char>(d);
      if (d == 0 || r.bounds.empty()) continue;
      const std::size_t p = s.piece[i];
      if ((d > 0 && p == r.bounds.size()) || (d < 0 && p == 0)) continue;
      const double b = d > 0 ? r.bounds[p] : r.bounds[p - 1];
      s.cross_at[i] = ta + first_root(0.5 * a, v, s.x_anchor[i] - b, [](double) { return true; });
      if (s.cross_at[i] < next) {
        next = s.cross_at[i];
        end = ArcEnd::friction_boundary;
      }
    }
    for (std::size_t j = 0; j < model.part_contacts.size(); ++j) {
      if (s.touching[j]) continue;
      const core::PartContact& pc = model.part_contacts[j];
      const auto f = static_cast<std::size_t>(pc.front), b = static_cast<std::size_t>(pc.rear);
      const double g0 = gap_of(model, s, static_cast<int>(j));
      const double dv = s.v[f] - s.v[b], da = s.a[f] - s.a[b];
      double root;
      if (g0 <= 0 && (dv < 0 || (dv == 0 && da < 0))) root = 0;
      else root = first_root(0.5 * da, dv, g0, [&](double tt) { return dv + da * tt < 0; });
      if (s.t + root < next) {
        next = s.t + root;
        end = ArcEnd::part_contact;
        contact = static_cast<int>(j);
      }
    }
    // the arc: every part on its parabola from its anchor
    if (observer)
      for (std::size_t i = 0; i < n; ++i) x0[i] = s.x[i], v0[i] = s.v[i];
    const double t0 = s.t;
    for (std::size_t i = 0; i < n; ++i) {
      const double tau = next - s.t_anchor[i];
      s.x[i] = s.x_anchor[i] + (s.v_anchor[i] + 0.5 * s.a[i] * tau) * tau;
      s.v[i] = s.v_anchor[i] + s.a[i] * tau;
    }
    s.t = next;
    ++arcs;
    ++s.statistics.arcs;
    // the event
    switch (end) {
      case ArcEnd::velocity_zero:  // every part whose velocity zero this is (a cluster's)
        for (std::size_t i = 0; i < n; ++i)
          if (s.zero_at[i] == next) s.v[i] = 0, s.moved[i] = 1;
        ++s.statistics.velocity_zeros;
        break;
      case ArcEnd::friction_boundary:  // every part that reached its next boundary
        for (std::size_t i = 0; i < n; ++i)
          if (s.cross_at[i] == next) s.piece[i] += s.direction[i] > 0 ? 1 : static_cast<std::size_t>(-1);
        ++s.statistics.boundaries;
        break;
      case ArcEnd::part_contact: {
        s.v_before.assign(s.v.begin(), s.v.end());
        impact(model, r, s, contact, o);
        for (std::size_t i = 0; i < n; ++i)
          if (s.v[i] != s.v_before[i]) s.moved[i] = 1;
        break;
      }
      case ArcEnd::acceleration_switch:
        if (++s.segment == nseg) {
          s.segment = 0;
          ++s.period_index;
          period_start = static_cast<double>(s.period_index) * P;
        }
        break;
      default:
        break;
    }
    if (observer)
      for (std::size_t i = 0; i < n; ++i) {
        const double v1 = s.v[i];
        const auto dir = static_cast<std::int8_t>(v0[i] + v1 > 0   ? 1
                                                  : v0[i] + v1 < 0 ? -1
                                                                   : 0);
        observer->on_motion({t0, s.t, x0[i], v0[i], s.x[i], v1, dir, end,
                             static_cast<std::int32_t>(i)},
                            nullptr);
      }
  }
  return arcs;
}

}  // namespace selfalign
