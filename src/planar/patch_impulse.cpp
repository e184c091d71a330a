#include "selfalign/planar/patch_impulse.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace selfalign {
double patch_objective(std::span<const PatchContact>, double, const std::array<double, 3>&,
                       const std::array<double, 3>&);

namespace {

using Twist = std::array<double, 3>;

// G_i delta: the slip velocity of contact i under twist delta.
inline void slip(const PatchContact& c, const Twist& d, double& ux, double& uy) {
  ux = d[0] - d[2] * c.dy;
  uy = d[1] + d[2] * c.dx;
}

// sum_i bound_i |G_i d| (the support function of L at d).
template <class Bound>
double support(std::span<const PatchContact> cs, const Twist& d, Bound bound) {
  double h = 0;
  for (const auto& c : cs) {
    double ux, uy;
    slip(c, d, ux, uy);
    h += bound(c) * std::hypot(ux, uy);
  }
  return h;
}

double stick_bound(const PatchContact& c) { return c.stick_bound; }
double slip_bound(const PatchContact& c) { return c.slip_bound; }

// A = sum_i b_i G_i^T G_i (3x3, SPD for >= 2 distinct points).
template <class Bound>
Eigen::Matrix3d moment_matrix(std::span<const PatchContact> cs, Bound bound) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  for (const auto& c : cs) {
    const double b = bound(c);
    a(0, 0) += b, a(1, 1) += b;
    a(0, 2) -= b * c.dy, a(1, 2) += b * c.dx;
    a(2, 2) += b * (c.dx * c.dx + c.dy * c.dy);
  }
  a(2, 0) = a(0, 2), a(2, 1) = a(1, 2);
  return a;
}

// An upper bound of the gauge of r in L: the least-squares distribution lambda_i = b_i G_i A^-1 r
// balances r, so gauge(r) <= max_i |G_i A^-1 r|.
double gauge_bound(std::span<const PatchContact> cs, const Eigen::LDLT<Eigen::Matrix3d>& a,
                   const Twist& r) {
  const Eigen::Vector3d z = a.solve(Eigen::Vector3d(r[0], r[1], r[2]));
  double g = 0;
  for (const auto& c : cs) {
    double ux, uy;
    slip(c, {z[0], z[1], z[2]}, ux, uy);
    g = std::max(g, std::hypot(ux, uy));
  }
  return g;
}

// min over |lambda| <= bound of 1/2 (lambda - z)^T A (lambda - z), A = I + q q^T / j with
// q = (-dy, dx): eigenvalues 1 + |d|^2/j along q and 1 across. Moré-Sorensen's secular Newton.
void block_projection(double dx, double dy, double inertia, double bound, double& lx, double& ly) {
  const double zx = lx, zy = ly;
  if (std::hypot(zx, zy) <= bound) return;
  const double dd = dx * dx + dy * dy;
  if (dd == 0) {
    const double s = bound / std::hypot(zx, zy);
    lx = zx * s, ly = zy * s;
    return;
  }
  const double r = std::sqrt(dd);
  const double qx = -dy / r, qy = dx / r;      // eigenvector of alpha1
  const double a1 = 1 + dd / inertia, a2 = 1;  // eigenvalues
  const double z1 = qx * zx + qy * zy, z2 = -qy * zx + qx * zy;
  double mu = 0;
  for (int it = 0; it < 60; ++it) {
    const double l1 = a1 * z1 / (a1 + mu), l2 = a2 * z2 / (a2 + mu);
    const double n = std::hypot(l1, l2);
    const double phi = 1 / n - 1 / bound;
    if (std::abs(phi) <= 1e-15 / bound) break;
    const double dn = -(l1 * l1 / (a1 + mu) + l2 * l2 / (a2 + mu)) / n;  // d|l|/dmu
    const double next = mu + phi * n * n / dn;  // Newton on 1/|l(mu)| - 1/bound
    if (!(next > mu) || next == mu) break;
    mu = next;
  }
  double l1 = a1 * z1 / (a1 + mu), l2 = a2 * z2 / (a2 + mu);
  const double n = std::hypot(l1, l2);
  if (n > bound) l1 *= bound / n, l2 *= bound / n;  // round-off: stay in the disc
  lx = qx * l1 - qy * l2, ly = qy * l1 + qx * l2;
}

