// identify(): multiple-shooting least squares of measured positions (docs/identification.md).
// Global stage NLopt MLSL-LDS, local stage Ceres Levenberg-Marquardt with the Schur complement
// over the window states, covariance from the Schur complement of J^T J, identifiability from
// its scaled spectrum, profile likelihood by refits with one parameter held.

#include "selfalign/identify/identification.hpp"

#include <ceres/ceres.h>
#include <nlopt.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <utility>

#include "selfalign/error.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/overloaded.hpp"
#include "shooting.hpp"
#include "window_cost.hpp"

namespace selfalign {
namespace {

using namespace identify_detail;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Rounds of re-shot window states after the local stage (see identify()).
constexpr int kPolishRounds = 4;
// Candidates of the global stage refined by the local stage (see Fit::global_stage).
constexpr std::size_t kLocalStarts = 4;
// Points of each pass of the offset scan (Fit::scan_offsets).
constexpr int kOffsetGrid = 41;

// Every value the fit estimates: the model parameters, one offset per run, a state per window.
struct Estimate {
  std::vector<double> theta;
  std::vector<double> tau;
  std::vector<double> states;  // 2 per window
};

void check_options(const IdentificationOptions& o) {
  if (!(o.window_periods > 0) || !std::isfinite(o.window_periods))
    throw InvalidParameter("window_periods", o.window_periods, "must be > 0 (table periods)");
  if (o.starts < 0) throw InvalidParameter("starts", o.starts, "must be >= 0 (0: no global stage)");
  if (o.global_evaluations < 1)
    throw InvalidParameter("global_evaluations", o.global_evaluations, "must be >= 1");
  if (o.max_iterations < 1)
    throw InvalidParameter("max_iterations", o.max_iterations, "must be >= 1");
  if (o.profile_points < 3)
    throw InvalidParameter("profile_points", o.profile_points, "must be >= 3");
  if (!(o.confidence > 0 && o.confidence < 1))
    throw InvalidParameter("confidence", o.confidence, "must be in (0, 1)");
  if (o.threads < 1) throw InvalidParameter("threads", o.threads, "must be >= 1");
  std::visit(Overloaded{[](const SquaredLoss&) {},
                        [](const auto& l) {
                          if (!(l.scale > 0) || !std::isfinite(l.scale))
                            throw InvalidParameter("loss scale", l.scale, "must be > 0 [m]");
                        }},
             o.loss);
}

class Fit {
 public:
  Fit(const std::vector<IdentificationRun>& runs, const IdentificationOptions& o) : o_(o) {
    check_options(o);
    if (runs.empty()) throw InvalidParameter("data", "none", "give at least one measured run");
    std::set<std::string> seen;
    for (const std::string& name : o.free) {
      if (!seen.insert(name).second)
        throw InvalidParameter("free", name, "is named twice");
      if (name == "t0" || name == "x0" || name == "v0")
        throw InvalidParameter("free", name,
                               "the initial state is estimated per shooting window: free only "
                               "model parameters and time_offset");
      if (name == kTimeOffset)
        offset_free_ = true;
      else
        names_.push_back(name);
    }
    if (names_.empty())
      throw InvalidParameter("free", o.free.empty() ? "none" : o.free.front(),
                             "name at least one model parameter (selfalign parameters lists them)");
    for (const IdentificationRun& r : runs) runs_.push_back(std::make_unique<ShootingRun>(r, names_));
    const std::size_t p = names_.size();
    start_.theta = runs_.front()->view().values();
    start_.tau.assign(runs_.size(), 0.0);
    // Windows, from each run's model at the starting values.
    for (std::size_t r = 0; r < runs_.size(); ++r) {
      const auto model = runs_[r]->model_or_throw(start_.theta);
      const double period = model->out.time(model->model.profile->period());
      periods_.push_back(period);
      const auto w = cut_windows(r, runs_[r]->data().t, o.window_periods * period);
      run_first_.push_back(windows_.size());
      windows_.insert(windows_.end(), w.begin(), w.end());
    }
    run_first_.push_back(windows_.size());
    std::size_t samples = 0;
    for (const auto& r : runs_) samples += r->data().t.size();
    estimated_ = p + (offset_free_ ? runs_.size() : 0) + 2 * windows_.size();
    samples_ = samples;
    if (samples <= estimated_) {
      const std::string name = runs_.size() == 1 ? runs_.front()->data().source + " samples"
                                                 : "samples";
      throw InvalidParameter(name, static_cast<double>(samples),
                             "must be > the " + std::to_string(estimated_) +
                                 " estimated parameters (" + std::to_string(p) + " free" +
                                 (offset_free_ ? " + " + std::to_string(runs_.size()) + " offsets" : "") +
                                 " + 2 per shooting window x " + std::to_string(windows_.size()) +
                                 "): give more data or longer windows (window_periods)");
    }
    // Bounds: given, or the config's value +-30 % (+-1 for a value 0).
    for (std::size_t j = 0; j < p; ++j) {
      const double v = start_.theta[j];
      IdentificationBounds b{v - kDefaultBoxWidth * std::abs(v), v + kDefaultBoxWidth * std::abs(v)};
      if (v == 0) b = {-1, 1};
      if (auto it = o.bounds.find(names_[j]); it != o.bounds.end()) b = it->second;
      if (!(b.lower < b.upper) || !(b.lower <= v && v <= b.upper))
        throw InvalidParameter("bounds " + names_[j],
                               format_number(b.lower) + ".." + format_number(b.upper),
                               "must be lower < upper and contain the config's value " +
                                   format_number(v));
      bounds_.push_back(b);
    }
    for (const auto& [name, b] : o.bounds)
      if (name != kTimeOffset && std::find(names_.begin(), names_.end(), name) == names_.end())
        throw InvalidParameter("bounds", name, "is not a free parameter");
    offset_bounds_ = {-periods_.front() / 2, periods_.front() / 2};
    if (auto it = o.bounds.find(kTimeOffset); it != o.bounds.end()) offset_bounds_ = it->second;
    // Step floors: the parameter's own scale, the period, the data's range and speed.
    for (std::size_t j = 0; j < p; ++j)
      floors_.push_back(start_.theta[j] != 0 ? std::abs(start_.theta[j])
                                             : 1e-3 * (bounds_[j].upper - bounds_[j].lower));
    floors_.push_back(periods_.front());
    double range = 0;
    for (const auto& r : runs_) {
      const auto [lo, hi] = std::minmax_element(r->data().x.begin(), r->data().x.end());
      range = std::max(range, *hi - *lo);
    }
    if (range == 0) range = 1e-3;
    floors_.push_back(range);
    floors_.push_back(range / periods_.front());
    start_.states.resize(2 * windows_.size());
    for (std::size_t k = 0; k < windows_.size(); ++k)
      estimate_window_state(runs_[windows_[k].run]->data(), windows_[k], &start_.states[2 * k]);
  }

