#pragma once
/// \file local_search.hpp
/// The one multi-start constrained local optimiser every profile family uses (NLopt inside,
/// not exposed): minimise J(x) over a box subject to g_j(x) <= 0, from several starts, keeping
/// the best feasible point ever evaluated (so the result is never worse than the best start).
///
/// Derivative-free: NLopt LN_COBYLA. Gradient-based: NLopt LD_SLSQP with central
/// finite-difference gradients of J and every g_j, step h_i = fd_step * max(|x_i|, |x|_inf)
/// (error O(h^2) from truncation + O(eps/h) from the objective's rounding).

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "selfalign/analysis/steady_state.hpp"

namespace selfalign {

/// Relative slack the optimisers of the three families allow on every actuator limit: rounding
/// only [-].
inline constexpr double kFeasibilityTol = 1e-10;

/// Objective and constraint values at one point.
struct DesignEvaluation {
  double objective = 0;             ///< J(x), finite (families use a finite penalty)
  std::vector<double> constraints;  ///< g_j(x), feasible when all <= tolerance
};

struct LocalSearchProblem {
  std::vector<double> lower, upper;          ///< box bounds, same size as x
  std::vector<std::string> constraint_names; ///< one per g_j, names the binding limit
  /// Evaluates J and every g_j (constraints.size() == constraint_names.size()).
  std::function<DesignEvaluation(std::span<const double> x)> evaluate;
  /// Optional: evaluates every point of a finite-difference stencil at once (in parallel, say),
  /// out[i] for points[i]; each must equal what evaluate would give. Empty: evaluate, in turn.
  /// It calls heartbeat() before each point (from any thread) and lets what it throws
  /// propagate: that is how a cancelled search (see local_search) stops inside a stencil.
  std::function<void(const std::vector<std::vector<double>>& points,
                     std::vector<DesignEvaluation>& out, const std::function<void()>& heartbeat)>
      evaluate_many;
  bool gradient_based = false;  ///< LD_SLSQP with FD gradients; else LN_COBYLA
  double fd_step = 1e-6;        ///< relative FD step (gradient-based only)
  double feasibility_tol = 1e-10;  ///< g_j <= tol counts as feasible
  int max_evaluations = 2000;      ///< per local run (FD evaluations included)
  double relative_tol = 1e-10;     ///< NLopt ftol_rel and xtol_rel
  /// Each start's run is restarted from its best point (fresh initial step / quasi-Newton
  /// state) while that improves J by more than relative_tol, at most this many times.
  int restarts = 4;
};

struct LocalSearchResult {
  bool feasible = false;
  std::vector<double> x;         ///< best feasible point (or least violating when infeasible)
  double objective = 0;          ///< J(x)
  double violation = 0;          ///< max_j g_j(x) (<= tol when feasible)
  std::string binding;           ///< name of the most violated constraint at x when infeasible
  int evaluations = 0;           ///< all evaluations of J
  int runs = 0;                  ///< starts run (restarts included in their start)
};

/// The scale of the finite penalty design_objective gives profiles that do not move the object
/// forward; every forward-moving f lies far below it.
inline constexpr double kBackwardPenalty = 1e6;

/// Whether J (from design_objective) is the penalty of a profile that does not move the object
/// forward: the families mirror such starts (y -> -y, hence v̄ -> -v̄).
inline bool is_backward_penalty(double objective) { return objective >= kBackwardPenalty; }

/// The objective J every family hands to local_search: f = 1/(c v̄^2) of eq. (11) when v̄ > 0,
/// else the finite penalty 1e6 (1 + |v̄| Δt / Δy), which grows with the backward speed so the
/// optimiser keeps going (and is far above any f of a forward-moving profile).
double design_objective(double v_bar, double period, double stroke);

/// v̄ of a steady state when it is trustworthy, else NaN (which design_objective penalises):
/// not converged, or |v̄| above the physical bound max|y'| + Δt (the object's absolute
/// acceleration is at most 1, so its velocity stays within Δt of the table's range). Guards
/// against a spurious secant fixed point of steady_state() seen on a few smooth profiles.
double trusted_v_bar(const SteadyState& state, double max_table_velocity, double period);

/// Runs the local optimiser from every start (each clamped into the box) and returns the best
/// point over all of them. progress(done, total) after each run when set, and with the same
/// `done` every 50 ms while a run is under way; an exception it throws stops the search and
/// propagates (a front end's Ctrl-C).
LocalSearchResult local_search(const LocalSearchProblem& problem,
                               const std::vector<std::vector<double>>& starts,
                               const std::function<void(int, int)>& progress = {});

/// "no feasible <what>: <binding> is binding (least violation <v> relative)" for a failed search.
std::string infeasible_message(const std::string& what, const LocalSearchResult& result);

/// Merges b into a: keeps the better (feasible first, then lower objective, then smaller
/// violation); evaluations and runs add up.
void merge_best(LocalSearchResult& a, const LocalSearchResult& b);

}  // namespace selfalign
