#include "disc_stage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "../planar/rigid_body_step.hpp"
#include "selfalign/error.hpp"

namespace selfalign::detail {

namespace {

const core::RigidBody* rigid(const core::Model& m, int i) {
  return std::get_if<core::RigidBody>(&m.bodies[static_cast<std::size_t>(i)]);
}

// A disc contact's geometry at the step's midpoint: the unit normal from a to b, the gap.
struct DiscGeometry {
  double nx = 1, ny = 0, gap = 0;
};

DiscGeometry geometry(double ax, double ay, double bx, double by, double ra, double rb) {
  const double dx = bx - ax, dy = by - ay, d = std::hypot(dx, dy);
  DiscGeometry g;
  if (d > 0) g.nx = dx / d, g.ny = dy / d;
  g.gap = d - (ra + rb);
  return g;
}

}  // namespace

void validate_disc_contacts(const core::Model& m) {
  for (std::size_t j = 0; j < m.disc_contacts.size(); ++j) {
    const core::DiscContact& c = m.disc_contacts[j];
    const std::string name = "disc_contacts[" + std::to_string(j) + "]";
    for (const int i : {c.a, c.b}) {
      if (i < 0 || static_cast<std::size_t>(i) >= m.bodies.size())
        throw InvalidParameter(name, std::to_string(i),
                               "indexes a body: must be in [0, " + std::to_string(m.bodies.size()) + ")");
      const core::RigidBody* r = rigid(m, i);
      const std::string body = "bodies[" + std::to_string(i) + "]";
      if (!r) throw InvalidParameter(name, body, "links planar parts (RigidBody) only");
      if (!(r->radius > 0 && r->radius <= 1e50))
        throw InvalidParameter(body + ".radius", r->radius, "a part in a disc contact needs a radius in (0, 1e50]");
    }
    if (c.a == c.b) throw InvalidParameter(name, std::to_string(c.a), "a and b must differ");
    if (!(c.restitution >= 0 && c.restitution <= 1))
      throw InvalidParameter(name + ".restitution", c.restitution, "must be in [0, 1]");
    if (!(c.friction >= 0 && c.friction <= 1e50))
      throw InvalidParameter(name + ".friction", c.friction, "must be in [0, 1e50]");
  }
}

void check_disc_overlap(const core::Model& m, const core::State& s) {
  for (const core::DiscContact& c : m.disc_contacts) {
    const auto& a = s.bodies[static_cast<std::size_t>(c.a)].pose;
    const auto& b = s.bodies[static_cast<std::size_t>(c.b)].pose;
    const DiscGeometry g = geometry(a.x, a.y, b.x, b.y, rigid(m, c.a)->radius, rigid(m, c.b)->radius);
    if (!(g.gap >= 0))
      throw InvalidParameter("poses[" + std::to_string(c.b) + "]", g.gap,
                             "overlaps body " + std::to_string(c.a) +
                                 ": the distance between the centres must be >= the radii's sum");
  }
}

void disc_step(const core::Model& m, core::State& s, const PlanarTablePose& tb,
               const PlanarTablePose& tb1, const core::StepLoads* loads) {
  const double h = m.options.step, th = m.options.theta;
  const std::size_t n = m.bodies.size();
  thread_local std::vector<RigidStage> stage;
  thread_local std::vector<std::array<double, 3>> ext;
  thread_local std::vector<PatchImpulseResult> result;
  thread_local std::vector<signed char> coupled;
  thread_local std::vector<int> active;
  thread_local std::vector<double> pn, pt, target, nx, ny;
  stage.resize(n);
  ext.assign(n, {0, 0, 0});
  result.resize(n);
  coupled.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (const auto* b = std::get_if<core::RigidBody>(&m.bodies[i]))
      stage[i] = rigid_body_prepare(m.field, b->law, b->part, h, tb, tb1, loads[i], s.bodies[i],
                                    std::span<PatchContact>(s.contacts[i]));
  // active contacts at the midpoint: the normal, and Newton's target for u_n at t_{k+1}
  active.clear(), pn.clear(), pt.clear(), target.clear(), nx.clear(), ny.clear();
  for (std::size_t j = 0; j < m.disc_contacts.size(); ++j) {
    const core::DiscContact& c = m.disc_contacts[j];
    const auto a = static_cast<std::size_t>(c.a), b = static_cast<std::size_t>(c.b);
    const double ra = rigid(m, c.a)->radius, rb = rigid(m, c.b)->radius;
    const DiscGeometry g = geometry(stage[a].xm, stage[a].ym, stage[b].xm, stage[b].ym, ra, rb);
    if (g.gap > 0) continue;
    // the normal relative velocity at t_k (table axes turned to world: the normal is world)
    const double ct = std::cos(tb.angle), st = std::sin(tb.angle);
    const auto& ua = s.bodies[a].twist;
    const auto& ub = s.bodies[b].twist;
    const double dvx = ct * (ub.ux - ua.ux) - st * (ub.uy - ua.uy);
    const double dvy = st * (ub.ux - ua.ux) + ct * (ub.uy - ua.uy);
    const double un0 = dvx * g.nx + dvy * g.ny;
    active.push_back(static_cast<int>(j));
    pn.push_back(0), pt.push_back(0);
    target.push_back(-c.restitution * std::min(un0, 0.0));
    nx.push_back(g.nx), ny.push_back(g.ny);
    coupled[a] = coupled[b] = 1;
  }
  // block Gauss-Seidel: bodies' patch problems, then each contact's projection
  for (int sweep = 0; sweep < kDiscSweeps && !active.empty(); ++sweep) {
    for (std::size_t i = 0; i < n; ++i)
      if (coupled[i]) {
        const std::array<double, 3> rel{stage[i].rel[0] + ext[i][0], stage[i].rel[1] + ext[i][1],
                                        stage[i].rel[2] + ext[i][2]};
        result[i] = rigid_body_solve(stage[i], rel, s.bodies[i], std::span<PatchContact>(s.contacts[i]));
      }
    double change = 0, largest = 0;
    for (std::size_t q = 0; q < active.size(); ++q) {
      const core::DiscContact& c = m.disc_contacts[static_cast<std::size_t>(active[q])];
      const auto a = static_cast<std::size_t>(c.a), b = static_cast<std::size_t>(c.b);
      const core::RigidBody& A = *rigid(m, c.a);
      const core::RigidBody& B = *rigid(m, c.b);
      const double tx = -ny[q], ty = nx[q];
      // contact point arms: r_a = ra n, r_b = -rb n; velocity of b relative to a there
      const auto& wa = result[a].twist;
      const auto& wb = result[b].twist;
      const double vx = (wb[0] - wb[2] * (-B.radius * ny[q])) - (wa[0] - wa[2] * (A.radius * ny[q]));
      const double vy = (wb[1] + wb[2] * (-B.radius * nx[q])) - (wa[1] + wa[2] * (A.radius * nx[q]));
      const double un = vx * nx[q] + vy * ny[q], ut = vx * tx + vy * ty;
      const double ia = 1 / A.mass, ib = 1 / B.mass;
      const double Ia = A.mass * A.part.inertia, Ib = B.mass * B.part.inertia;
      const double wnn = ia + ib, wtt = ia + ib + A.radius * A.radius / Ia + B.radius * B.radius / Ib;
      const double pn1 = std::max(0.0, pn[q] - (un - target[q]) / wnn);
      const double bound = c.friction * pn1;
      const double pt1 = std::clamp(pt[q] - ut / wtt, -bound, bound);
      const double dn = pn1 - pn[q], dt = pt1 - pt[q];
      pn[q] = pn1, pt[q] = pt1;
      change = std::max({change, std::abs(dn), std::abs(dt)});
      largest = std::max({largest, std::abs(pn1), std::abs(pt1)});
      // the increment: +P on b at r_b = -rb n, -P on a at r_a = ra n (per unit mass)
      const double px = dn * nx[q] + dt * tx, py = dn * ny[q] + dt * ty;
      ext[b][0] += px * ib, ext[b][1] += py * ib;
      ext[b][2] += (-B.radius) * dt / Ib;  // r_b x P = -rb (n x P) = -rb dt
      ext[a][0] -= px * ia, ext[a][1] -= py * ia;
      ext[a][2] -= A.radius * dt / Ia;     // r_a x (-P) = -ra dt
    }
    if (change <= kDiscTolerance * std::max(largest, 1e-300)) break;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto* b = std::get_if<core::RigidBody>(&m.bodies[i]);
    if (!b) continue;
    if (coupled[i]) {
      const std::array<double, 3> rel{stage[i].rel[0] + ext[i][0], stage[i].rel[1] + ext[i][1],
                                      stage[i].rel[2] + ext[i][2]};
      result[i] = rigid_body_solve(stage[i], rel, s.bodies[i], std::span<PatchContact>(s.contacts[i]));
      rigid_body_integrate(h, th, tb1, stage[i], result[i], s.bodies[i]);
    } else {
      rigid_body_integrate(h, th, tb1, stage[i],
                           rigid_body_solve(stage[i], stage[i].rel, s.bodies[i],
                                            std::span<PatchContact>(s.contacts[i])),
                           s.bodies[i]);
    }
  }
}

}  // namespace selfalign::detail
