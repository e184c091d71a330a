#pragma once
/// \file chain_problem.hpp
/// The contact problem of a row of touching 1-D parts (issue 24), the one problem behind both
/// of the row's solvers (docs/rows.md):
///   - Moreau's step (core/step.hpp): the unknowns are the velocities at t_{k+1};
///   - the exact row solver's mode at an event (simulate/row_exact.hpp): the unknowns are the
///     accelerations just after the event.
/// For parts 0 .. n-1 from the rear to the front, each with mass m_i > 0, target u_i (the
/// velocity without friction and contacts, resp. the acceleration), and the convex friction
/// term of its Coulomb law, the forward and backward bounds f_i, b_i >= 0 (per unit mass:
/// coefficient x level x normal impulse, resp. x normal load), it is
///     minimise   sum_i m_i ( (v_i - u_i)^2 / 2 + f_i max(v_i, 0) + b_i max(-v_i, 0) )
///     subject to v_{i+1} - v_i >= c_i   (i = 0 .. n-2; the contact between i and i+1)
/// with c_i = 0 for a contact that holds (Moreau's plastic contact, an event's touching pair)
/// and c_i = -e (relative velocity before) for Newton's restitution e. Its optimality
/// conditions are the contact law: each contact force lambda_i >= 0, complementary to
/// v_{i+1} - v_i - c_i >= 0; each part's friction in [-b_i, f_i] (per unit mass), set-valued at
/// v_i = 0 (exact stick: no velocity threshold). The objective is strictly convex (m_i > 0),
/// so the solution is unique (docs/rows.md gives the proof and the static > kinetic rule).
///
/// Solved exactly by the pool-adjacent-violators algorithm for separable convex objectives on a
/// chain (Best, Chakravarti and Ubhaya 2000): in the shifted velocities w_i = v_i - C_i,
/// C_i = c_0 + ... + c_{i-1}, the constraints are w_0 <= w_1 <= ... <= w_{n-1}; blocks of parts
/// that move together are pooled while a block's minimiser exceeds its successor's. A block's
/// minimiser of a sum of quadratics and kinks is closed-form (all kinks at one point: the
/// block's soft threshold) or found by one scan over its sorted kinks. O(n) blocks merges,
/// each O(block) when every c_i = 0.

#include <span>
#include <vector>

namespace selfalign::core {

/// One part of a chain (per unit mass where it says so).
struct ChainPart {
  double mass = 1;      ///< m_i > 0 [-]
  double target = 0;    ///< u_i: the velocity (acceleration) without friction and contacts [-]
  double forward = 0;   ///< f_i >= 0: friction's largest backward pull on forward motion [-]
  double backward = 0;  ///< b_i >= 0: friction's largest forward pull on backward motion [-]
};

/// A pooled block of the algorithm (internal to solve_chain; in the workspace so that a solve
/// allocates nothing once the workspace is sized).
struct ChainBlock {
  int begin = 0, end = 0;
  double mass = 0, mu = 0, mc = 0, mf = 0, mb = 0;  ///< sums of m, m u, m C, m f, m b
  bool uniform = true;   ///< every part of the block has the same shift C
  double shift = 0;      ///< that C (uniform blocks)
  double w = 0, y = 0;   ///< the minimiser: shifted (v = w + C), and v itself (uniform)
};

/// Reusable workspace (no allocation per call once sized).
struct ChainWorkspace {
  std::vector<double> shift, kinks;
  std::vector<ChainBlock> blocks;
  std::vector<signed char> broken_forward, broken_backward;
};

/// Solves the chain problem for `parts` (n >= 1) and the offsets `c` (n - 1 values) into
/// `v` (n values). Exact up to rounding (one closed form per final block). A block of one part
/// gives its closed form term for term: u - f if u > f, u + b if u < -b, else 0 (the 1-D
/// Moreau projection's arithmetic). Preconditions (not checked here: the callers validate):
/// masses > 0, bounds >= 0, all finite.
void solve_chain(std::span<const ChainPart> parts, std::span<const double> c,
                 std::span<double> v, ChainWorkspace& work);

/// The same, allocating: the n velocities. (The contact forces are not returned: where several
/// parts of one block are at rest, the friction between them and the table, hence the forces
/// between them, are statically indeterminate; v is unique.)
std::vector<double> solve_chain(std::span<const ChainPart> parts, std::span<const double> c);

/// Static above kinetic (docs/rows.md): parts that are not sliding on hold with their static
/// bound s_i in both directions; a part that the static problem sets moving (v_i != 0) has
/// broken loose and pulls with its kinetic bound in that direction, and the problem is solved
/// again, until no further part breaks loose (at most 2n + 1 solves; the set only grows). For
/// one part it is the 1-D Moreau projection with static and kinetic bounds, term for term.
struct ChainFriction {
  double hold = 0;          ///< s_i: the static bound (per unit mass) of a part not sliding on
  double forward = 0;       ///< kinetic bound forward (f_i above)
  double backward = 0;      ///< kinetic bound backward (b_i above)
  int sliding_on = 0;       ///< +1 / -1: sliding on in that direction (kinetic bound there), 0: not
};

/// Solves with the break-loose rule: parts[i].forward / backward are overwritten from
/// friction[i] at each pass. Returns the number of solves.
int solve_chain_static_kinetic(std::span<ChainPart> parts, std::span<const ChainFriction> friction,
                               std::span<const double> c, std::span<double> v,
                               ChainWorkspace& work);

}  // namespace selfalign::core
