#include "selfalign/design/local_search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>

#include <nlopt.hpp>

#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/error.hpp"

namespace selfalign {

namespace {

// The longest a local run goes without calling progress (see local_search).
constexpr std::chrono::milliseconds kHeartbeatInterval{50};

double max_violation(const DesignEvaluation& e) {
  double v = -std::numeric_limits<double>::infinity();
  for (double g : e.constraints) v = std::isnan(g) ? std::numeric_limits<double>::infinity()
                                                   : std::max(v, g);
  return e.constraints.empty() ? 0.0 : v;
}

// Thrown by the heartbeat when progress throws (a front end cancelling the search): carries
// progress's own exception through the families' parallel stencils and through NLopt (whose
// C++ wrapper would turn it into a plain stop); local_search rethrows the original.
struct SearchCancelled {
  std::exception_ptr reason;
};

// One local run: wraps the problem for NLopt, caches the last evaluation (NLopt asks for J
// and g at the same x in two calls) and records the best point it sees. heartbeat() comes
// before every evaluation; a SearchCancelled it throws inside NLopt stops NLopt and is
// rethrown after optimize().
class Run {
 public:
  Run(const LocalSearchProblem& p, const std::function<void()>& heartbeat)
      : p_(p), heartbeat_(heartbeat) {
    best_.objective = std::numeric_limits<double>::infinity();
    best_.violation = std::numeric_limits<double>::infinity();
  }

  LocalSearchResult operator()(std::vector<double> x) {
    const auto n = static_cast<unsigned>(x.size());
    const std::size_t m = p_.constraint_names.size();
    for (unsigned i = 0; i < n; ++i) x[i] = std::clamp(x[i], p_.lower[i], p_.upper[i]);
    record(x.data(), evaluate(x.data()));  // the start itself counts
    nlopt::opt opt(p_.gradient_based ? nlopt::LD_SLSQP : nlopt::LN_COBYLA, n);
    opt.set_lower_bounds(p_.lower);
    opt.set_upper_bounds(p_.upper);
    opt.set_min_objective(&Run::objective, this);
    if (m > 0)
      opt.add_inequality_mconstraint(&Run::constraints, this,
                                     std::vector<double>(m, p_.feasibility_tol * 0.1));
    opt.set_maxeval(std::max(1, p_.gradient_based
                                    ? p_.max_evaluations / (2 * static_cast<int>(n) + 1)
                                    : p_.max_evaluations));
    opt.set_ftol_rel(p_.relative_tol);
    opt.set_xtol_rel(p_.relative_tol);
    if (!p_.gradient_based) {
      std::vector<double> step(n);
      for (unsigned i = 0; i < n; ++i) step[i] = 0.05 * (p_.upper[i] - p_.lower[i]);
      opt.set_initial_step(step);
    }
    double value = 0;
    try {
      opt.optimize(x, value);
    } catch (const std::runtime_error&) {
      // roundoff-limited or a failed line search: the best point seen is kept below.
    } catch (const std::invalid_argument&) {
    }
    if (cancelled_) throw *cancelled_;
    best_.evaluations = evaluations_;
    best_.runs = 1;
    return best_;
  }

 private:
  const DesignEvaluation& evaluate(const double* x) {
    const std::size_t n = p_.lower.size();
    if (have_cache_ && std::equal(x, x + n, cache_x_.begin())) return cache_;
    heartbeat_();
    cache_x_.assign(x, x + n);
    cache_ = p_.evaluate(std::span<const double>(x, n));
    ++evaluations_;
    have_cache_ = true;
    return cache_;
  }

  void record(const double* x, const DesignEvaluation& e) {
    const double v = max_violation(e);
    const bool ok = v <= p_.feasibility_tol && std::isfinite(e.objective);
    const bool better = ok ? (!best_.feasible || e.objective < best_.objective)
                           : (!best_.feasible && v < best_.violation);
    if (!better) return;
    best_.feasible = ok;
    best_.x.assign(x, x + p_.lower.size());
    best_.objective = e.objective;
    best_.violation = v;
    best_.binding.clear();
    if (!ok)
      for (std::size_t j = 0; j < e.constraints.size(); ++j)
        if (e.constraints[j] == v) best_.binding = p_.constraint_names[j];
  }

  // Evaluates at x (recorded) and, when asked, the central-difference gradients of J and g.
  void evaluate_with_gradients(const double* x, double* grad_j, double* grad_g) {
    const std::size_t n = p_.lower.size(), m = p_.constraint_names.size();
    const DesignEvaluation centre = evaluate(x);
    record(x, centre);
    if (grad_j == nullptr && grad_g == nullptr) return;
    if (have_grad_ && grad_x_ == cache_x_) {
      if (grad_j) std::copy(grad_objective_.begin(), grad_objective_.end(), grad_j);
      if (grad_g) std::copy(grad_constraints_.begin(), grad_constraints_.end(), grad_g);
      return;
    }
    grad_x_.assign(x, x + n);
    grad_objective_.assign(n, 0.0);
    grad_constraints_.assign(m * n, 0.0);
    double scale = 0;
    for (std::size_t i = 0; i < n; ++i) scale = std::max(scale, std::abs(x[i]));
    // The stencil x +- h_i e_i, evaluated together (evaluate_many) or in turn, recorded in order.
    std::vector<std::vector<double>> points(2 * n, std::vector<double>(x, x + n));
    std::vector<double> steps(n);
    for (std::size_t i = 0; i < n; ++i) {
      steps[i] = p_.fd_step * std::max({std::abs(x[i]), scale, 1e-12});
      points[2 * i][i] = x[i] + steps[i];
      points[2 * i + 1][i] = x[i] - steps[i];
    }
    std::vector<DesignEvaluation> values(2 * n);
    if (p_.evaluate_many) {
      p_.evaluate_many(points, values, heartbeat_);
      evaluations_ += static_cast<int>(2 * n);
    } else {
      for (std::size_t k = 0; k < 2 * n; ++k) values[k] = evaluate(points[k].data());
    }
    for (std::size_t i = 0; i < n; ++i) {
      const DesignEvaluation& plus = values[2 * i];
      const DesignEvaluation& minus = values[2 * i + 1];
      record(points[2 * i].data(), plus);
      record(points[2 * i + 1].data(), minus);
      grad_objective_[i] = (plus.objective - minus.objective) / (2 * steps[i]);
      for (std::size_t j = 0; j < m; ++j)
        grad_constraints_[j * n + i] = (plus.constraints[j] - minus.constraints[j]) / (2 * steps[i]);
    }
    cache_x_.assign(x, x + n);  // the cache holds the centre again (no re-evaluation)
    cache_ = centre;
    have_cache_ = true;
    have_grad_ = true;
    if (grad_j) std::copy(grad_objective_.begin(), grad_objective_.end(), grad_j);
    if (grad_g) std::copy(grad_constraints_.begin(), grad_constraints_.end(), grad_g);
  }

