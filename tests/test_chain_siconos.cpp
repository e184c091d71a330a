// The chain problem of core/chain_problem.hpp against a second method: the LCP of its
// optimality conditions solved by Siconos numerics (Debian's libsiconos-numerics-dev 4.4), a
// pivoting solver that knows nothing of the pool-adjacent-violators algorithm.
//
// Siconos numerics, as used here (read from the installed headers, /usr/include/siconos):
//   - Linking: the C library libsiconos_numerics.so (it pulls libsiconos_externals, OpenBLAS,
//     LAPACKE, CXSparse, MUMPS itself) with the include directories /usr/include/siconos
//     (SiconosConfig.h) and /usr/include/siconos/numerics (everything else); tests/CMakeLists.txt
//     finds them with find_path / find_library. Debian's CMake package
//     (/usr/lib/cmake/siconos-4.5.0/siconos-config.cmake) is not usable with numerics alone: it
//     checks for /usr/bin/siconos and the kernel's libraries and stops with a fatal error (it
//     would also set CMAKE_CXX_STANDARD 11).
//   - The headers are C with extern "C" guards (unless BUILD_AS_CPP, not defined in Debian's
//     SiconosConfig.h), so they are included directly; they define only prefixed or harmless
//     macros (CS_INT, HAS_*, WITH_CMAKE, SICONOS_*), which matters in the unity build.
//   - LinearComplementarityProblem {int size; NumericsMatrix* M; double* q;}: find z >= 0 with
//     w = M z + q >= 0, z'w = 0. It can live on the stack (no newLCP / free needed).
//   - NumericsMatrix: NM_create(NM_DENSE, rows, cols) allocates matrix0 (dense, COLUMN-MAJOR:
//     entry (i, j) at matrix0[i + rows * j], as Lemke reads it: M[dim * jc + ic]); NM_free(m)
//     frees it and the struct. (NM_create_from_data(NM_DENSE, r, c, data) would take `data`
//     over: NM_free would free it.)
//   - SolverOptions* solver_options_create(id) with id from lcp_cst.h: SICONOS_LCP_LEMKE (200,
//     lcp_lexicolemke: Lemke's method with lexicographic pivoting, Cottle-Pang-Stone 1992;
//     iparam[SICONOS_IPARAM_MAX_ITER] pivots at most; its lexicographic ties use
//     max|M| * DBL_EPSILON unless iparam[SICONOS_LCP_IPARAM_PIVOTING_METHOD_TYPE] says
//     otherwise), SICONOS_LCP_ENUM (213: enumerates the 2^size complementary bases; its first
//     call leaks its work arrays unless lcp_enum_init / lcp_enum_reset are called),
//     SICONOS_LCP_PIVOT (215, Bard / least-index / Lemke by iparam), PATH, NSGS, ...;
//     dparam[SICONOS_DPARAM_TOL] is the tolerance of the error test. In 4.4
//     solver_options_delete(options) frees the members but NOT the struct: free() it too
//     (valgrind: no leak then).
//   - int linearComplementarity_driver(problem, z, w, options): dispatches on options->solverId;
//     returns info, 0 on success (Lemke: 1 = too many pivots, or the pivot column is nonpositive,
//     i.e. the ray termination of an infeasible LCP). q >= 0 returns z = 0 at once.
//     lcp_compute_error(problem, z, w, tol, &err) recomputes w = M z + q and the complementarity
//     error (returns 1 if err > tol).
//   - Also there: RelayProblem (w = M z + q, -w in the normal cone of [lb, ub] at z; solvers
//     SICONOS_RELAY_LEMKE / ENUM / PATH / PGS / AVI_CAOFERRIS, relay_driver) and
//     MixedLinearComplementarityProblem (equalities and complementarities; SICONOS_MLCP_ENUM,
//     DIRECT_ENUM, PGS, PATH, LCP_LEMKE, ...). The plain LCP below needs neither.
//
// Two LCPs (derived here; the oracle builds both). With D = diag(m), A the (n-1) x n difference
// matrix (A_{i,i} = -1, A_{i,i+1} = +1; gap g = A v - c), u, f, b, c the data and phi_j the
// friction per unit mass (in [-b_j, f_j], = f_j where v_j > 0, = -b_j where v_j < 0), the
// optimality (KKT) conditions, necessary and sufficient for this convex problem, are
//     D (v - u) + D phi - A' lambda = 0,   0 <= lambda _|_ A v - c >= 0.
// lambda is the problem's contact force: part 0's row is m_0 (v_0 - u_0) + m_0 phi_0 = -lambda_0,
// the header's momentum balance.
//
// 1. The dual LCP (tried first). Eliminate v = u - phi + D^{-1} A' lambda. For a part with
//    f_j + b_j > 0 write its friction force m_j phi_j = m_j f_j - sigma_j, sigma_j in
//    [0, m_j (f_j + b_j)], and eta_j >= 0 for the upper bound; the box's sign conditions on v_j
//    are then  0 <= sigma_j _|_ v_j + eta_j >= 0  and  0 <= eta_j _|_ m_j (f_j + b_j) - sigma_j >= 0
//    (sigma = 0: v >= 0; sigma at its top: eta = -v >= 0; between: v = 0). A frictionless part
//    has phi_j = 0 and no variable. In z = (sigma, eta, lambda):
//        v      = u - f + D^{-1} sigma + D^{-1} A' lambda
//        w_sigma = v + eta,   w_eta = D (f + b) - sigma,   w_lambda = A v - c
//        M = [ D^{-1}  I  D^{-1} A' ;  -I  0  0 ;  A D^{-1}  0  A D^{-1} A' ]
//    (rows and columns of frictionless parts left out). Its symmetric part is the Gram matrix of
//    [I 0 A'] under D^{-1}: positive semidefinite, so M is copositive-plus and Lemke's method
//    ends with a solution (the LCP is feasible: the problem has one). v is recovered from the
//    formula, so a stick comes out as a rounding residue (1e-16), not exactly 0.
// 2. The primal LCP (the last fallback). Split v = p - q, p, q >= 0: for fixed v,
//    min f p + b q over p - q = v is f max(v, 0) + b max(-v, 0), so the problem is a QP in
//    (p, q) whose KKT conditions are the LCP in z = (p, q, lambda):
//        M = [ D  -D  -A' ;  -D  D  A' ;  A  -A  0 ],   q = ( D (f - u), D (b + u), -c ),
//    M + M' = [ 2D -2D 0 ; -2D 2D 0 ; 0 0 0 ] positive semidefinite. v = p - q; a stick is exact
//    (nonbasic variables are 0).
// Siconos's Lemke (lcp_lexicolemke) takes any pivot > 0.0, without a tolerance; on these
// rank-deficient matrices a rounding residue of 1e-17 is now and then taken as a pivot and the
// result is garbage (|z| ~ 1e16), which the driver's error test reports (info 1). Measured on
// 1200 random instances (n <= 8): the primal LCP failed 23 times, the dual once, never both,
// and the dual of the mirrored chain (parts in reverse order, v -> -v: u -> -u, f <-> b) solved
// every instance whose dual failed. So the oracle tries the dual, the mirrored dual, then the
// primal, accepts a result only where Siconos reports success AND its lcp_compute_error is at
// most kLcpErrorTol, and fails the test if none is accepted. (Siconos's other LCP solvers did
// worse here: PIVOT 121 failures of 1200, PATHSEARCH 412, Murty 572, Bard 772, NEWTONMIN 680,
// NEWTON_FB 244, PATH 1141 (not built in), PIVOT_LUMOD aborts on an assertion.)
//
// lambda is NOT unique in general (several parts of one block at rest: the friction among them
// is statically indeterminate), so it is not compared with anything; instead Siconos's lambda
// must certify the library's v: with the library's v (exact stick) and Siconos's lambda, every
// part's friction
//     phi_k = (lambda_{k-1} - lambda_k) / m_k - (v_k - u_k)
// must be f_k where v_k > 0, -b_k where v_k < 0 and within [-b_k, f_k] where v_k == 0, and
// lambda >= 0 complementary to the library's gaps. These are the KKT conditions at the
// library's v, so they prove it optimal up to the tolerances (and an exact stick that the
// library missed, a tiny v_k != 0 instead of 0, fails them: phi_k would have to be f_k or -b_k).
//
// Accuracy: Lemke's pivots on a tableau of size 23 at most (n <= 8) with entries in
// [0.2, 5] and +-1: rounding about 1e-14 (measured: max |v - v_siconos| 7.8e-14 over 4800
// instances, lcp_compute_error <= 1.1e-14; the primal LCP against Siconos's enumeration solver,
// n <= 4: 8.8e-15). kVelocityTol = 1e-9 leaves four orders of magnitude of margin and is still
// far below any modelling difference (a wrong block or kink: differences of 1e-3 and more with
// these data). The oracle's |v| <= kStickTol = 1e-9 counts as its stick.

