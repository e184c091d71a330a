#pragma once
/// \file process_walk.hpp
/// One draw of a designed process, walked once on the smooth region and finished at any start
/// x_mu of the rough region: the robust search's screen (docs/robust-design.md, section 6).
///
/// Until the part first reaches x_mu + offset its motion does not depend on x_mu: the friction
/// level is 1 up to there (eqs. 7-9). So the run at x_mu is the walk on the uniform table up to
/// its last look (a period start t_k = k Δt) at which the part has not yet reached x_mu,
/// continued by the exact stopping run of analysis/stopping.hpp from that state. at(x_mu)
///   = run_process(request, process with x_mu, inputs, max_periods)
/// for every stop kind (permanent stick, accumulation, not stopped), to rounding and to within
/// one period of the max_periods budget, at the cost of the walk once plus, per x_mu, the
/// settling after entry. The walk is extended on demand and kept: its looks (one state a
/// period) are what every later x_mu continues from.

#include <memory>
#include <optional>
#include <vector>

#include "selfalign/analysis/period_map.hpp"
#include "selfalign/robust/process_uncertainty.hpp"

namespace selfalign {

class ProcessWalk {
 public:
  /// The draw `inputs` of `process` (its x_mu is not used: at() takes one). max_periods bounds
  /// every run from rest, as in run_process.
  ProcessWalk(const DesignRequest& request, const Process& process, const InputValues& inputs,
              int max_periods);
  ProcessWalk(const ProcessWalk&) = delete;
  ProcessWalk& operator=(const ProcessWalk&) = delete;

  /// The outcome with the rough region starting at x_mu [m] (plus the draw's offset).
  ProcessOutcome at(double x_mu);

  /// Periods walked so far.
  int periods() const noexcept { return static_cast<int>(looks_.size()) - 1; }

 private:
  void walk_to(double x);  // until the part has reached x [-] or the budget ends

  ProcessModel model_;
  double offset_;  // the draw's x_mu offset [m]
  int max_periods_;
  std::unique_ptr<PeriodMap> smooth_;  // the uniform table m = 1
  std::optional<PeriodMap::Run> run_;
  std::vector<ObjectState> looks_;  // state at t_k = k Δt, k = 0, 1, ...
  std::vector<double> reach_;       // max x over [0, t_k] [-]
  bool stalled_ = false;            // a look repeated exactly: the part never gets further
};

}  // namespace selfalign
