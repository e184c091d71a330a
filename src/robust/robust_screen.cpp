#include "robust_screen.hpp"
#include "selfalign/special_values.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>

#include "../analysis/parallel_cells.hpp"
#include "selfalign/robust/process_walk.hpp"

namespace selfalign::detail {
namespace {

// Candidates screened per parallel batch (the order is fixed, so is the result).
constexpr std::size_t kBatch = 64;
// The trial lattice: steps of tolerance / 4, at most 2 x 16 + 1 trials (wider steps then).
constexpr double kTrialsPerTolerance = 4;
constexpr int kMaxHalfTrials = 16;
// After this many draws the placement drops the trials that can no longer be the best.
constexpr int kTrialCheck = 10;
// A rung defers the candidates whose nominal T_p exceeds the T_p quantile of the 8th fastest
// that qualifies (a quantile >= 0.5 of T_p is not below the nominal run's: they cannot be among
// the fastest 8). Fixed, not `finalists`: the screen does not depend on it.
constexpr std::size_t kDeferRank = 8;

// One trial x_mu of a candidate and its outcomes so far.
struct Trial {
  explicit Trial(double x, int k = 0) : x_mu(x), lattice(k) {}
  double x_mu = 0;  // [m]
  int lattice = 0;  // its place in the lattice, 0 at the centre
  bool alive = true;
  int within = 0;
  std::vector<float> time;  // T_p per draw [s]; +inf when the run did not stop
  FailureCounts failures;
};

struct State {
  std::vector<Trial> trials;
  int draws = 0;
  Screened seen;  // at the last rung
};

// The window of width 2 tol over the sorted values z holding the most of them: its count and
// centre (the midpoint of the extreme values inside; the first such window on ties).
double best_window_centre(std::vector<double> z, double tol) {
  std::sort(z.begin(), z.end());
  std::size_t best = 0;
  double centre = z.front();
  for (std::size_t lo = 0, hi = 0; lo < z.size(); ++lo) {
    hi = std::max(hi, lo);
    while (hi + 1 < z.size() && z[hi + 1] - z[lo] <= 2 * tol) ++hi;
    if (hi - lo + 1 > best) best = hi - lo + 1, centre = 0.5 * (z[lo] + z[hi]);
  }
  return centre;
}

class Screen {
 public:
  Screen(const DesignRequest& q, const std::vector<ScreenCandidate>& c,
         const std::vector<InputValues>& d, const RobustOptions& o)
      : q_(q), cands_(c), draws_(d), o_(o), states_(c.size()) {}

  ScreenResult run();

 private:
  void record(Trial& t, const ProcessOutcome& out) const {
    const bool stopped = out.kind != StopKind::not_stopped;
    t.time.push_back(stopped ? static_cast<float>(out.process_time) : static_cast<float>(kInf));
    t.within += stopped && std::abs(out.end_position - q_.distance) <= q_.tolerance;
    t.failures.add(out.kind, out.entry_time, out.end_position, q_.distance, q_.tolerance);
  }
  void place(std::size_t i);
  void extend(std::size_t i, int to);
  void summarize(std::size_t i, int n);