#include <gtest/gtest.h>

#include <LCP_Solvers.h>
#include <LinearComplementarityProblem.h>
#include <NonSmoothDrivers.h>
#include <NumericsMatrix.h>
#include <SolverOptions.h>
#include <lcp_cst.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "selfalign/core/chain_problem.hpp"

namespace chain_siconos_test {

using selfalign::core::ChainFriction;
using selfalign::core::ChainPart;

constexpr double kVelocityTol = 1e-9;  // |v - v_siconos| (see the accuracy note above)
constexpr double kStickTol = 1e-9;     // the oracle's |v_i| at or below this: a stick
constexpr double kForceTol = 1e-9;     // times the instance's force scale (force_scale)
constexpr double kLcpErrorTol = 1e-10; // Siconos's lcp_compute_error of an accepted solution

struct OracleSolution {
  std::vector<double> v;
  std::vector<double> lambda;
  double lcp_error = 0;  // Siconos's lcp_compute_error of the accepted (z, w)
  int formulation = 0;   // 0: dual, 1: mirrored dual, 2: primal
};

// A dense LCP, M column-major (entry (i, j) at M[i + size * j], as NumericsMatrix stores it).
struct DenseLcp {
  int size = 0;
  std::vector<double> M, q;
  explicit DenseLcp(int n) : size(n), M(static_cast<std::size_t>(n) * static_cast<std::size_t>(n)),
                             q(static_cast<std::size_t>(n)) {}
  double& at(int row, int col) {
    return M[static_cast<std::size_t>(row) + static_cast<std::size_t>(size) * static_cast<std::size_t>(col)];
  }
};

// Solves the LCP with Siconos's lexicographic Lemke; z, or nothing where Siconos reports a
// failure or the error exceeds kLcpErrorTol.
inline bool siconos_lemke(const DenseLcp& lcp, std::vector<double>& z, double& error) {
  const auto size = static_cast<std::size_t>(lcp.size);
  z.assign(size, 0.0);
  error = 0;
  if (size == 0) return true;
  NumericsMatrix* matrix = NM_create(NM_DENSE, lcp.size, lcp.size);  // owns matrix0
  std::copy(lcp.M.begin(), lcp.M.end(), matrix->matrix0);
  std::vector<double> q = lcp.q, w(size, 0.0);
  LinearComplementarityProblem problem{};
  problem.size = lcp.size;
  problem.M = matrix;
  problem.q = q.data();
  SolverOptions* options = solver_options_create(SICONOS_LCP_LEMKE);
  const int info = linearComplementarity_driver(&problem, z.data(), w.data(), options);
  lcp_compute_error(&problem, z.data(), w.data(), kLcpErrorTol, &error);
  solver_options_delete(options);  // 4.4: frees the members, not the struct
  std::free(options);
  NM_free(matrix);
  return info == 0 && error <= kLcpErrorTol;
}

// The dual LCP (1. above).
inline bool dual_chain(std::span<const ChainPart> parts, std::span<const double> c,
                       OracleSolution& out) {
  const int n = static_cast<int>(parts.size());
  const auto idx = [](int k) { return static_cast<std::size_t>(k); };
  std::vector<int> sigma(idx(n), -1), eta(idx(n), -1);
  int frictional = 0;
  for (int j = 0; j < n; ++j)
    if (parts[idx(j)].forward + parts[idx(j)].backward > 0) sigma[idx(j)] = frictional++;
  for (int j = 0; j < n; ++j)
    if (sigma[idx(j)] >= 0) eta[idx(j)] = frictional + sigma[idx(j)];
  const auto L = [frictional](int i) { return 2 * frictional + i; };
  DenseLcp lcp(2 * frictional + n - 1);
  // row += s * v_j, v_j = u_j - f_j + sigma_j / m_j + (lambda_{j-1} - lambda_j) / m_j
  const auto add_v = [&](int row, int j, double s) {
    const ChainPart& p = parts[idx(j)];
    const int sj = sigma[idx(j)];
    lcp.q[idx(row)] += s * (p.target - (sj >= 0 ? p.forward : 0.0));
    if (sj >= 0) lcp.at(row, sj) += s / p.mass;
    if (j >= 1) lcp.at(row, L(j - 1)) += s / p.mass;
    if (j + 1 < n) lcp.at(row, L(j)) -= s / p.mass;
  };
  for (int j = 0; j < n; ++j) {
    const int sj = sigma[idx(j)], ej = eta[idx(j)];
    if (sj < 0) continue;
    add_v(sj, j, 1.0);  // w_sigma = v + eta
    lcp.at(sj, ej) = 1.0;
    lcp.at(ej, sj) = -1.0;  // w_eta = m (f + b) - sigma
    const ChainPart& p = parts[idx(j)];
    lcp.q[idx(ej)] = p.mass * (p.forward + p.backward);
  }
  for (int i = 0; i + 1 < n; ++i) {  // w_lambda = v_{i+1} - v_i - c_i
    add_v(L(i), i + 1, 1.0);
    add_v(L(i), i, -1.0);
    lcp.q[idx(L(i))] -= c[idx(i)];
  }
  std::vector<double> z;
  if (!siconos_lemke(lcp, z, out.lcp_error)) return false;
  out.v.assign(idx(n), 0.0);
  out.lambda.assign(idx(n - 1), 0.0);
  for (int j = 0; j < n; ++j) {
    const ChainPart& p = parts[idx(j)];
    const int sj = sigma[idx(j)];
    double v = p.target - (sj >= 0 ? p.forward : 0.0);
    if (sj >= 0) v += z[idx(sj)] / p.mass;
    if (j >= 1) v += z[idx(L(j - 1))] / p.mass;
    if (j + 1 < n) v -= z[idx(L(j))] / p.mass;
    out.v[idx(j)] = v;
  }
  for (int i = 0; i + 1 < n; ++i) out.lambda[idx(i)] = z[idx(L(i))];
  return true;
}

// The primal LCP (2. above).
inline bool primal_chain(std::span<const ChainPart> parts, std::span<const double> c,
                         OracleSolution& out) {
  const int n = static_cast<int>(parts.size());
  const auto idx = [](int k) { return static_cast<std::size_t>(k); };
  const auto P = [](int j) { return j; };
  const auto Q = [n](int j) { return n + j; };
  const auto L = [n](int i) { return 2 * n + i; };
  DenseLcp lcp(3 * n - 1);
  for (int j = 0; j < n; ++j) {
    const ChainPart& part = parts[idx(j)];
    const double m = part.mass;
    lcp.at(P(j), P(j)) = m;
    lcp.at(P(j), Q(j)) = -m;
    lcp.at(Q(j), P(j)) = -m;
    lcp.at(Q(j), Q(j)) = m;
    lcp.q[idx(P(j))] = m * (part.forward - part.target);
    lcp.q[idx(Q(j))] = m * (part.backward + part.target);
    if (j + 1 < n) {  // contact j pushes part j backward: -A' has +1 at (p_j, lambda_j)
      lcp.at(P(j), L(j)) = 1.0;
      lcp.at(Q(j), L(j)) = -1.0;
    }
    if (j >= 1) {  // contact j - 1 pushes part j forward
      lcp.at(P(j), L(j - 1)) = -1.0;
      lcp.at(Q(j), L(j - 1)) = 1.0;
    }
  }
  for (int i = 0; i + 1 < n; ++i) {  // w_lambda = v_{i+1} - v_i - c_i
    lcp.at(L(i), P(i)) = -1.0;
    lcp.at(L(i), Q(i)) = 1.0;
    lcp.at(L(i), P(i + 1)) = 1.0;
    lcp.at(L(i), Q(i + 1)) = -1.0;
    lcp.q[idx(L(i))] = -c[idx(i)];
  }
  std::vector<double> z;
  if (!siconos_lemke(lcp, z, out.lcp_error)) return false;
  out.v.assign(idx(n), 0.0);
  out.lambda.assign(idx(n - 1), 0.0);
  for (int j = 0; j < n; ++j) out.v[idx(j)] = z[idx(P(j))] - z[idx(Q(j))];
  for (int i = 0; i + 1 < n; ++i) out.lambda[idx(i)] = z[idx(L(i))];
  return true;
}

// The chain problem by Siconos: the dual LCP, the mirrored chain's dual, the primal LCP, the
// first that Siconos solves (see above). Throws if none.
inline OracleSolution siconos_chain(std::span<const ChainPart> parts, std::span<const double> c) {
  OracleSolution out;
  if (dual_chain(parts, c, out)) return out;
  // mirrored: part n-1-j with -u, f and b swapped; contact n-2-i; v_j = -v'_{n-1-j}
  std::vector<ChainPart> mirrored(parts.rbegin(), parts.rend());
  for (ChainPart& p : mirrored) {
    p.target = -p.target;
    std::swap(p.forward, p.backward);
  }
  const std::vector<double> mirrored_c(c.rbegin(), c.rend());
  if (dual_chain(mirrored, mirrored_c, out)) {
    std::reverse(out.v.begin(), out.v.end());
    for (double& v : out.v) v = -v;
    std::reverse(out.lambda.begin(), out.lambda.end());
    out.formulation = 1;
    return out;
  }
  if (primal_chain(parts, c, out)) {
    out.formulation = 2;
    return out;
  }
  throw std::runtime_error("Siconos's Lemke failed on the dual, mirrored dual and primal LCPs");
}

// The break-loose rule of solve_chain_static_kinetic (its doc comment), written again with the
// Siconos oracle as the inner solver: parts not sliding on hold with s_i both ways; one sliding
// on pulls with its kinetic bound in that direction; a part the current problem sets moving
// (v_i != 0: the oracle's |v_i| > kStickTol) pulls with its kinetic bound in the direction of
// its motion from then on; solve again until no part breaks loose further.
struct OracleStaticKinetic {
  OracleSolution solution;
  std::vector<ChainPart> parts;  // the bounds of the last solve
  int solves = 0;
};

inline OracleStaticKinetic siconos_static_kinetic(std::span<const ChainPart> parts0,
                                                  std::span<const ChainFriction> friction,
                                                  std::span<const double> c) {
  const std::size_t n = parts0.size();
  OracleStaticKinetic out;
  out.parts.assign(parts0.begin(), parts0.end());
  std::vector<bool> kinetic_forward(n), kinetic_backward(n);
  for (std::size_t i = 0; i < n; ++i) {
    kinetic_forward[i] = friction[i].sliding_on > 0;
    kinetic_backward[i] = friction[i].sliding_on < 0;
  }
  for (;;) {
    for (std::size_t i = 0; i < n; ++i) {
      out.parts[i].forward = kinetic_forward[i] ? friction[i].forward : friction[i].hold;
      out.parts[i].backward = kinetic_backward[i] ? friction[i].backward : friction[i].hold;
    }
    out.solution = siconos_chain(out.parts, c);
    ++out.solves;
    bool more = false;
    for (std::size_t i = 0; i < n; ++i) {
      const double v = out.solution.v[i];
      if (v > kStickTol && !kinetic_forward[i]) kinetic_forward[i] = true, more = true;
      if (v < -kStickTol && !kinetic_backward[i]) kinetic_backward[i] = true, more = true;
    }
    if (!more) return out;
  }
}

struct Instance {
  std::vector<ChainPart> parts;
  std::vector<double> c;
  std::vector<ChainFriction> friction;  // the static-kinetic tests only
};

inline std::string describe(const Instance& in, std::span<const double> v_library,
                            std::span<const double> v_oracle,
                            std::span<const double> lambda_oracle) {
  std::ostringstream s;
  s.precision(17);
  s << "n = " << in.parts.size() << "\n";
  for (std::size_t i = 0; i < in.parts.size(); ++i) {
    const ChainPart& p = in.parts[i];
    s << "  part " << i << ": m " << p.mass << " u " << p.target << " f " << p.forward << " b "
      << p.backward;
    if (!in.friction.empty()) {
      const ChainFriction& f = in.friction[i];
      s << " | hold " << f.hold << " kf " << f.forward << " kb " << f.backward << " sliding_on "
        << f.sliding_on;
    }
    s << " | v_library " << v_library[i] << " v_siconos " << v_oracle[i] << "\n";
  }
  for (std::size_t i = 0; i < in.c.size(); ++i)
    s << "  contact " << i << ": c " << in.c[i] << " lambda_siconos " << lambda_oracle[i] << "\n";
  return s.str();
}

// The scale of the contact forces: sum m (1 + |u| + f + b) + total offset.
inline double force_scale(std::span<const ChainPart> parts, std::span<const double> c) {
  double s = 0;
  for (const ChainPart& p : parts) s += p.mass * (1 + std::abs(p.target) + p.forward + p.backward);
  for (double ci : c) s += ci;
  return s;
}

struct Stats {
  int instances = 0, parts = 0, sticks = 0, uncertified = 0;
  int formulations[3] = {0, 0, 0};  // accepted: dual, mirrored dual, primal
  double max_dv = 0, max_lcp_error = 0, max_kkt = 0;
};

// All checks of one instance: |v - v_siconos|, exact stick both ways, and the KKT conditions at
// the library's v with Siconos's lambda (the certificate described at the top).
inline void check_against_oracle(const Instance& in, std::span<const ChainPart> parts,
                                 std::span<const double> v, const OracleSolution& oracle,
                                 Stats& stats) {
  const std::size_t n = parts.size();
  const double force_tol = kForceTol * force_scale(parts, in.c);
  bool ok = true;
  ++stats.instances;
  ++stats.formulations[oracle.formulation];
  stats.max_lcp_error = std::max(stats.max_lcp_error, oracle.lcp_error);
  for (std::size_t i = 0; i < n; ++i) {
    ++stats.parts;
    const double dv = std::abs(v[i] - oracle.v[i]);
    stats.max_dv = std::max(stats.max_dv, dv);
    if (dv > kVelocityTol) ok = false;
    if (std::abs(oracle.v[i]) <= kStickTol) {
      ++stats.sticks;
      if (v[i] != 0.0) ok = false;  // exact stick: no threshold in the library
    }
    if (v[i] == 0.0 && std::abs(oracle.v[i]) > kVelocityTol) ok = false;
  }
  // the certificate: lambda >= 0, complementary to the library's gaps, friction in the set
  double kkt = 0;  // the largest violation seen
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double lambda = oracle.lambda[i];
    const double gap = v[i + 1] - v[i] - in.c[i];
    kkt = std::max(kkt, std::max(0.0, -lambda) / force_tol);
    kkt = std::max(kkt, std::max(0.0, -gap) / kVelocityTol);
    kkt = std::max(kkt, std::min(lambda / force_tol, gap / kVelocityTol));
  }
  for (std::size_t k = 0; k < n; ++k) {
    const ChainPart& p = parts[k];
    const double behind = k == 0 ? 0.0 : oracle.lambda[k - 1];
    const double ahead = k + 1 == n ? 0.0 : oracle.lambda[k];
    const double m_phi = behind - ahead - p.mass * (v[k] - p.target);  // m_k phi_k
    const double hi = p.mass * p.forward, lo = -p.mass * p.backward;
    double violation = 0;
    if (v[k] > 0)
      violation = std::abs(m_phi - hi);
    else if (v[k] < 0)
      violation = std::abs(m_phi - lo);
    else
      violation = std::max({0.0, m_phi - hi, lo - m_phi});
    kkt = std::max(kkt, violation / force_tol);
  }
  stats.max_kkt = std::max(stats.max_kkt, kkt);
  if (kkt > 1) {
    ok = false;
    ++stats.uncertified;
  }
  if (!ok) {
    Instance shown = in;
    shown.parts.assign(parts.begin(), parts.end());
    ADD_FAILURE() << "the library disagrees with Siconos (kkt violation " << kkt
                  << " x tolerance):\n"
                  << describe(shown, v, oracle.v, oracle.lambda);
  }
}