  const std::vector<std::string>& names() const { return names_; }
  bool offset_free() const { return offset_free_; }
  const Estimate& start() const { return start_; }
  std::size_t samples() const { return samples_; }
  std::size_t estimated() const { return estimated_; }
  const std::vector<Window>& windows() const { return windows_; }
  const ShootingRun& run(std::size_t r) const { return *runs_[r]; }
  std::size_t run_count() const { return runs_.size(); }
  const std::vector<IdentificationBounds>& bounds() const { return bounds_; }
  const IdentificationBounds& offset_box() const { return offset_bounds_; }

  // Position-reset shooting over every run (reset_shooting): the window states consistent with
  // the model at e.theta, written into e.states; the RSS, NaN where the model fails.
  double reset_rss(Estimate& e) const {
    double s = 0;
    for (std::size_t r = 0; r < runs_.size(); ++r) {
      const auto model = runs_[r]->model(e.theta);
      if (!model) return kNaN;
      s += reset_shooting(*model, runs_[r]->data(), run_windows(r), e.tau[r],
                          &e.states[2 * run_first_[r]]);
    }
    return s;
  }

  // The offsets (when free), run by run, at e.theta: the reset-shooting RSS on a grid of
  // kOffsetGrid points over the offset box, then on a finer grid about the best. A clock
  // offset of a few per cent of the period misplaces every event of every window, and the
  // local stage started there can wander into another basin; the scan costs 2 kOffsetGrid
  // passes over the data. Leaves e.states re-shot at the result.
  void scan_offsets(Estimate& e) const {
    if (!offset_free_) {
      reset_rss(e);  // no offset to scan: the window states alone, re-shot at e.theta
      return;
    }
    for (std::size_t r = 0; r < runs_.size(); ++r) {
      const std::size_t k = run_first_[r];
      const auto model = runs_[r]->model(e.theta);
      if (!model) return;
      const auto windows = run_windows(r);
      double lo = offset_bounds_.lower, hi = offset_bounds_.upper, best = e.tau[r];
      for (int pass = 0; pass < 2; ++pass) {
        double best_rss = reset_shooting(*model, runs_[r]->data(), windows, best, &e.states[2 * k]);
        const double step = (hi - lo) / (kOffsetGrid - 1);
        for (int i = 0; i < kOffsetGrid; ++i) {
          const double tau = lo + step * i;
          const double rss = reset_shooting(*model, runs_[r]->data(), windows, tau, &e.states[2 * k]);
          if (rss < best_rss) best_rss = rss, best = tau;
        }
        lo = std::max(offset_bounds_.lower, best - step), hi = std::min(offset_bounds_.upper, best + step);
      }
      e.tau[r] = best;
    }
    reset_rss(e);
  }

