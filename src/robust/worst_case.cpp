#include "selfalign/robust/worst_case.hpp"
#include "selfalign/special_values.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include <nlopt.hpp>

#include "../analysis/parallel_cells.hpp"
#include "selfalign/error.hpp"

namespace selfalign {
namespace {

// The objective gives a run that does not stop this error [m], far beyond any real one, so the
// local search treats "never stops" as the worst outcome yet stays finite for NLopt.
constexpr double kNotStoppedError = 1e6;

// The k-th point of the Halton sequence in base b (radical inverse), k >= 1.
double halton(std::uint64_t k, std::uint64_t base) {
  double f = 1, r = 0;
  for (; k > 0; k /= base) f /= static_cast<double>(base), r += f * static_cast<double>(k % base);
  return r;
}

struct Point {
  explicit Point(const InputValues& values) : v(values) {}
  InputValues v{};
  ProcessOutcome out;
  double error = 0;  // kNotStoppedError when not stopped
};

}  // namespace

WorstCase worst_case(const DesignRequest& q, const Process& p, const ProcessUncertainty& u,
                     const WorstCaseOptions& o) {
  validate(q);
  validate(p);
  validate(u);
  validate_draws(q, p, u);
  if (!(o.sigmas > 0 && o.sigmas <= 8)) throw InvalidParameter("sigmas", o.sigmas, "must be in (0, 8]");
  if (o.interior_points < 0 || o.interior_points > 100'000)
    throw InvalidParameter("interior_points", o.interior_points, "must be in [0, 1e5]");
  if (o.starts < 0 || o.starts > 100) throw InvalidParameter("starts", o.starts, "must be in [0, 100]");
  if (o.local_evaluations < 0 || o.local_evaluations > 100'000)
    throw InvalidParameter("local_evaluations", o.local_evaluations, "must be in [0, 1e5]");
  if (!(q.tolerance > 0))
    throw InvalidParameter("tolerance", q.tolerance, "must be > 0 [m]");

  const auto& inputs = uncertain_inputs();
  const InputValues nominal = nominal_inputs(q, u);
  WorstCase w;
  std::vector<std::size_t> active;
  for (std::size_t k = 0; k < kUncertainInputs; ++k) {
    w.box.push_back(box(u.*inputs[k].member, nominal[k], o.sigmas));
    if (w.box[k].first < w.box[k].second) active.push_back(k);
  }
  if (active.empty())
    throw InvalidParameter("uncertainty", "none", "must make at least one input uncertain");
  const std::size_t dim = active.size();
  // The unit cube's point z -> the inputs.
  const auto inputs_at = [&](const std::vector<double>& z) {
    InputValues v = nominal;
    for (std::size_t i = 0; i < dim; ++i) {
      const auto [lo, hi] = w.box[active[i]];
      v[active[i]] = lo + std::clamp(z[i], 0.0, 1.0) * (hi - lo);
    }
    return v;
  };
  const ProcessFamily family(q, p);
  const auto evaluate = [&](Point& pt) {
    pt.out = run_process(family, pt.v, o.max_periods);
    pt.error = pt.out.kind == StopKind::not_stopped ? kNotStoppedError
                                                     : std::abs(pt.out.end_position - q.distance);
  };

  // 1. Corners and Halton interior points, in parallel (each into its own slot).
  std::vector<Point> points;
  const std::size_t corners = std::size_t{1} << dim;
  for (std::size_t c = 0; c < corners; ++c) {
    std::vector<double> z(dim);
    for (std::size_t i = 0; i < dim; ++i) z[i] = (c >> i) & 1;
    points.emplace_back(inputs_at(z));
  }
  constexpr std::uint64_t kPrimes[] = {2, 3, 5, 7, 11, 13, 17};
  for (int k = 1; k <= o.interior_points; ++k) {
    std::vector<double> z(dim);
    for (std::size_t i = 0; i < dim; ++i) z[i] = halton(static_cast<std::uint64_t>(k), kPrimes[i]);
    points.emplace_back(inputs_at(z));
  }
  SweepOptions sweep;
  sweep.threads = o.threads;
  detail::parallel_cells(points.size(), sweep, [&](std::size_t i) { evaluate(points[i]); });

  // 2. Nelder-Mead (NLopt, bounded) maximising the error from the worst distinct points.
  std::vector<std::size_t> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return points[a].error > points[b].error; });
  int local = 0;
  const bool searching = o.starts > 0 && o.local_evaluations > 0;
  for (int s = 0; searching && s < std::min<int>(o.starts, static_cast<int>(order.size())); ++s) {
    const Point& from = points[order[static_cast<std::size_t>(s)]];
    if (from.error >= kNotStoppedError) continue;  // already the worst possible outcome
    std::vector<double> z(dim);
    for (std::size_t i = 0; i < dim; ++i) {
      const auto [lo, hi] = w.box[active[i]];
      z[i] = (from.v[active[i]] - lo) / (hi - lo);
    }
    nlopt::opt opt(nlopt::LN_NELDERMEAD, static_cast<unsigned>(dim));
    opt.set_lower_bounds(std::vector<double>(dim, 0.0));
    opt.set_upper_bounds(std::vector<double>(dim, 1.0));
    opt.set_maxeval(o.local_evaluations);
    opt.set_initial_step(0.1);
    opt.set_xtol_rel(1e-6);
    std::function<double(const std::vector<double>&)> objective =
        [&](const std::vector<double>& x) {
          Point pt{inputs_at(x)};
          evaluate(pt);
          points.push_back(pt);
          ++local;
          return pt.error;
        };
    opt.set_max_objective(
        [](const std::vector<double>& x, std::vector<double>&, void* data) {
          return (*static_cast<std::function<double(const std::vector<double>&)>*>(data))(x);
        },
        &objective);
    double best = 0;
    try {
      opt.optimize(z, best);
    } catch (const std::exception&) {
      // NLopt's roundoff-limited / forced stops keep the points evaluated so far.
    }
  }

  // 3. The worst and the slowest of every point evaluated.
  w.evaluations = static_cast<int>(points.size());
  w.method = std::to_string(corners) + " corners of the " + std::to_string(dim) +
             "-dimensional box, " + std::to_string(o.interior_points) +
             " Halton interior points" +
             (local > 0 ? ", NLopt bounded Nelder-Mead from the " + std::to_string(o.starts) +
                              " worst (" + std::to_string(local) + " runs)"
                        : "");
  const Point* worst = &points.front();
  const Point* slowest = &points.front();
  const auto time_of = [](const Point& pt) {
    return std::isnan(pt.out.process_time) ? kInf : pt.out.process_time;
  };
  w.all_within = true;
  for (const Point& pt : points) {
    if (pt.error > worst->error) worst = &pt;
    if (time_of(pt) > time_of(*slowest)) slowest = &pt;
    w.all_within = w.all_within && pt.error <= q.tolerance;
  }
  w.worst_inputs = worst->v;
  w.worst = worst->out;
  w.worst_error = worst->error >= kNotStoppedError ? kInf : worst->error;
  w.slowest_inputs = slowest->v;
  w.slowest_time = time_of(*slowest);
  return w;
}

}  // namespace selfalign