// grad f at twist x with the kinetic bounds, leaving out contact `skip` and contacts at rest
// (where f is not differentiable): M (x - free) + sum_i c_i G_i^T u_i / |u_i|.
Twist smooth_gradient(std::span<const PatchContact> cs, double inertia, const Twist& free,
                      const Twist& x, int skip = -1) {
  Twist g{x[0] - free[0], x[1] - free[1], inertia * (x[2] - free[2])};
  for (std::size_t i = 0; i < cs.size(); ++i) {
    if (static_cast<int>(i) == skip) continue;
    const PatchContact& c = cs[i];
    double ux, uy;
    slip(c, x, ux, uy);
    const double u = std::hypot(ux, uy);
    if (u == 0) continue;
    const double fx = c.slip_bound * ux / u, fy = c.slip_bound * uy / u;
    g[0] += fx, g[1] += fy, g[2] += -c.dy * fx + c.dx * fy;
  }
  return g;
}

double gradient_norm(std::span<const PatchContact> cs, double inertia, const Twist& free,
                     const Twist& x) {
  const Twist g = smooth_gradient(cs, inertia, free, x);
  return std::hypot(g[0], g[1], g[2]);
}

// One descent step from a non-optimal kink of contact j: p = -M^-1 (least-norm element of
// grad f_smooth + G_j^T disc(c_j)). Returns false when no step decreases f.
bool kink_descent(std::span<const PatchContact> cs, double inertia, const Twist& free, int j,
                  Twist& x, double& fx) {
  const PatchContact& cj = cs[static_cast<std::size_t>(j)];
  const Twist gs = smooth_gradient(cs, inertia, free, x, j);
  double g0 = gs[0], g1 = gs[1], g2 = gs[2];
  // lambda minimising |g + G_j^T lambda|^2_{M^-1}: A_j lambda = -G_j M^-1 g, A_j = I + q q^T/j
  double bx, by;
  slip(cj, {g0, g1, g2 / inertia}, bx, by);
  const double qx = -cj.dy, qy = cj.dx, qq = qx * qx + qy * qy;
  const double k = (qx * bx + qy * by) / (inertia + qq);
  double lx = -(bx - k * qx), ly = -(by - k * qy);
  block_projection(cj.dx, cj.dy, inertia, cj.slip_bound, lx, ly);
  g0 += lx, g1 += ly, g2 += -cj.dy * lx + cj.dx * ly;
  const Twist p{-g0, -g1, -g2 / inertia};
  const double slope = -(g0 * g0 + g1 * g1 + g2 * g2 / inertia);
  if (!(slope < 0)) return false;
  const auto at = [&](double t) {
    return patch_objective(cs, inertia, free, {x[0] + t * p[0], x[1] + t * p[1], x[2] + t * p[2]});
  };
  double t = 1, ft = at(t);
  if (ft < fx) {
    for (int i = 0; i < 40; ++i) {
      const double f2 = at(2 * t);
      if (!(f2 < ft)) break;
      t *= 2, ft = f2;
    }
  } else {
    for (int i = 0; i < 60 && !(ft < fx); ++i) t *= 0.5, ft = at(t);
    if (!(ft < fx)) return false;
  }
  x = {x[0] + t * p[0], x[1] + t * p[1], x[2] + t * p[2]};
  fx = ft;
  return true;
}

// The pivot candidate about contact j (closed form) and its exact optimality check.
bool pivot_solution(std::span<const PatchContact> cs, double inertia, const Twist& w, int j,
                    Twist& out) {
  const PatchContact& p = cs[static_cast<std::size_t>(j)];
  const Twist rj{p.dy, -p.dx, 1};
  const double a = p.dx * p.dx + p.dy * p.dy + inertia;
  const double b = rj[0] * w[0] + rj[1] * w[1] + rj[2] * w[2];
  double cc = 0, held = 0;
  for (const auto& c : cs) {
    const double dist = std::hypot(c.dx - p.dx, c.dy - p.dy);
    if (dist == 0) held += c.slip_bound;
    cc += c.slip_bound * dist;
  }
  const double s = std::copysign(std::max(0.0, std::abs(b) - cc), b) / a;
  if (s == 0) return false;
  const Twist d{s * rj[0], s * rj[1], s * rj[2]};
  // the contacts at rest under d (j and those coinciding with it) are left out of the gradient
  const Twist free{w[0], w[1], w[2] / inertia};
  const Twist g = smooth_gradient(cs, inertia, free, d);
  const double g0 = g[0], g1 = g[1];
  if (!(std::hypot(g0, g1) <= held * (1 + 1e-12))) return false;
  out = d;
  return true;
}

}  // namespace