  // Sum of squared residuals with the window states as given; NaN where the model fails.
  double rss(const Estimate& e) const {
    double s = 0;
    for (std::size_t k = 0; k < windows_.size(); ++k) {
      const Window& w = windows_[k];
      std::vector<double> r(w.end - w.first);
      const auto model = runs_[w.run]->model(e.theta);
      if (!model || !predict_window(*model, runs_[w.run]->data(), w, e.tau[w.run],
                                    &e.states[2 * k], r.data()))
        return kNaN;
      for (double v : r) s += v * v;
    }
    return s;
  }

  // Global stage: MLSL with low-discrepancy starts over the box of theta (and the offsets),
  // each point scored by position-reset shooting (reset_rss). Returns up to kLocalStarts
  // candidates, best first, pairwise at least 5 % of the box apart (the reset-shooting
  // objective's minima are near the full fit's but need not be in the same order), the best
  // RSS and the evaluations.
  struct GlobalResult {
    std::vector<Estimate> candidates;
    double best_rss;
    int evaluations;
  };
  GlobalResult global_stage(const Estimate& e) const {
    const std::size_t p = names_.size(), m = p + (offset_free_ ? runs_.size() : 0);
    std::vector<double> lo(m), hi(m), x(m);
    for (std::size_t j = 0; j < p; ++j) lo[j] = bounds_[j].lower, hi[j] = bounds_[j].upper, x[j] = e.theta[j];
    for (std::size_t j = p; j < m; ++j)
      lo[j] = offset_bounds_.lower, hi[j] = offset_bounds_.upper, x[j] = e.tau[j - p];
    struct Context {
      const Fit* fit;
      Estimate e;
      int evaluations = 0;
      std::vector<std::pair<double, std::vector<double>>> seen;  // (rss, point)
    } ctx{this, e, 0, {}};
    auto objective = [](unsigned n, const double* v, double*, void* data) {
      auto* c = static_cast<Context*>(data);
      const std::size_t pp = c->fit->names_.size();
      std::copy(v, v + pp, c->e.theta.begin());
      for (std::size_t j = pp; j < n; ++j) c->e.tau[j - pp] = v[j];
      ++c->evaluations;
      const double s = c->fit->reset_rss(c->e);
      if (std::isfinite(s)) c->seen.emplace_back(s, std::vector<double>(v, v + n));
      return std::isfinite(s) ? s : std::numeric_limits<double>::max();
    };
    nlopt::opt global(nlopt::GN_MLSL_LDS, static_cast<unsigned>(m));
    nlopt::opt local(nlopt::LN_BOBYQA, static_cast<unsigned>(m));
    local.set_xtol_rel(1e-4);
    global.set_local_optimizer(local);
    global.set_population(static_cast<unsigned>(o_.starts));
    global.set_lower_bounds(lo);
    global.set_upper_bounds(hi);
    global.set_maxeval(o_.global_evaluations);
    global.set_min_objective(objective, &ctx);
    double best = kNaN;
    try {
      global.optimize(x, best);
    } catch (const nlopt::roundoff_limited&) {
    } catch (const std::runtime_error&) {
    }
    std::sort(ctx.seen.begin(), ctx.seen.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    GlobalResult out{{}, ctx.seen.empty() ? kNaN : ctx.seen.front().first, ctx.evaluations};
    std::vector<std::vector<double>> chosen;
    for (const auto& [rss, point] : ctx.seen) {
      if (chosen.size() >= kLocalStarts) break;
      bool far = true;
      for (const auto& c : chosen) {
        double d = 0;
        for (std::size_t j = 0; j < m; ++j) d = std::max(d, std::abs(point[j] - c[j]) / (hi[j] - lo[j]));
        far = far && d > 0.05;
      }
      if (!far) continue;
      chosen.push_back(point);
      Estimate c = e;
      std::copy(point.begin(), point.begin() + static_cast<long>(p), c.theta.begin());
      for (std::size_t j = p; j < m; ++j) c.tau[j - p] = point[j];
      out.candidates.push_back(std::move(c));
    }
    (void)best;
    return out;
  }

  // Local stage: Levenberg-Marquardt from e (changed in place). `held`: a theta index kept at
  // its value (profile likelihood). Returns Ceres' summary.
  ceres::Solver::Summary local_stage(Estimate& e, int held = -1, bool hold_sticks = true) const {
    const std::size_t p = names_.size();
    std::unique_ptr<ceres::LossFunction> loss = std::visit(
        Overloaded{[](const SquaredLoss&) -> std::unique_ptr<ceres::LossFunction> { return nullptr; },
                   [](const HuberLoss& l) -> std::unique_ptr<ceres::LossFunction> {
                     return std::make_unique<ceres::HuberLoss>(l.scale);
                   },
                   [](const CauchyLoss& l) -> std::unique_ptr<ceres::LossFunction> {
                     return std::make_unique<ceres::CauchyLoss>(l.scale);
                   }},
        o_.loss);
    ceres::Problem::Options po;
    po.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    po.manifold_ownership = ceres::TAKE_OWNERSHIP;
    ceres::Problem problem(po);
    auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
    for (std::size_t k = 0; k < windows_.size(); ++k) {
      const Window& w = windows_[k];
      problem.AddResidualBlock(new WindowCost(*runs_[w.run], w, p, floors_, true), loss.get(),
                               {e.theta.data(), &e.tau[w.run], &e.states[2 * k]});
      ordering->AddElementToGroup(&e.states[2 * k], 0);
      // A window that starts in stick (its re-shot start velocity exactly 0) keeps v = 0: the
      // residuals have a kink in v there (any v != 0 slips, then sticks again), where
      // Levenberg-Marquardt would crawl; only its position is estimated.
      if (hold_sticks && e.states[2 * k + 1] == 0)
        problem.SetManifold(&e.states[2 * k], new ceres::SubsetManifold(2, {1}));
    }
    ordering->AddElementToGroup(e.theta.data(), 1);
    for (std::size_t r = 0; r < runs_.size(); ++r) {
      ordering->AddElementToGroup(&e.tau[r], 1);
      if (!offset_free_) {
        problem.SetParameterBlockConstant(&e.tau[r]);
      } else {
        problem.SetParameterLowerBound(&e.tau[r], 0, offset_bounds_.lower);
        problem.SetParameterUpperBound(&e.tau[r], 0, offset_bounds_.upper);
      }
    }
    for (std::size_t j = 0; j < p; ++j) {
      problem.SetParameterLowerBound(e.theta.data(), static_cast<int>(j), bounds_[j].lower);
      problem.SetParameterUpperBound(e.theta.data(), static_cast<int>(j), bounds_[j].upper);
    }
    if (held >= 0) {
      if (p == 1)
        problem.SetParameterBlockConstant(e.theta.data());
      else
        problem.SetManifold(e.theta.data(), new ceres::SubsetManifold(static_cast<int>(p), {held}));
    }
    ceres::Solver::Options so;
    so.linear_solver_type = ceres::DENSE_SCHUR;
    so.linear_solver_ordering = ordering;
    so.max_num_iterations = o_.max_iterations;
    so.num_threads = o_.threads;
    so.function_tolerance = 1e-12;
    so.parameter_tolerance = 1e-12;
    so.gradient_tolerance = 1e-14;
    so.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    return summary;
  }

  // The Jacobian's Schur complement S = sum_k G_k^T (I - P_k) G_k over the global columns G_k
  // (theta, then each run's free offset), P_k the projection onto the span of window k's state
  // columns X_k (the states eliminated). Throws nothing; a window whose model fails gives
  // zeros.
  Eigen::MatrixXd schur(const Estimate& e) const {
    const std::size_t p = names_.size(), R = offset_free_ ? runs_.size() : 0, g = p + R;
    Eigen::MatrixXd S = Eigen::MatrixXd::Zero(static_cast<long>(g), static_cast<long>(g));
    for (std::size_t k = 0; k < windows_.size(); ++k) {
      const Window& w = windows_[k];
      const long n = static_cast<long>(w.end - w.first);
      WindowCost cost(*runs_[w.run], w, p, floors_);
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Jt(n, static_cast<long>(p)),
          Jtau(n, 1), Jx(n, 2);
      Eigen::VectorXd r(n);
      const double* blocks[3] = {e.theta.data(), &e.tau[w.run], &e.states[2 * k]};
      double* jac[3] = {Jt.data(), Jtau.data(), Jx.data()};
      if (!cost.Evaluate(blocks, r.data(), jac)) continue;
      Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, static_cast<long>(g));
      G.leftCols(static_cast<long>(p)) = Jt;
      if (offset_free_) G.col(static_cast<long>(p + w.run)) = Jtau.col(0);
      // G's part orthogonal to the span of X (the state columns): S += G_perp^T G_perp, which
      // is positive semidefinite by construction (no normal-equation inverse to round).
      // Both state columns: the last local stage frees every start velocity.
      const Eigen::MatrixXd X = Jx;
      Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(X);
      const long rank = qr.rank();
      Eigen::MatrixXd QtG = qr.householderQ().transpose() * G;
      QtG.topRows(rank).setZero();
      S += QtG.transpose() * QtG;
    }
    return S;
  }

