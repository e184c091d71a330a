#pragma once
/// \file worst_case.hpp
/// The worst case of a designed process over the box of its uncertain inputs: the largest
/// end-position error (a run that does not stop counts as the worst) and the longest process
/// time. A search, not only the corners: every corner of the box, a Halton set of interior
/// points, then NLopt's bounded Nelder-Mead from the worst points found; `method` says what
/// was done and `evaluations` how many exact stopping runs it took. Deterministic and
/// independent of the thread count.

#include <string>
#include <utility>
#include <vector>

#include "selfalign/robust/process_uncertainty.hpp"

namespace selfalign {

struct WorstCaseOptions {
  /// A normal without truncation bounds spans mean -/+ sigmas sd in the box.
  double sigmas = 3;
  int interior_points = 64;     ///< Halton points inside the box, in [0, 1e5]
  int starts = 3;               ///< local searches, from the worst points found, in [0, 100]
  int local_evaluations = 100;  ///< runs per local search, in [0, 1e5]
  int max_periods = 3000;
  int threads = 0;
};

struct WorstCase {
  std::string method;  ///< how the box was searched
  int evaluations = 0; ///< exact stopping runs
  /// The box searched, per input (uncertain_inputs() order): [v, v] for a known input.
  std::vector<std::pair<double, double>> box;
  InputValues worst_inputs{};  ///< the inputs of the largest end-position error
  ProcessOutcome worst;        ///< that run
  /// |end - target| of that run [m]; +inf when it does not stop.
  double worst_error = 0;
  /// Every evaluated point ended within the tolerance (the request's; > 0 required).
  bool all_within = false;
  InputValues slowest_inputs{};  ///< the inputs of the longest process time
  double slowest_time = 0;       ///< [s]; +inf when a run does not stop
};

/// Throws InvalidParameter for bad inputs (no uncertain input, options out of range, ...).
WorstCase worst_case(const DesignRequest& request, const Process& process,
                     const ProcessUncertainty& uncertainty, const WorstCaseOptions& options = {});

}  // namespace selfalign