const char* patch_mode_name(PatchMode mode) noexcept {
  switch (mode) {
    case PatchMode::stick: return "stick";
    case PatchMode::pivot: return "pivot";
    case PatchMode::slip: return "slip";
  }
  return "?";
}

double patch_objective(std::span<const PatchContact> cs, double inertia, const Twist& free,
                       const Twist& d) {
  const double e0 = d[0] - free[0], e1 = d[1] - free[1], e2 = d[2] - free[2];
  return 0.5 * (e0 * e0 + e1 * e1 + inertia * e2 * e2) + support(cs, d, slip_bound);
}

PatchImpulseResult PatchImpulseSolver::solve(std::span<const PatchContact> cs, double inertia,
                                             const Twist& free) {
  PatchImpulseResult res;
  const Twist w{free[0], free[1], inertia * free[2]};  // W* = M delta*
  if (w[0] == 0 && w[1] == 0 && w[2] == 0) return res;
  bool all_central = true;
  double total_stick = 0, total_slip = 0;
  for (const auto& c : cs) {
    all_central = all_central && c.dx == 0 && c.dy == 0;
    total_stick += c.stick_bound, total_slip += c.slip_bound;
  }
  if (all_central) {  // point contact: disc projection of the translation, free spin
    const double v = std::hypot(free[0], free[1]);
    if (v > total_stick) {
      const double k = 1 - total_slip / v;
      res.twist = {free[0] * k, free[1] * k, free[2]};
    } else {
      res.twist = {0, 0, free[2]};
    }
    res.mode = res.twist[0] == 0 && res.twist[1] == 0 && res.twist[2] == 0 ? PatchMode::stick
                                                                              : PatchMode::slip;
    return res;
  }
  const double eta = stick_tolerance;
  const Twist target{w[0] / (1 - eta), w[1] / (1 - eta), w[2] / (1 - eta)};
  const Eigen::LDLT<Eigen::Matrix3d> a_stick(moment_matrix(cs, stick_bound));
  // 1. one-shot certificate: the least-squares distribution of the inflated target fits.
  if (gauge_bound(cs, a_stick, target) <= 1) return res;
  // 2. dual block Gauss-Seidel on the inflated target, warm-started.
  const std::size_t n = cs.size();
  if (lambda_.size() != 2 * n) lambda_.assign(2 * n, 0.0);
  Twist d = target;  // M^-1 (target - G^T lambda)
  d[2] /= inertia;
  for (std::size_t i = 0; i < n; ++i) {
    double& lx = lambda_[2 * i];
    double& ly = lambda_[2 * i + 1];
    const double nl = std::hypot(lx, ly), b = cs[i].stick_bound;
    if (nl > b) lx *= b / nl, ly *= b / nl;
    d[0] -= lx, d[1] -= ly, d[2] -= (-cs[i].dy * lx + cs[i].dx * ly) / inertia;
  }
  bool slipping = false, stuck = false;
  const double scale = std::hypot(w[0], w[1], w[2] / std::sqrt(inertia)) + total_stick;
  constexpr int kMaxSweeps = 2000;
  for (int sweep = 0; sweep < kMaxSweeps && !slipping && !stuck; ++sweep) {
    ++res.sweeps;
    for (std::size_t i = 0; i < n; ++i) {
      const PatchContact& c = cs[i];
      double ux, uy;
      slip(c, d, ux, uy);
      // unconstrained block minimiser z = lambda_i + A_i^-1 u_i, A_i = I + q q^T / j
      const double qx = -c.dy, qy = c.dx, qq = qx * qx + qy * qy;
      const double qu = qx * ux + qy * uy;
      const double k = qq == 0 ? 0 : qu / (inertia + qq);  // Sherman-Morrison
      double lx = lambda_[2 * i] + ux - k * qx, ly = lambda_[2 * i + 1] + uy - k * qy;
      block_projection(c.dx, c.dy, inertia, c.stick_bound, lx, ly);
      const double dlx = lx - lambda_[2 * i], dly = ly - lambda_[2 * i + 1];
      lambda_[2 * i] = lx, lambda_[2 * i + 1] = ly;
      d[0] -= dlx, d[1] -= dly, d[2] -= (-c.dy * dlx + c.dx * dly) / inertia;
    }
    // slip proof: d . W* > h_stick(d)
    const double dw = d[0] * w[0] + d[1] * w[1] + d[2] * w[2];
    const double hd = support(cs, d, stick_bound);
    if (dw - hd > 1e-13 * (std::abs(dw) + hd) && dw - hd > 0) {
      slipping = true;
      break;
    }
    // stick certificate: gauge(target - G^T lambda) <= eta / (1 - eta)
    const Twist r{d[0], d[1], inertia * d[2]};
    if (gauge_bound(cs, a_stick, r) <= eta / (1 - eta)) stuck = true;
    if (std::hypot(r[0], r[1], r[2] / std::sqrt(inertia)) <= 1e-17 * scale) stuck = true;
  }
  if (stuck) return res;
  // 3. slip: Newton on f with the kinetic bounds, from the dual's twist.
  Twist x = d;
  const double gscale = scale;
  double fx = patch_objective(cs, inertia, free, x);
  for (int it = 0; it <= 100; ++it) {
    double umax = 0, umin = HUGE_VAL;
    int jmin = -1;
    for (std::size_t i = 0; i < n; ++i) {
      double ux, uy;
      slip(cs[i], x, ux, uy);
      const double u = std::hypot(ux, uy);
      umax = std::max(umax, u);
      if (u < umin) umin = u, jmin = static_cast<int>(i);
    }
    if (umin <= 1e-2 * umax) {  // near a kink: is it the pivot's exact optimum?
      Twist p;
      if (pivot_solution(cs, inertia, w, jmin, p)) {
        res.twist = p, res.mode = PatchMode::pivot, res.pivot = jmin;
        return res;
      }
    }
    if (umin <= 1e-7 * umax) {
      // On a kink that is not optimal: Newton's model would zigzag into it. Step along minus
      // the least-norm subgradient (contact jmin's impulse free in its disc), a descent
      // direction off the kink, with a doubling/halving line search.
      if (!kink_descent(cs, inertia, free, jmin, x, fx)) break;
      ++res.newton_steps;
      continue;
    }
    const Twist gt = smooth_gradient(cs, inertia, free, x);
    const Eigen::Vector3d g(gt[0], gt[1], gt[2]);
    Eigen::Matrix3d hess = Eigen::Vector3d(1, 1, inertia).asDiagonal();
    for (const auto& c : cs) {  // + sum_i c_i G_i^T (I - n n^T) G_i / |u_i|
      double ux, uy;
      slip(c, x, ux, uy);
      const double u = std::hypot(ux, uy);
      if (u == 0) continue;
      const double tx = -uy / u, ty = ux / u;  // tangent to the slip direction
      const Eigen::Vector3d gt3(tx, ty, -c.dy * tx + c.dx * ty);
      hess += (c.slip_bound / u) * gt3 * gt3.transpose();
    }
    if (g.norm() <= 1e-13 * gscale || it == 100) break;
    ++res.newton_steps;
    const Eigen::Vector3d p = -hess.ldlt().solve(g);
    const double slope = g.dot(p);
    double t = 1;
    Twist trial{};
    double ft = fx;
    bool moved = false;
    // Below f's resolution (the decrease 1/2 |slope| under a few ulps of f) Armijo cannot
    // judge the step: take the full Newton step when it shrinks the gradient, else stop.
    const bool resolvable = -slope > 1e-14 * std::abs(fx);
    for (int ls = 0; resolvable && ls < 60; ++ls, t *= 0.5) {
      trial = {x[0] + t * p[0], x[1] + t * p[1], x[2] + t * p[2]};
      ft = patch_objective(cs, inertia, free, trial);
      if (ft <= fx + 1e-4 * t * slope) {
        moved = true;
        break;
      }
    }
    if (!moved) {  // f cannot resolve the step: accept it when the gradient shrinks
      trial = {x[0] + p[0], x[1] + p[1], x[2] + p[2]};
      if (!(gradient_norm(cs, inertia, free, trial) < g.norm())) break;
      ft = patch_objective(cs, inertia, free, trial);
    }
    if (trial == x) break;
    x = trial, fx = ft;
  }
  if (res.newton_steps >= 100) {  // no convergence: the optimum is a kink; find its pivot
    for (std::size_t i = 0; i < n; ++i) {
      Twist p;
      if (pivot_solution(cs, inertia, w, static_cast<int>(i), p)) {
        res.twist = p, res.mode = PatchMode::pivot, res.pivot = static_cast<int>(i);
        return res;
      }
    }
  }
  if (!slipping) {  // the sweeps ran out: decide by the slip proof at Newton's twist
    const double dw = x[0] * w[0] + x[1] * w[1] + x[2] * w[2];
    if (!(dw > support(cs, x, stick_bound))) return res;
  }
  res.twist = x;
  res.mode = PatchMode::slip;
  return res;
}

}  // namespace selfalign