 private:
  // Run r's windows: cut run by run, so a contiguous span of windows_.
  std::span<const Window> run_windows(std::size_t r) const {
    return std::span<const Window>(windows_).subspan(run_first_[r], run_first_[r + 1] - run_first_[r]);
  }

  const IdentificationOptions& o_;
  std::vector<std::unique_ptr<ShootingRun>> runs_;
  std::vector<std::string> names_;
  bool offset_free_ = false;
  Estimate start_;
  std::vector<double> periods_;
  std::vector<Window> windows_;
  std::vector<std::size_t> run_first_;  // run r's windows are [run_first_[r], run_first_[r+1])
  std::vector<IdentificationBounds> bounds_;
  IdentificationBounds offset_bounds_{0, 0};
  std::vector<double> floors_;
  std::size_t samples_ = 0, estimated_ = 0;
};

// Indices (into the global columns) that are not identifiable: a zero column, then, while
// the scaled matrix's smallest eigenvalue is below tol^2 of its largest, the index carrying
// most of that eigenvector.
std::vector<bool> unidentifiable(const Eigen::MatrixXd& S) {
  const long g = S.rows();
  std::vector<bool> out(static_cast<std::size_t>(g), false);
  double largest = 0;
  for (long j = 0; j < g; ++j) largest = std::max(largest, S(j, j));
  for (long j = 0; j < g; ++j)
    if (!(S(j, j) > 1e-24 * largest)) out[static_cast<std::size_t>(j)] = true;
  for (;;) {
    std::vector<long> keep;
    for (long j = 0; j < g; ++j)
      if (!out[static_cast<std::size_t>(j)]) keep.push_back(j);
    if (keep.empty()) return out;
    const long m = static_cast<long>(keep.size());
    Eigen::MatrixXd C(m, m);
    for (long a = 0; a < m; ++a)
      for (long b = 0; b < m; ++b)
        C(a, b) = S(keep[a], keep[b]) / std::sqrt(S(keep[a], keep[a]) * S(keep[b], keep[b]));
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(C);
    const double lmin = eig.eigenvalues()(0), lmax = eig.eigenvalues()(m - 1);
    if (lmin > kIdentifiabilityTolerance * kIdentifiabilityTolerance * lmax) return out;
    long worst = 0;
    eig.eigenvectors().col(0).cwiseAbs().maxCoeff(&worst);
    out[static_cast<std::size_t>(keep[worst])] = true;
  }
}

// Why a parameter is not identifiable, from the fitted motion where the data show it.
std::string reason_for(const std::string& name, const std::vector<FittedRun>& runs,
                       const Fit& fit, const Estimate& e, bool loose) {
  bool sticks = false;
  for (const FittedRun& r : runs)
    for (unsigned char s : r.stick) sticks = sticks || s;
  if ((name == "mu_static") && !sticks)
    return "the part never sticks in the fitted motion, so the static coefficient is never "
           "seen";
  if (name == "c_mu" || name == "x_mu" || name == "width") {
    bool reaches = false;
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const auto model = fit.run(r).model(e.theta);
      if (!model) continue;
      const FrictionMap& f = *model->model.friction;
      double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin;
      for (double x : runs[r].x_fitted) xmin = std::min(xmin, x), xmax = std::max(xmax, x);
      const double lo = model->in(Dimension::length, xmin), hi = model->in(Dimension::length, xmax);
      const double b0 = f.bound(lo);
      for (int i = 1; i <= 64 && !reaches; ++i) reaches = f.bound(lo + (hi - lo) * i / 64) != b0;
    }
    if (!reaches)
      return "the part never reaches the region where the friction changes, so " + name +
             " is never seen";
  }
  if (loose)
    return "the data constrain it less than its box (its standard error is wider than the "
           "box)";
  return "the positions do not depend on it independently of the other free parameters "
         "(the Jacobian's scaled singular value is below 1e-6)";
}

}  // namespace