  const DesignRequest& q_;
  const std::vector<ScreenCandidate>& cands_;
  const std::vector<InputValues>& draws_;
  const RobustOptions& o_;
  std::vector<State> states_;
};

// The trials of candidate i from its first min(25, n) draws: the rigid shift of their end
// positions (exact for accumulation, whose end is x_stick,min = x_mu + a constant, eq. 41) puts
// the most within the tolerance at x^; a permanent stick ends at the first rest beyond
// x_stick,min, which moves by up to a walking step with x_mu, so the lattice spans
// x^ +- (step + tolerance).
void Screen::place(std::size_t i) {
  const ScreenCandidate& c = cands_[i];
  State& s = states_[i];
  const int n0 = std::min<int>(kFirstRung, static_cast<int>(draws_.size()));
  const double x0 = c.process.x_mu;
  std::vector<std::unique_ptr<ProcessWalk>> walks;
  std::vector<double> z;
  bool rigid = true;  // no permanent stick: every end is x_stick,min = x_mu + a constant
  for (int j = 0; j < n0; ++j) {
    walks.push_back(std::make_unique<ProcessWalk>(q_, c.process, draws_[j], c.budget));
    const ProcessOutcome out = walks.back()->at(x0);
    if (out.kind != StopKind::not_stopped) z.push_back(out.end_position - x0);
    rigid = rigid && out.kind != StopKind::permanent_stick;
  }
  if (z.empty()) {
    s.trials.emplace_back(x0);
  } else {
    const double centre = q_.distance - best_window_centre(z, q_.tolerance);
    const double half = (rigid ? 0 : c.nominal_step) + q_.tolerance / (rigid ? 2 : 1);
    const int m = std::clamp(static_cast<int>(std::ceil(half * kTrialsPerTolerance / q_.tolerance)),
                             1, kMaxHalfTrials);
    for (int k = -m; k <= m; ++k) {
      const double x = centre + half * k / m;
      if (x > 0) s.trials.emplace_back(x, k);
    }
    if (s.trials.empty()) s.trials.emplace_back(x0);
  }
  // The trials on the first draws, then (from kTrialCheck on) only those that can still be
  // the best.
  for (int j = 0; j < n0; ++j) {
    if (j == kTrialCheck) summarize(i, j);
    for (Trial& t : s.trials)
      if (t.alive) record(t, walks[static_cast<std::size_t>(j)]->at(t.x_mu));
  }
  s.draws = n0;
}

void Screen::extend(std::size_t i, int to) {
  State& s = states_[i];
  if (s.draws == 0) place(i);
  for (int j = s.draws; j < to; ++j) {
    ProcessWalk walk(q_, cands_[i].process, draws_[static_cast<std::size_t>(j)], cands_[i].budget);
    for (Trial& t : s.trials)
      if (t.alive) record(t, walk.at(t.x_mu));
  }
  s.draws = std::max(s.draws, to);
}

// The best trial on the first n draws (most within, then the lowest T_p quantile, then the
// nearest the lattice's centre); trials that can no longer be the best (their Wilson upper
// bound below its lower bound) are dropped.
void Screen::summarize(std::size_t i, int n) {
  State& s = states_[i];
  const Trial* best = nullptr;
  double best_time = kInf;
  for (const Trial& t : s.trials) {
    if (!t.alive) continue;
    const std::vector<double> times(t.time.begin(), t.time.begin() + n);
    const double time = empirical_quantile(times, o_.time_quantile, static_cast<std::size_t>(n));
    const bool better = !best || t.within > best->within ||
                        (t.within == best->within &&
                         (time < best_time ||
                          (time == best_time && std::abs(t.lattice) < std::abs(best->lattice))));
    if (better) best = &t, best_time = time;
  }
  s.seen = {i, best->x_mu, n, best->within, static_cast<double>(best->within) / n, best_time,
            best->failures};
  const double floor = wilson_interval(best->within, n).first;
  for (Trial& t : s.trials)
    if (t.alive && wilson_interval(t.within, n).second < floor) {
      t.alive = false;
      std::vector<float>().swap(t.time);
    }
}

// The lowest P(within) whose selection (verification_runs runs) can pass: the smallest k/n
// whose 95% Wilson lower bound reaches the target (1 when even n/n does not).
double selection_bar(double target, int n) {
  int lo = 0, hi = n;  // wilson lower bound (k, n) rises with k
  if (wilson_interval(n, n).first < target) return 1;
  while (hi - lo > 1) {
    const int mid = lo + (hi - lo) / 2;
    (wilson_interval(mid, n).first >= target ? hi : lo) = mid;
  }
  return static_cast<double>(hi) / n;
}

ScreenResult Screen::run() {
  ScreenResult out;
  out.rungs = screen_rungs(static_cast<int>(draws_.size()));
  const double bar = selection_bar(o_.probability_target, o_.verification_runs);
  const auto qualifies = [&](std::size_t i) { return states_[i].seen.p_within >= bar; };
  SweepOptions sweep;
  sweep.threads = o_.threads;
  std::vector<std::size_t> queue(cands_.size());
  for (std::size_t i = 0; i < queue.size(); ++i) queue[i] = i;
  std::vector<bool> seen(cands_.size(), false);
  std::size_t done = 0;
  for (std::size_t r = 0; r < out.rungs.size() && !queue.empty(); ++r) {
    const int n = out.rungs[r];
    // T*: the kDeferRank-th lowest T_p quantile among those that qualify so far.
    std::vector<double> qualified;
    double t_star = kInf;
    std::vector<std::size_t> screened, deferred;
    for (std::size_t b = 0; b < queue.size(); b += kBatch) {
      std::vector<std::size_t> batch;
      for (std::size_t k = b; k < std::min(queue.size(), b + kBatch); ++k)
        (cands_[queue[k]].nominal_time <= t_star ? batch : deferred).push_back(queue[k]);
      if (batch.empty()) continue;
      std::vector<bool> failed(batch.size(), false);
      parallel_cells(
          batch.size(), sweep,
          [&](std::size_t k) {
            extend(batch[k], n);
            summarize(batch[k], n);
          },
          [&](std::size_t k, const std::string&) { failed[k] = true; });
      for (std::size_t k = 0; k < batch.size(); ++k) {
        if (failed[k]) continue;  // a candidate the runs cannot resolve is not a design
        seen[batch[k]] = true;
        screened.push_back(batch[k]);
        if (qualifies(batch[k])) qualified.push_back(states_[batch[k]].seen.time);
      }
      std::sort(qualified.begin(), qualified.end());
      if (qualified.size() >= kDeferRank) t_star = qualified[kDeferRank - 1];
      done += batch.size();
      if (o_.progress) o_.progress(done, done + queue.size() - std::min(queue.size(), b + kBatch));
    }
    // This rung's finalists: the fastest that qualify, and the most probable (fastest first).
    const auto& st = states_;
    std::vector<std::size_t> fastest, surest = screened;
    std::copy_if(screened.begin(), screened.end(), std::back_inserter(fastest), qualifies);
    std::stable_sort(fastest.begin(), fastest.end(), [&](std::size_t a, std::size_t b) {
      return st[a].seen.time < st[b].seen.time;
    });
    std::stable_sort(surest.begin(), surest.end(), [&](std::size_t a, std::size_t b) {
      const Screened &x = st[a].seen, &y = st[b].seen;
      return x.within > y.within || (x.within == y.within && x.time < y.time);
    });
    const auto k = static_cast<std::size_t>(o_.finalists);
    for (const auto* list : {&fastest, &surest})
      for (std::size_t j = 0; j < std::min(k, list->size()); ++j) {
        const Screened& s = st[(*list)[j]].seen;
        const bool known = std::any_of(out.finalists.begin(), out.finalists.end(), [&](const Screened& f) {
          return f.candidate == s.candidate && f.x_mu == s.x_mu;
        });
        if (!known && s.within > 0) out.finalists.push_back(s);
      }
    out.any_qualifies = !fastest.empty();
    if (r + 1 == out.rungs.size()) break;
    // On to the next rung: the deferred, and those screened that can still reach the bar; when
    // none can, the better half of those that can still be the best (upper bound above the
    // best lower bound), at least kDeferRank.
    std::vector<std::size_t> next = deferred, keep;
    for (std::size_t i : screened)
      if (wilson_interval(st[i].seen.within, n).second >= bar) keep.push_back(i);
    if (keep.empty()) {
      double floor = 0;
      for (std::size_t i : screened) floor = std::max(floor, wilson_interval(st[i].seen.within, n).first);
      for (std::size_t i : surest)
        if (st[i].seen.within > 0 && wilson_interval(st[i].seen.within, n).second >= floor)
          keep.push_back(i);
      keep.resize(std::min(keep.size(), std::max(kDeferRank, (keep.size() + 1) / 2)));
    }
    std::sort(keep.begin(), keep.end());
    for (std::size_t i : screened)
      if (std::binary_search(keep.begin(), keep.end(), i)) next.push_back(i);
      else states_[i] = State{{}, 0, states_[i].seen};  // out: keep only its summary
    std::sort(next.begin(), next.end());  // queue order: the nominal T_p's
    queue = std::move(next);
  }
  for (std::size_t i = 0; i < cands_.size(); ++i)
    if (seen[i]) out.last_seen.push_back(states_[i].seen);
  return out;
}

}  // namespace

std::vector<int> screen_rungs(int n) {
  std::vector<int> rungs;
  for (int r = kFirstRung; r < n; r *= 2) rungs.push_back(r);
  rungs.push_back(n);
  return rungs;
}

ScreenResult screen(const DesignRequest& q, const std::vector<ScreenCandidate>& candidates,
                    const std::vector<InputValues>& draws, const RobustOptions& options) {
  return Screen(q, candidates, draws, options).run();
}

}  // namespace selfalign::detail