inline Instance random_instance(std::mt19937_64& rng, int k) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> size(1, 8);
  Instance in;
  const int n = size(rng);
  in.parts.resize(static_cast<std::size_t>(n));
  for (ChainPart& p : in.parts) {
    p.mass = 0.2 + 4.8 * unit(rng);
    p.target = -3 + 6 * unit(rng);
    p.forward = 2 * unit(rng);
    p.backward = 2 * unit(rng);
    if (unit(rng) < 0.1) p.forward = p.backward = 0;  // frictionless parts now and then
  }
  in.c.assign(static_cast<std::size_t>(n - 1), 0.0);
  if (k % 2 == 1)  // half the instances with restitution offsets
    for (double& ci : in.c) ci = unit(rng);
  return in;
}

inline void print_stats(const char* name, const Stats& s, double seconds) {
  std::printf("[ %s ] %d instances, %d parts, %d sticks; max |v - v_siconos| %.3g, "
              "max Siconos LCP error %.3g, max KKT violation %.3g x tolerance; LCPs solved: "
              "%d dual, %d mirrored dual, %d primal; %.2f s\n",
              name, s.instances, s.parts, s.sticks, s.max_dv, s.max_lcp_error, s.max_kkt,
              s.formulations[0], s.formulations[1], s.formulations[2], seconds);
}