Identification identify(const std::vector<IdentificationRun>& runs,
                        const IdentificationOptions& options) {
  const Fit fit(runs, options);
  const std::size_t p = fit.names().size();
  Identification out;
  Estimate e = fit.start();
  out.global_best_rss = kNaN;
  std::vector<Estimate> candidates{e};
  if (options.starts > 0) {
    Fit::GlobalResult g = fit.global_stage(e);
    out.global_best_rss = g.best_rss;
    out.global_evaluations = g.evaluations;
    // The start itself stays a candidate: the global stage adds basins, never loses one.
    candidates.insert(candidates.end(), g.candidates.begin(), g.candidates.end());
  }
  // Local stage from each candidate, then polish: the window states re-shot from the model at
  // the estimate (reset_rss) and the fit repeated while that lowers the RSS by more than 1e-6
  // of it (a window state can settle on the wrong side of a stick/slip event, a local minimum
  // of its own; the re-shot states are consistent with the fitted model). The lowest RSS wins.
  Estimate initial;
  ceres::Solver::Summary summary;
  double best_rss = kNaN;
  for (Estimate& c : candidates) {
    fit.scan_offsets(c);  // the offsets at the candidate, window states consistent with it
    const Estimate from = c;
    ceres::Solver::Summary sc = fit.local_stage(c);
    double rss_c = fit.rss(c);
    for (int round = 0; round < kPolishRounds; ++round) {
      Estimate trial = c;
      fit.reset_rss(trial);
      const ceres::Solver::Summary s = fit.local_stage(trial);
        const double trial_rss = fit.rss(trial);
      if (!(trial_rss < rss_c * (1 - 1e-6))) break;
      c = std::move(trial), rss_c = trial_rss, sc = s;
    }
    // Last, every start velocity free (a held window may in truth start slipping slowly).
    {
      Estimate trial = c;
      const ceres::Solver::Summary s = fit.local_stage(trial, -1, false);
      const double trial_rss = fit.rss(trial);
      if (trial_rss <= rss_c) c = std::move(trial), rss_c = trial_rss, sc = s;
    }
    if (!(rss_c >= best_rss)) e = c, best_rss = rss_c, summary = sc, initial = from;
  }
  out.iterations = static_cast<int>(summary.iterations.size()) - 1;
  out.converged = summary.termination_type == ceres::CONVERGENCE;
  out.termination = summary.message;
  if (!out.converged)
    out.warnings.push_back("the local stage did not converge: " + summary.message);

  // Residuals and fitted runs.
  out.samples = fit.samples();
  out.windows = fit.windows().size();
  out.estimated = fit.estimated();
  for (std::size_t r = 0; r < fit.run_count(); ++r) {
    FittedRun fr;
    fr.source = fit.run(r).data().source;
    fr.skipped = fit.run(r).data().skipped;
    fr.t = fit.run(r).data().t;
    fr.x_measured = fit.run(r).data().x;
    const std::size_t n = fr.t.size();
    fr.x_fitted.assign(n, kNaN), fr.residual.assign(n, kNaN), fr.window.assign(n, -1);
    fr.stick.assign(n, 0);
    fr.time_offset = e.tau[r];
    fr.time_offset_standard_error = kNaN;
    out.runs.push_back(std::move(fr));
  }
  std::vector<int> per_run(fit.run_count(), 0);
  const auto model_at = [&](std::size_t r) { return fit.run(r).model(e.theta); };
  for (std::size_t k = 0; k < fit.windows().size(); ++k) {
    const Window& w = fit.windows()[k];
    FittedRun& fr = out.runs[w.run];
    const auto model = model_at(w.run);
    if (model)
      predict_window(*model, fit.run(w.run).data(), w, e.tau[w.run], &e.states[2 * k],
                     &fr.residual[w.first], &fr.stick[w.first], &fr.x_fitted[w.first]);
    for (std::size_t i = w.first; i < w.end; ++i) fr.window[i] = per_run[w.run];
    ++per_run[w.run];
  }
  for (FittedRun& fr : out.runs) {
    double s = 0;
    for (double v : fr.residual) {
      s += v * v;
      out.max_abs_residual = std::max(out.max_abs_residual, std::abs(v));
    }
    out.rss += s;
    fr.rms = std::sqrt(s / static_cast<double>(fr.residual.size()));
  }
  const double dof = static_cast<double>(out.samples - out.estimated);
  out.sigma = std::sqrt(out.rss / dof);
  out.z = boost::math::quantile(boost::math::normal(), 0.5 + options.confidence / 2);

  // Covariance: sigma^2 S^-1 over the identifiable global columns.
  const Eigen::MatrixXd S = fit.schur(e);
  // A parameter is also not identifiable when the data constrain it less than its box does
  // (standard error wider than the box): a column that is small but not collinear.
  std::vector<bool> lost = unidentifiable(S);
  std::vector<double> box;
  for (const IdentificationBounds& b : fit.bounds()) box.push_back(b.upper - b.lower);
  for (std::size_t r = 0; r < (fit.offset_free() ? fit.run_count() : 0); ++r)
    box.push_back(fit.offset_box().upper - fit.offset_box().lower);
  const long g = S.rows();
  Eigen::MatrixXd cov;
  std::vector<bool> loose(static_cast<std::size_t>(g), false);
  for (bool again = true; again;) {
    std::vector<long> keep;
    for (long j = 0; j < g; ++j)
      if (!lost[static_cast<std::size_t>(j)]) keep.push_back(j);
    cov = Eigen::MatrixXd::Constant(g, g, kNaN);
    if (!keep.empty()) {
      const long m = static_cast<long>(keep.size());
      Eigen::MatrixXd Sk(m, m);
      for (long a = 0; a < m; ++a)
        for (long b = 0; b < m; ++b) Sk(a, b) = S(keep[a], keep[b]);
      const Eigen::MatrixXd inv = Sk.ldlt().solve(Eigen::MatrixXd::Identity(m, m));
      for (long a = 0; a < m; ++a)
        for (long b = 0; b < m; ++b) cov(keep[a], keep[b]) = out.sigma * out.sigma * inv(a, b);
    }
    again = false;
    long worst = -1;
    double worst_ratio = 1;
    for (long j : keep) {
      const double ratio = std::sqrt(cov(j, j)) / box[static_cast<std::size_t>(j)];
      if (!(ratio <= worst_ratio)) worst = j, worst_ratio = std::isfinite(ratio) ? ratio : 1e300;
    }
    if (worst >= 0) {
      lost[static_cast<std::size_t>(worst)] = loose[static_cast<std::size_t>(worst)] = true;
      again = true;
    }
  }
  out.covariance.assign(p * p, kNaN);
  out.correlation.assign(p * p, kNaN);
  for (std::size_t a = 0; a < p; ++a)
    for (std::size_t b = 0; b < p; ++b) {
      const long la = static_cast<long>(a), lb = static_cast<long>(b);
      out.covariance[a * p + b] = cov(la, lb);
      out.correlation[a * p + b] = cov(la, lb) / std::sqrt(cov(la, la) * cov(lb, lb));
    }
  if (fit.offset_free())
    for (std::size_t r = 0; r < fit.run_count(); ++r) {
      const long j = static_cast<long>(p + r);
      out.runs[r].time_offset_standard_error = std::sqrt(cov(j, j));
    }
  for (std::size_t j = 0; j < p; ++j) {
    IdentifiedParameter ip;
    ip.name = fit.names()[j];
    ip.initial = initial.theta[j];
    ip.identifiable = !lost[j];
    ip.profile_lower = ip.profile_upper = kNaN;
    if (ip.identifiable) {
      ip.estimate = e.theta[j];
      ip.standard_error = std::sqrt(cov(static_cast<long>(j), static_cast<long>(j)));
      ip.lower = ip.estimate - out.z * ip.standard_error;
      ip.upper = ip.estimate + out.z * ip.standard_error;
      const IdentificationBounds& b = fit.bounds()[j];
      const double edge = 1e-9 * (b.upper - b.lower);
      if (ip.estimate - b.lower < edge || b.upper - ip.estimate < edge)
        out.warnings.push_back(ip.name + " ended at a bound of its box [" + format_number(b.lower) +
                               ", " + format_number(b.upper) +
                               "]: widen it (bounds) if the value is plausible");
    } else {
      ip.estimate = ip.standard_error = ip.lower = ip.upper = kNaN;
      ip.reason = reason_for(ip.name, out.runs, fit, e, loose[j]);
      out.warnings.push_back(ip.name + " is not identifiable from these data: " + ip.reason);
    }
    out.parameters.push_back(std::move(ip));
  }
  for (std::size_t a = 0; a < p; ++a)
    for (std::size_t b = a + 1; b < p; ++b)
      if (std::abs(out.correlation[a * p + b]) > 0.99)
        out.warnings.push_back(fit.names()[a] + " and " + fit.names()[b] + " are correlated (" +
                               format_number(out.correlation[a * p + b]) +
                               "): the data determine their combination better than each");

  // Profile likelihood: refits with one parameter held on a grid of +-2 z se.
  const double chi2 = boost::math::quantile(boost::math::chi_squared(1), options.confidence);
  for (const std::string& name : options.profile) {
    const auto it = std::find(fit.names().begin(), fit.names().end(), name);
    if (it == fit.names().end())
      throw InvalidParameter("profile", name, "is not a free parameter");
    const std::size_t j = static_cast<std::size_t>(it - fit.names().begin());
    IdentifiedParameter& ip = out.parameters[j];
    if (!ip.identifiable) continue;
    ProfileLikelihood pl;
    pl.name = name;
    const int K = options.profile_points;
    for (int i = 0; i < K; ++i) {
      const double u = -1.0 + 2.0 * i / (K - 1);
      const double v = ip.estimate + 2 * out.z * ip.standard_error * u;
      pl.values.push_back(v);
      const IdentificationBounds& b = fit.bounds()[j];
      if (v < b.lower || v > b.upper) {
        pl.rss.push_back(kNaN);
        continue;
      }
      Estimate h = e;
      h.theta[j] = v;
      if (i == (K - 1) / 2 && K % 2 == 1) {
        pl.rss.push_back(out.rss);
        continue;
      }
      if (!std::isfinite(fit.rss(h))) {
        pl.rss.push_back(kNaN);
        continue;
      }
      fit.local_stage(h, static_cast<int>(j));
      pl.rss.push_back(fit.rss(h));
    }
    // The interval: where the profile crosses rss + chi2 sigma^2, interpolated.
    const double level = out.rss + chi2 * out.sigma * out.sigma;
    const int c = (K - 1) / 2;
    auto crossing = [&](int step) {
      for (int i = c; i + step >= 0 && i + step < K; i += step) {
        const double a = pl.rss[static_cast<std::size_t>(i)], b = pl.rss[static_cast<std::size_t>(i + step)];
        if (!std::isfinite(a) || !std::isfinite(b)) return kNaN;
        if (b >= level) {
          const double va = pl.values[static_cast<std::size_t>(i)], vb = pl.values[static_cast<std::size_t>(i + step)];
          return a >= level ? va : va + (vb - va) * (level - a) / (b - a);
        }
      }
      return kNaN;
    };
    ip.profile_lower = crossing(-1);
    ip.profile_upper = crossing(+1);
    out.profiles.push_back(std::move(pl));
  }
  return out;
}

}  // namespace selfalign
