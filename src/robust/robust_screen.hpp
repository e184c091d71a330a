#pragma once
// Internal: the Monte-Carlo screen of design_robust (docs/robust-design.md, section 6).
//
// Each candidate is screened on the common draws 0, 1, ... of the screening seed, in rungs of
// n_r = min(screening_runs, 25 2^r) draws (25, 50, 100, 200 = the default). Every draw is walked
// once and finished at a set of trial x_mu values (ProcessWalk): the outcome at each trial is
// the exact stopping run's, whatever the stop kind, not an extrapolation. The trials are fixed
// once per candidate from its first min(25, n) draws: a lattice (steps <= tolerance/4) around
// the x_mu that the rigid shift of their end positions suggests, +-tolerance/2 wide when every
// run accumulated (its end is x_stick,min = x_mu + a constant, eq. 41: rigid), +-(walking step
// + tolerance) when one stuck for good (the first rest beyond x_stick,min moves by up to a
// step with x_mu). Trials that can no longer be the best (Wilson upper bound of their count
// below the best one's lower bound) are dropped after 10 draws and after every rung.
//
// A candidate qualifies when its best trial's P(within) reaches the selection's bar: the
// lowest P whose selection Monte Carlo (verification_runs runs) can pass the target (its 95%
// Wilson lower bound). Rung r screens its queue in the order of the nominal T_p, in batches;
// once 8 candidates qualify, those whose nominal T_p exceeds the 8th fastest T_p quantile wait
// for the next rung (deferred). The rung's finalists are its `finalists` fastest qualifiers and
// its `finalists` surest candidates (most runs within, then fastest). The screened candidates
// that can still reach the bar (Wilson upper bound) go on to the next rung with the deferred
// ones; when none can, the better half of those that can still be the best.
//
// Everything a rung does depends only on its own first n_r draws and on the rungs before it,
// and nothing in the screen on `finalists`: a search with more screening runs repeats the rungs
// of a smaller one (when the smaller one's count is a rung: 25 2^j) and, with as many or more
// finalists, its finalists are a superset of the smaller one's.

#include <cstddef>
#include <limits>
#include <vector>

#include "selfalign/robust/robust_design.hpp"

namespace selfalign::detail {

// A candidate the screen may take: a grid profile that can reach the target by the closed-form
// bound and stops at the nominal inputs.
struct ScreenCandidate {
  std::size_t grid_index = 0;
  double bound = 0;         // the closed-form bound of P(within)
  Process process;          // SI; x_mu: the provisional placement
  double nominal_time = 0;  // T_p at the nominal inputs and the provisional x_mu [s]
  double nominal_step = 0;  // mean walking step a period at the nominal inputs [m]
  int budget = 0;           // periods a screening run may take
};

// A candidate at a placed x_mu, as a rung of the screen saw it.
struct Screened {
  std::size_t candidate = 0;  // index into the screen's candidates
  double x_mu = 0;            // [m]
  int draws = 0;              // screening runs behind p_within and time
  int within = 0;             // of them ended within the tolerance
  double p_within = 0;
  double time = std::numeric_limits<double>::infinity();  // T_p quantile [s]
  FailureCounts failures;
};

struct ScreenResult {
  std::vector<int> rungs;            // draws per rung
  std::vector<Screened> finalists;   // every rung's, first appearance kept, in rung order
  std::vector<Screened> last_seen;   // each screened candidate at its last rung
  bool any_qualifies = false;        // a candidate qualified on the last rung
};

// Screens `candidates` (sorted by nominal_time) on `draws` (screening_runs of them).
ScreenResult screen(const DesignRequest& request, const std::vector<ScreenCandidate>& candidates,
                    const std::vector<InputValues>& draws, const RobustOptions& options);

// The draws of the first rung (the trials' placement uses as many).
inline constexpr int kFirstRung = 25;

// The rungs for n screening runs: 25, 50, 100, ... below n, then n.
std::vector<int> screen_rungs(int n);

}  // namespace selfalign::detail