using selfalign::core::ChainWorkspace;

TEST(ChainSiconos, TwoEqualFrictionlessMassesShareTheMomentum) {
  // u = (1, 0), c = 0: the rear part catches the front one; both end at the mean, 0.5.
  const std::vector<ChainPart> parts{{1, 1, 0, 0}, {1, 0, 0, 0}};
  const std::vector<double> c{0};
  const std::vector<double> v = selfalign::core::solve_chain(parts, c);
  const auto oracle = siconos_chain(parts, c);
  EXPECT_EQ(v[0], 0.5);
  EXPECT_EQ(v[1], 0.5);
  EXPECT_NEAR(oracle.v[0], 0.5, kVelocityTol);
  EXPECT_NEAR(oracle.v[1], 0.5, kVelocityTol);
  EXPECT_NEAR(oracle.lambda[0], 0.5, kVelocityTol);  // m_0 (u_0 - v_0): unique, both move
}

TEST(ChainSiconos, ARestitutionOffsetSeparatesThePair) {
  // u = (1, 0), c = 0.5, no friction: v_1 = v_0 + 0.5 and momentum 1: v = (0.25, 0.75).
  const std::vector<ChainPart> parts{{1, 1, 0, 0}, {1, 0, 0, 0}};
  const std::vector<double> c{0.5};
  const std::vector<double> v = selfalign::core::solve_chain(parts, c);
  const auto oracle = siconos_chain(parts, c);
  EXPECT_NEAR(v[0], 0.25, 1e-15);
  EXPECT_NEAR(v[1], 0.75, 1e-15);
  EXPECT_NEAR(oracle.v[0], 0.25, kVelocityTol);
  EXPECT_NEAR(oracle.v[1], 0.75, kVelocityTol);
  EXPECT_NEAR(oracle.lambda[0], 0.75, kVelocityTol);
}

