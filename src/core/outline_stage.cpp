#include "outline_stage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Dense>

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
  std::size_t contact = 0;  // its contact's index (a contact's points are consecutive)
  int combo = -1;           // the first point's: the modes of the contact's last block solve
  double friction = 0;
  double nx = 1, ny = 0, tx = 0, ty = 1;
  double rax = 0, ray = 0, rbx = 0, rby = 0;
  double wnn = 0, wtt = 0, target = 0;
  double pn = 0, pt = 0;
};

double cross(double rx, double ry, double px, double py) { return rx * py - ry * px; }

// One contact's points (1 or 2, the same bodies) solved together exactly: the impulses P'
// (n, t per point) with u' = u + W (P' - P) on Coulomb's law and the points' targets, W the
// free-body Delassus matrix of the points (4 x 4 for two). By enumeration of each point's mode
// (apart, stick, slip either way: 4 or 16 linear systems; a singular one, two points whose
// tangent rows coincide, solved for its least-norm solution and kept if it solves). Returns
// false where no mode fits (rounding): the caller projects point by point. Solving the points
// of a face together removes the slow drift of point-by-point Gauss-Seidel where the two
// points' tangent rows are nearly parallel (W nearly singular): 10 000 sweeps did not
// converge there (tests/test_outline_siconos.cpp).
bool solve_contact_block(std::span<const ActivePoint> pts, const core::RigidBody& A,
                         const core::RigidBody& B, const std::array<double, 3>& wa,
                         const std::array<double, 3>& wb, int& last_combo,
                         std::array<double, 4>& out) {
  const int m = static_cast<int>(pts.size());
  const int size = 2 * m;
  // rows d of J: (n_k, t_k) per point; columns: a's twist, b's twist
  Eigen::Matrix<double, 4, 6> J = Eigen::Matrix<double, 4, 6>::Zero();
  Eigen::Vector4d u = Eigen::Vector4d::Zero(), P = Eigen::Vector4d::Zero(), target = Eigen::Vector4d::Zero();
  for (int k = 0; k < m; ++k) {
    const ActivePoint& p = pts[static_cast<std::size_t>(k)];
    for (int d = 0; d < 2; ++d) {
      const double dx = d == 0 ? p.nx : p.tx, dy = d == 0 ? p.ny : p.ty;
      const int row = 2 * k + d;
      J.row(row) << -dx, -dy, -cross(p.rax, p.ray, dx, dy), dx, dy, cross(p.rbx, p.rby, dx, dy);
    }
    P[2 * k] = p.pn, P[2 * k + 1] = p.pt, target[2 * k] = p.target;
  }
  const Eigen::Matrix<double, 6, 1> w(wa[0], wa[1], wa[2], wb[0], wb[1], wb[2]);
  u = J * w;
  Eigen::Matrix<double, 6, 1> minv;
  minv << 1 / A.mass, 1 / A.mass, 1 / (A.mass * A.part.inertia), 1 / B.mass, 1 / B.mass,
      1 / (B.mass * B.part.inertia);
  const Eigen::Matrix4d W = J * minv.asDiagonal() * J.transpose();
  const Eigen::Vector4d c = u - W * P;  // u' = c + W P'
  double scale_u = 0, scale_p = 0, wmax = 0;
  for (int i = 0; i < size; ++i)
    scale_u = std::max({scale_u, std::abs(u[i]), std::abs(target[i]), std::abs(c[i])}),
    wmax = std::max(wmax, W(i, i));
  scale_u = std::max(scale_u, 1e-300);
  scale_p = scale_u / wmax;
  constexpr double kEps = 1e-10;  // relative: the modes' inequalities up to rounding
  int combos = 1;
  for (int k = 0; k < m; ++k) combos *= 4;
  // the previous sweep's modes first (nearly always still right), then the others
  const int start = last_combo >= 0 && last_combo < combos ? last_combo : 0;
  for (int tried = 0; tried < combos; ++tried) {
    const int combo = (start + tried) % combos;
    // mode per point: 0 apart, 1 stick, 2 slip (u_t > 0), 3 slip (u_t < 0)
    const int mode[2] = {combo % 4, (combo / 4) % 4};
    // unknowns x and P' = G x; equations E u' = e
    Eigen::Matrix<double, 4, 4> G = Eigen::Matrix4d::Zero(), E = Eigen::Matrix4d::Zero();
    Eigen::Vector4d e = Eigen::Vector4d::Zero();
    int nx = 0, ne = 0;
    for (int k = 0; k < m; ++k) {
      const double mu = pts[static_cast<std::size_t>(k)].friction;
      if (mode[k] == 0) continue;
      E(ne, 2 * k) = 1, e[ne] = target[2 * k], ++ne;  // u_n' = target
      if (mode[k] == 1) {
        G(2 * k, nx++) = 1, G(2 * k + 1, nx++) = 1;
        E(ne, 2 * k + 1) = 1, e[ne] = 0, ++ne;  // u_t' = 0
      } else {
        G(2 * k, nx) = 1, G(2 * k + 1, nx) = mode[k] == 2 ? -mu : mu, ++nx;
      }
    }
    Eigen::Vector4d Pn = Eigen::Vector4d::Zero();
    if (nx > 0) {
      using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 4, 4>;  // no heap
      using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 4, 1>;
      const Small K = E.topRows(ne) * W * G.leftCols(nx);
      const SmallVector rhs = e.head(ne) - E.topRows(ne) * c;
      const SmallVector x = K.completeOrthogonalDecomposition().solve(rhs);
      if (!((K * x - rhs).norm() <= kEps * scale_u)) continue;
      Pn = G.leftCols(nx) * x;
    }
    const Eigen::Vector4d un = c + W * Pn;
    bool ok = true;
    for (int k = 0; k < m && ok; ++k) {
      const double mu = pts[static_cast<std::size_t>(k)].friction;
      const double pn = Pn[2 * k], pt = Pn[2 * k + 1];
      const double vn = un[2 * k] - target[2 * k], vt = un[2 * k + 1];
      switch (mode[k]) {
        case 0: ok = vn >= -kEps * scale_u; break;
        case 1: ok = pn >= -kEps * scale_p && std::abs(pt) <= mu * pn + kEps * scale_p; break;
        case 2: ok = pn >= -kEps * scale_p && vt >= -kEps * scale_u; break;
        default: ok = pn >= -kEps * scale_p && vt <= kEps * scale_u; break;
      }
    }
    if (!ok) continue;
    last_combo = combo;
    for (int k = 0; k < m; ++k) {
      const double pn = std::max(0.0, Pn[2 * k]), bound = pts[static_cast<std::size_t>(k)].friction * pn;
      out[static_cast<std::size_t>(2 * k)] = pn;
      out[static_cast<std::size_t>(2 * k + 1)] = std::clamp(Pn[2 * k + 1], -bound, bound);
    }
    return true;
  }
  return false;
}

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
  for (std::size_t ci = 0; ci < m.outline_contacts.size(); ++ci) {
    const core::OutlineContact& c = m.outline_contacts[ci];
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
      p.a = a, p.b = b, p.contact = ci, p.friction = c.friction;
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
    // each contact's points together (solve_contact_block; point by point where no mode fits)
    for (std::size_t first = 0; first < active.size();) {
      std::size_t last = first + 1;
      while (last < active.size() && active[last].contact == active[first].contact) ++last;
      const std::span<ActivePoint> group(active.data() + first, last - first);
      ActivePoint& p0 = group[0];
      const core::RigidBody& A = std::get<core::RigidBody>(m.bodies[p0.a]);
      const core::RigidBody& B = std::get<core::RigidBody>(m.bodies[p0.b]);
      std::array<double, 4> block{};
      const bool exact = group.size() <= 2 &&
                         solve_contact_block(group, A, B, result[p0.a].twist, result[p0.b].twist,
                                             group[0].combo, block);
      for (std::size_t k = 0; k < group.size(); ++k) {
        ActivePoint& p = group[k];
        double pn1, pt1;
        if (exact) {
          pn1 = block[2 * k], pt1 = block[2 * k + 1];
        } else {
          // the velocity of b's point relative to a's
          const auto wa = result[p.a].twist;
          const auto wb = result[p.b].twist;
          const double vx = (wb[0] - wb[2] * p.rby) - (wa[0] - wa[2] * p.ray);
          const double vy = (wb[1] + wb[2] * p.rbx) - (wa[1] + wa[2] * p.rax);
          const double un = vx * p.nx + vy * p.ny, ut = vx * p.tx + vy * p.ty;
          pn1 = std::max(0.0, p.pn - (un - p.target) / p.wnn);
          const double bound = p.friction * pn1;
          pt1 = std::clamp(p.pt - ut / p.wtt, -bound, bound);
        }
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
        // Gauss-Seidel over the contacts: the next one sees this one's impulse (the free-body
        // response until the next sweep's patch solves; a Jacobi update, each point correcting
        // the same velocity error, over-corrects where a body has several points: a row of
        // three rectangles turned unstably)
        for (int d = 0; d < 3; ++d) {
          const auto kd = static_cast<std::size_t>(d);
          ext[p.b][kd] += db[kd], ext[p.a][kd] += da[kd];
          result[p.b].twist[kd] += db[kd], result[p.a].twist[kd] += da[kd];
        }
      }
      first = last;
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
