#include "outline_stage.hpp"

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

// One manifold point of an active contact in the Gauss-Seidel sweeps: its bodies, normal and
// tangent (world), arms from the bodies' midpoint centres, free-body Delassus terms
// W = 1/m_a + 1/m_b + (r_a x d)^2/I_a + (r_b x d)^2/I_b along d = n and t, Newton's target
// for u_n at t_{k+1}, and its impulses (on b; -P on a).
struct ActivePoint {
  std::size_t a = 0, b = 0;
  double friction = 0;
  double nx = 1, ny = 0, tx = 0, ty = 1;
  double rax = 0, ray = 0, rbx = 0, rby = 0;
  double wnn = 0, wtt = 0, target = 0;
  double pn = 0, pt = 0;
};

double cross(double rx, double ry, double px, double py) { return rx * py - ry * px; }

}  // namespace

void validate_outline_contacts(const core::Model& m) {
  for (std::size_t j = 0; j < m.outline_contacts.size(); ++j) {
    const core::OutlineContact& c = m.outline_contacts[j];
    const std::string name = "outline_contacts[" + std::to_string(j) + "]";
    for (const int i : {c.a, c.b}) {
      if (i < 0 || static_cast<std::size_t>(i) >= m.bodies.size())
        throw InvalidParameter(name, std::to_string(i),
                               "indexes a body: must be in [0, " + std::to_string(m.bodies.size()) + ")");
      const core::RigidBody* r = rigid(m, i);
      const std::string body = "bodies[" + std::to_string(i) + "]";
      if (!r) throw InvalidParameter(name, body, "links planar parts (RigidBody) only");
      if (std::holds_alternative<NoOutline>(r->outline))
        throw InvalidParameter(body + ".outline", "none",
                               "a part in an outline contact needs a disc or a convex polygon");
    }
    if (c.a == c.b) throw InvalidParameter(name, std::to_string(c.a), "a and b must differ");
    if (!(c.restitution >= 0 && c.restitution <= 1))
      throw InvalidParameter(name + ".restitution", c.restitution, "must be in [0, 1]");
    if (!(c.friction >= 0 && c.friction <= 1e50))
      throw InvalidParameter(name + ".friction", c.friction, "must be in [0, 1e50]");
  }
}

void check_outline_overlap(const core::Model& m, const core::State& s) {
  for (const core::OutlineContact& c : m.outline_contacts) {
    const core::RigidBody& A = *rigid(m, c.a);
    const core::RigidBody& B = *rigid(m, c.b);
    const double gap = contact_manifold(A.outline, s.bodies[static_cast<std::size_t>(c.a)].pose,
                                        B.outline, s.bodies[static_cast<std::size_t>(c.b)].pose)
                           .gap();
    if (!(gap >= -1e-12 * (outline_radius(A.outline) + outline_radius(B.outline))))
      throw InvalidParameter("poses[" + std::to_string(c.b) + "]", gap,
                             "overlaps body " + std::to_string(c.a) +
                                 ": the outlines must not overlap (gap >= 0)");
  }
}