TEST(ChainSiconos, FrictionHoldsBothParts) {
  // u = (0.3, -0.1), bounds 1: each part's target lies within its bounds; both stick exactly.
  const std::vector<ChainPart> parts{{1, 0.3, 1, 1}, {1, -0.1, 1, 1}};
  const std::vector<double> c{0};
  const std::vector<double> v = selfalign::core::solve_chain(parts, c);
  const auto oracle = siconos_chain(parts, c);
  EXPECT_EQ(v[0], 0.0);
  EXPECT_EQ(v[1], 0.0);
  EXPECT_NEAR(oracle.v[0], 0.0, kStickTol);
  EXPECT_NEAR(oracle.v[1], 0.0, kStickTol);
}

TEST(ChainSiconos, StaticKineticClosedForms) {
  struct Case {
    double u, hold, kf, kb;
    int sliding_on;
    double v;
    int solves;
  };
  // one part: the 1-D Moreau projection with static and kinetic bounds
  const Case cases[] = {
      {1.5, 1.0, 0.5, 0.4, 0, 1.0, 2},    // breaks loose forward: 1.5 - 0.5
      {0.8, 1.0, 0.5, 0.4, 0, 0.0, 1},    // held by static friction
      {0.8, 1.0, 0.5, 0.4, +1, 0.3, 1},   // sliding on forward: kinetic at once
      {-1.5, 1.0, 0.5, 0.4, +1, -1.1, 2}, // sliding forward, reversed: static, then kinetic back
      {-0.8, 1.0, 0.5, 0.4, -1, -0.4, 1}, // sliding on backward
  };
  for (const Case& k : cases) {
    std::vector<ChainPart> parts{{2.0, k.u, 0, 0}};
    const std::vector<ChainFriction> friction{{k.hold, k.kf, k.kb, k.sliding_on}};
    std::vector<double> v(1);
    ChainWorkspace work;
    const int solves = selfalign::core::solve_chain_static_kinetic(parts, friction, {}, v, work);
    EXPECT_NEAR(v[0], k.v, 1e-15) << "u " << k.u << " sliding_on " << k.sliding_on;
    EXPECT_EQ(solves, k.solves) << "u " << k.u << " sliding_on " << k.sliding_on;
    const auto oracle = siconos_static_kinetic(parts, friction, {});
    EXPECT_NEAR(oracle.solution.v[0], k.v, kVelocityTol);
    EXPECT_EQ(oracle.solves, k.solves);
  }
  // two equal parts at rest, hold 1, kinetic 0.5, u = (2.5, 0): statically the pair moves at
  // (2.5 - 2 x 1) / 2 = 0.25, so both break loose: (2.5 - 2 x 0.5) / 2 = 0.75.
  std::vector<ChainPart> parts{{1, 2.5, 0, 0}, {1, 0, 0, 0}};
  const std::vector<ChainFriction> friction{{1, 0.5, 0.5, 0}, {1, 0.5, 0.5, 0}};
  const std::vector<double> c{0};
  std::vector<double> v(2);
  ChainWorkspace work;
  EXPECT_EQ(selfalign::core::solve_chain_static_kinetic(parts, friction, c, v, work), 2);
  EXPECT_NEAR(v[0], 0.75, 1e-15);
  EXPECT_NEAR(v[1], 0.75, 1e-15);
  const auto oracle = siconos_static_kinetic(parts, friction, c);
  EXPECT_NEAR(oracle.solution.v[0], 0.75, kVelocityTol);
  EXPECT_NEAR(oracle.solution.v[1], 0.75, kVelocityTol);
}

