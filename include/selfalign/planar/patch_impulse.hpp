#pragma once
/// \file patch_impulse.hpp
/// The impulse balance of one Moreau step for a rigid part on a contact patch (issue 13): with
/// isotropic Coulomb friction at every contact point it is the convex problem in the part's
/// relative twist delta = (v_x, v_y, omega) (relative to the table's twist, about the centre of
/// mass; docs/planar.md derives it)
///
///   minimise f(delta) = 1/2 (delta - delta*)^T M (delta - delta*) + sum_i c_i |G_i delta|,
///
/// M = diag(1, 1, j) (mass and moment of inertia per unit mass), delta* the relative twist
/// without friction, G_i delta = (v_x - omega d_iy, v_y + omega d_ix) the slip velocity of
/// contact i at lever arm d_i, c_i = h mu_i m(p_i) w_i its largest friction impulse. f is
/// strictly convex: the solution is unique. Its dual is the projection of the stopping impulse
/// W* = M delta* onto the patch's friction limit set L = { sum_i G_i^T lambda_i : |lambda_i| <=
/// c_i } (in the M^-1 metric), and delta = M^-1 (W* - proj W*). So the part sticks (delta = 0)
/// exactly when the impulse that would stop it lies in L; a contact j is a pivot (zero slip at
/// j, the others slipping) when the optimum lies on the line of rotations about p_j.
///
/// The solver decides each of the three cases with a certificate, not a velocity threshold:
///  - stick: a friction impulse distribution in L that balances W* / (1 - eta) up to a residual
///    whose gauge is at most eta / (1 - eta) proves W* in L (eta = 1e-10: W* within a relative
///    1e-10 of the boundary of L counts as in L). Found by the dual block Gauss-Seidel of
///    Jean and Moreau (as Siconos' NSGS) with exact disc-constrained block solves, after a
///    one-shot check of the least-squares distribution;
///  - slip: a twist d with d.W* > sum_i c_i |G_i d| proves delta = 0 is not optimal; the
///    optimum then comes from Newton's method with a backtracking line search on f
///    (quadratic convergence on the smooth part), to |grad f| <= 1e-13 of the problem's scale;
///  - pivot about contact j: the minimiser along delta = s (d_jy, -d_jx, 1) is a soft
///    threshold in closed form, and it is optimal iff the impulse left for contact j fits in its
///    disc (an exact subgradient check).
/// For static above kinetic friction, stick is tested with the static bounds and the slip solved
/// with the kinetic ones. A patch whose points all sit at the centre of mass is the point
/// contact: a closed-form disc projection, the spin unchanged.

#include <array>
#include <span>
#include <vector>

namespace selfalign {

/// One contact of the step: lever arm d from the centre of mass in the world frame [-], its
/// largest static friction impulse (stick test) and its kinetic impulse (slip) [-].
struct PatchContact {
  double dx = 0, dy = 0;
  double stick_bound = 0, slip_bound = 0;  ///< h s m w and h k m w; 0 < slip <= stick
};

/// How the step ended.
enum class PatchMode { stick, pivot, slip };

/// "stick", "pivot" or "slip".
const char* patch_mode_name(PatchMode mode) noexcept;

struct PatchImpulseResult {
  std::array<double, 3> twist{};  ///< relative twist after the step (v_x, v_y, omega) [-]
  PatchMode mode = PatchMode::stick;
  int pivot = -1;          ///< the pivot contact's index (mode pivot), else -1
  int sweeps = 0;          ///< dual Gauss-Seidel sweeps
  int newton_steps = 0;    ///< Newton iterations
};

/// The solver keeps the last dual impulses as a warm start (one allocation per patch size).
class PatchImpulseSolver {
 public:
  /// Solves the step's problem. \param inertia j > 0 [-]; \param free_twist delta*.
  PatchImpulseResult solve(std::span<const PatchContact> contacts, double inertia,
                           const std::array<double, 3>& free_twist);

  /// The relative tolerance eta of the stick certificate.
  static constexpr double stick_tolerance = 1e-10;

 private:
  std::vector<double> lambda_;  // 2 n dual impulses (x, y per contact)
};

/// f(delta) of the header comment with the slip bounds (for tests and checks).
double patch_objective(std::span<const PatchContact> contacts, double inertia,
                       const std::array<double, 3>& free_twist, const std::array<double, 3>& twist);

}  // namespace selfalign