void outline_step(const core::Model& m, core::State& s, const PlanarTablePose& tb,
                  const PlanarTablePose& tb1, const core::StepLoads* loads) {
  const double h = m.options.step, th = m.options.theta;
  const std::size_t n = m.bodies.size();
  thread_local std::vector<RigidStage> stage;
  thread_local std::vector<std::array<double, 3>> ext;
  thread_local std::vector<PatchImpulseResult> result;
  thread_local std::vector<signed char> coupled;
  thread_local std::vector<ActivePoint> active;
  stage.resize(n);
  ext.assign(n, {0, 0, 0});
  result.resize(n);
  coupled.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (const auto* b = std::get_if<core::RigidBody>(&m.bodies[i]))
      stage[i] = rigid_body_prepare(m.field, b->law, b->part, h, tb, tb1, loads[i], s.bodies[i],
                                    std::span<PatchContact>(s.contacts[i]));
  // the relative twist at t_k in world axes (table axes turned by the table's angle)
  const double ct = std::cos(tb.angle), st = std::sin(tb.angle);
  const auto twist0 = [&](std::size_t i) {
    const PlanarTwist& u = s.bodies[i].twist;
    return std::array<double, 3>{ct * u.ux - st * u.uy, st * u.ux + ct * u.uy, u.omega};
  };
  // active contacts at the midpoint poses: their manifold points, Newton's targets
  active.clear();
  for (const core::OutlineContact& c : m.outline_contacts) {
    const auto a = static_cast<std::size_t>(c.a), b = static_cast<std::size_t>(c.b);
    const core::RigidBody& A = *rigid(m, c.a);
    const core::RigidBody& B = *rigid(m, c.b);
    const ContactManifold cm = contact_manifold(A.outline, {stage[a].xm, stage[a].ym, stage[a].am},
                                                B.outline, {stage[b].xm, stage[b].ym, stage[b].am});
    if (!(cm.gap() <= 0)) continue;
    const auto ua = twist0(a), ub = twist0(b);
    const double ia = 1 / A.mass, ib = 1 / B.mass;
    const double Ia = A.mass * A.part.inertia, Ib = B.mass * B.part.inertia;
    for (int k = 0; k < cm.count; ++k) {
      const ManifoldPoint& mp = cm.points[static_cast<std::size_t>(k)];
      ActivePoint p;
      p.a = a, p.b = b, p.friction = c.friction;
      p.nx = cm.nx, p.ny = cm.ny, p.tx = -cm.ny, p.ty = cm.nx;
      p.rax = mp.ax - stage[a].xm, p.ray = mp.ay - stage[a].ym;
      p.rbx = mp.bx - stage[b].xm, p.rby = mp.by - stage[b].ym;
      const double ran = cross(p.rax, p.ray, p.nx, p.ny), rbn = cross(p.rbx, p.rby, p.nx, p.ny);
      const double rat = cross(p.rax, p.ray, p.tx, p.ty), rbt = cross(p.rbx, p.rby, p.tx, p.ty);
      p.wnn = ia + ib + ran * ran / Ia + rbn * rbn / Ib;
      p.wtt = ia + ib + rat * rat / Ia + rbt * rbt / Ib;
      // the normal relative velocity of the points at t_k
      const double vx = (ub[0] - ub[2] * p.rby) - (ua[0] - ua[2] * p.ray);
      const double vy = (ub[1] + ub[2] * p.rbx) - (ua[1] + ua[2] * p.rax);
      // Newton's target where the point touches; apart (the other end of a tilted face,
      // gap > 0 at the midpoint) the speculative bound u_n >= -gap/(theta h): the point may
      // close its gap by the step's end (gap_{k+1} = gap + theta h u_n for theta = 1/2), not
      // overlap. Two points of faces that touch keep both ends of the faces together.
      p.target = mp.gap > 0 ? -mp.gap / (th * h)
                            : -c.restitution * std::min(vx * p.nx + vy * p.ny, 0.0);
      active.push_back(p);
      coupled[a] = coupled[b] = 1;
    }
  }
  // block Gauss-Seidel: bodies' patch problems, then each point's projection
  const auto solve = [&](std::size_t i) {
    const std::array<double, 3> rel{stage[i].rel[0] + ext[i][0], stage[i].rel[1] + ext[i][1],
                                    stage[i].rel[2] + ext[i][2]};
    result[i] = rigid_body_solve(stage[i], rel, s.bodies[i], std::span<PatchContact>(s.contacts[i]));
  };
  for (int sweep = 0; sweep < kOutlineSweeps && !active.empty(); ++sweep) {
    for (std::size_t i = 0; i < n; ++i)
      if (coupled[i]) solve(i);
    double change = 0, largest = 0;
    for (ActivePoint& p : active) {
      const core::RigidBody& A = std::get<core::RigidBody>(m.bodies[p.a]);
      const core::RigidBody& B = std::get<core::RigidBody>(m.bodies[p.b]);
      // the velocity of b's point relative to a's
      const auto wa = result[p.a].twist;
      const auto wb = result[p.b].twist;
      const double vx = (wb[0] - wb[2] * p.rby) - (wa[0] - wa[2] * p.ray);
      const double vy = (wb[1] + wb[2] * p.rbx) - (wa[1] + wa[2] * p.rax);
      const double un = vx * p.nx + vy * p.ny, ut = vx * p.tx + vy * p.ty;
      const double pn1 = std::max(0.0, p.pn - (un - p.target) / p.wnn);
      const double bound = p.friction * pn1;
      const double pt1 = std::clamp(p.pt - ut / p.wtt, -bound, bound);
      const double dn = pn1 - p.pn, dt = pt1 - p.pt;
      p.pn = pn1, p.pt = pt1;
      change = std::max({change, std::abs(dn), std::abs(dt)});
      largest = std::max({largest, std::abs(pn1), std::abs(pt1)});
      // the increment: +P on b at r_b, -P on a at r_a (per unit mass; I = m j)
      const double px = dn * p.nx + dt * p.tx, py = dn * p.ny + dt * p.ty;
      const std::array<double, 3> db{px / B.mass, py / B.mass,
                                     cross(p.rbx, p.rby, px, py) / (B.mass * B.part.inertia)};
      const std::array<double, 3> da{-px / A.mass, -py / A.mass,
                                     -cross(p.rax, p.ray, px, py) / (A.mass * A.part.inertia)};
      // Gauss-Seidel over the points: the next point sees this one's impulse (the free-body
      // response until the next sweep's patch solves; a Jacobi update, each point correcting
      // the same velocity error, over-corrects where a body has several points: a row of
      // three rectangles turned unstably)
      for (int d = 0; d < 3; ++d) {
        const auto k = static_cast<std::size_t>(d);
        ext[p.b][k] += db[k], ext[p.a][k] += da[k];
        result[p.b].twist[k] += db[k], result[p.a].twist[k] += da[k];
      }
    }
    if (change <= kOutlineTolerance * std::max(largest, 1e-300)) break;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::holds_alternative<core::RigidBody>(m.bodies[i])) continue;
    if (coupled[i]) solve(i);
    else
      result[i] = rigid_body_solve(stage[i], stage[i].rel, s.bodies[i],
                                   std::span<PatchContact>(s.contacts[i]));
    rigid_body_integrate(h, th, tb1, stage[i], result[i], s.bodies[i]);
  }
}

}  // namespace selfalign::detail