TEST(ChainSiconos, AgreesOnAThousandRandomInstances) {
  const auto start = std::chrono::steady_clock::now();
  std::mt19937_64 rng(20240611);
  Stats stats;
  for (int k = 0; k < 1200; ++k) {
    const Instance in = random_instance(rng, k);
    const std::vector<double> v = selfalign::core::solve_chain(in.parts, in.c);
    ASSERT_EQ(v.size(), in.parts.size());
    const auto oracle = siconos_chain(in.parts, in.c);
    check_against_oracle(in, in.parts, v, oracle, stats);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  print_stats("ChainSiconos", stats, seconds);
  EXPECT_GT(stats.sticks, stats.parts / 10);  // the sample exercises exact stick
}

TEST(ChainSiconos, StaticAboveKineticAgreesOnAThousandRandomInstances) {
  const auto start = std::chrono::steady_clock::now();
  std::mt19937_64 rng(777);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> direction(-1, 1);
  Stats stats;
  int more_than_one_solve = 0;
  for (int k = 0; k < 1200; ++k) {
    Instance in = random_instance(rng, k);
    for (const ChainPart& p : in.parts) {
      ChainFriction f;
      f.forward = p.forward;
      f.backward = p.backward;
      // hold >= max(kinetic): now and then equal to it, else up to 1 above
      f.hold = std::max(f.forward, f.backward) + (unit(rng) < 0.1 ? 0.0 : unit(rng));
      f.sliding_on = direction(rng);
      in.friction.push_back(f);
    }
    std::vector<ChainPart> parts = in.parts;
    std::vector<double> v(parts.size());
    ChainWorkspace work;
    const int solves =
        selfalign::core::solve_chain_static_kinetic(parts, in.friction, in.c, v, work);
    const auto oracle = siconos_static_kinetic(in.parts, in.friction, in.c);
    // the same final bounds (same break-loose sets) and the same number of solves
    for (std::size_t i = 0; i < parts.size(); ++i) {
      EXPECT_EQ(parts[i].forward, oracle.parts[i].forward) << "instance " << k << " part " << i;
      EXPECT_EQ(parts[i].backward, oracle.parts[i].backward) << "instance " << k << " part " << i;
    }
    EXPECT_EQ(solves, oracle.solves) << "instance " << k;
    EXPECT_LE(solves, 2 * static_cast<int>(parts.size()) + 1);
    if (solves > 1) ++more_than_one_solve;
    check_against_oracle(in, oracle.parts, v, oracle.solution, stats);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  print_stats("ChainSiconos static/kinetic", stats, seconds);
  std::printf("[ ChainSiconos static/kinetic ] %d instances broke loose (more than one solve)\n",
              more_than_one_solve);
  EXPECT_GT(more_than_one_solve, 100);  // the sample exercises the break-loose rule
}

}  // namespace chain_siconos_test