  // Inside NLopt's callbacks: keeps a cancellation and stops NLopt.
  template <class F>
  auto guarded(const F& f) -> decltype(f()) {
    try {
      return f();
    } catch (const SearchCancelled& c) {
      cancelled_ = c;
      throw nlopt::forced_stop();
    }
  }

  static double objective(unsigned n, const double* x, double* grad, void* data) {
    auto& self = *static_cast<Run*>(data);
    (void)n;
    return self.guarded([&] {
      self.evaluate_with_gradients(x, grad, nullptr);
      return self.evaluate(x).objective;
    });
  }

  static void constraints(unsigned m, double* result, unsigned n, const double* x, double* grad,
                          void* data) {
    auto& self = *static_cast<Run*>(data);
    (void)n;
    self.guarded([&] {
      self.evaluate_with_gradients(x, nullptr, grad);
      const DesignEvaluation& e = self.evaluate(x);
      for (unsigned j = 0; j < m; ++j) result[j] = e.constraints[j];
    });
  }

  const LocalSearchProblem& p_;
  const std::function<void()>& heartbeat_;
  std::optional<SearchCancelled> cancelled_;
  LocalSearchResult best_;
  int evaluations_ = 0;
  bool have_cache_ = false, have_grad_ = false;
  std::vector<double> cache_x_, grad_x_, grad_objective_, grad_constraints_;
  DesignEvaluation cache_;
};

}  // namespace

double trusted_v_bar(const SteadyState& state, double max_table_velocity, double period) {
  if (!state.converged || !std::isfinite(state.v_bar) ||
      std::abs(state.v_bar) > max_table_velocity + period)
    return std::numeric_limits<double>::quiet_NaN();
  return state.v_bar;
}

double design_objective(double v_bar, double period, double stroke) {
  if (!std::isfinite(v_bar)) return kBackwardPenalty * 2.0;
  if (v_bar > 0) {
    const double f = objective_f(v_bar);
    if (std::isfinite(f)) return f;
  }
  return kBackwardPenalty * (1.0 + std::abs(v_bar) * period / stroke);
}

std::string infeasible_message(const std::string& what, const LocalSearchResult& result) {
  return "no feasible " + what + ": " + result.binding + " is binding (least violation " +
         format_number(result.violation) + " relative)";
}

void merge_best(LocalSearchResult& a, const LocalSearchResult& b) {
  const int evaluations = a.evaluations + b.evaluations, runs = a.runs + b.runs;
  const bool b_better =
      a.x.empty() || (b.feasible && (!a.feasible || b.objective < a.objective)) ||
      (!b.feasible && !a.feasible && b.violation < a.violation);
  if (b_better && !b.x.empty()) a = b;
  a.evaluations = evaluations;
  a.runs = runs;
}

LocalSearchResult local_search(const LocalSearchProblem& problem,
                               const std::vector<std::vector<double>>& starts,
                               const std::function<void(int, int)>& progress) {
  LocalSearchResult best;
  const int total = static_cast<int>(starts.size());
  // progress(k, total) also while run k is under way, at most every kHeartbeatInterval and
  // from one thread at a time (the heartbeat comes from the stencils' workers too): one local
  // run can be long, and a front end cancels the search by throwing from progress.
  using Clock = std::chrono::steady_clock;
  int k = 0;
  std::mutex beat_mutex;
  auto last_report = Clock::now();  // under beat_mutex
  const std::function<void()> heartbeat = [&] {
    if (!progress) return;
    const std::unique_lock lock(beat_mutex, std::try_to_lock);
    if (!lock.owns_lock()) return;  // another thread is reporting
    const auto now = Clock::now();
    if (now - last_report < kHeartbeatInterval) return;
    last_report = now;
    try {
      progress(k, total);
    } catch (...) {
      throw SearchCancelled{std::current_exception()};
    }
  };
  try {
    for (; k < total; ++k) {
      LocalSearchResult run = Run(problem, heartbeat)(starts[static_cast<std::size_t>(k)]);
      for (int again = 0; again < problem.restarts && run.feasible; ++again) {
        const double before = run.objective;
        merge_best(run, Run(problem, heartbeat)(run.x));
        if (!(run.objective < before - problem.relative_tol * std::abs(before))) break;
      }
      merge_best(best, run);
      if (progress) progress(k + 1, total);
      last_report = Clock::now();
    }
  } catch (const SearchCancelled& c) {
    std::rethrow_exception(c.reason);
  }
  best.runs = total;  // starts (restarts of a start are part of its run)
  return best;
}

}  // namespace selfalign
