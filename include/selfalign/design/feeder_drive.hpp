#pragma once
/// \file feeder_drive.hpp
/// The choice of a feeder drive for a target conveying speed (issue 23, item 4; docs/feeder.md,
/// "Choosing the drive"): on a track (incline, friction) at a given drive frequency, for each
/// candidate vibration angle psi the least amplitude a0 (machine number K = a0 w^2 / g) whose
/// steady conveying speed, by the exact feeder solver, reaches the target, within a flight
/// bound: no lift-off at all (max_flight_angle = 0: K <= the lift-off onset, Gamma <= 1) or a
/// flight angle at most max_flight_angle per period. The design is the candidate with the least
/// K (the least peak acceleration of the drive, so the least force on the leaf springs).
///
/// Per angle: the speed v(K) of feeder_run_exact (the mean over the last of `periods` periods
/// from rest) is sampled on `k_samples` machine numbers spaced geometrically from the forward
/// slip onset (below it the part is held: v = 0) to the cap (k_max, and the lift-off onset
/// when no flight is allowed); the first sample that reaches the target brackets the least K
/// with the sample before it, which bisection then closes to `k_tolerance` (relative). The
/// flight bound is checked there: the flight angle grows with K, so if the least K that
/// reaches the speed flies too long, every larger one does too (infeasible at that angle). A
/// target that no sample reaches is infeasible at that angle; where v(K) is not monotone the
/// first sampled crossing is taken (the sampling is the resolution of "least").

#include <string>
#include <vector>

#include "selfalign/analysis/sweep.hpp"  // ProgressCallback

namespace selfalign {

struct FeederDriveOptions {
  double incline = 0;                        ///< theta [rad], in (-pi/2, pi/2)
  double mu_static = 0.5, mu_kinetic = 0.4;  ///< absolute coefficients, 0 < k <= s
  double g = 1;                              ///< [-] (9.81 in SI)
  double period = 1;                         ///< drive period [-] (1 / frequency in SI)
  double target_speed = 0;                   ///< the conveying speed wanted [-] (m/s in SI), > 0
  /// The flight allowed per period [rad]: 0 = none (the part never leaves the track), else the
  /// largest flight angle, in (0, 2 pi].
  double max_flight_angle = 0;
  std::vector<double> vibration_angles = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
  double k_max = 10;                ///< the largest machine number considered [-], > 0
  int k_samples = 48;               ///< samples per angle, in [2, 10000]
  double k_tolerance = 1e-10;       ///< relative width of the bisected K, in [1e-15, 0.1]
  long long periods = 20;           ///< from rest per run; the last one is measured
  double restitution = 0;           ///< Newton's e at landings
  int threads = 0;                  ///< angles in parallel; 0: all cores
  ProgressCallback progress;        ///< (angles done, angles), optional
};

/// One candidate angle's least drive, or why there is none.
struct FeederDriveCandidate {
  double vibration_angle = 0;
  bool feasible = false;
  double machine_number = NAN, amplitude = NAN, throw_number = NAN;  ///< NaN: infeasible
  double speed = NAN;         ///< the speed at that K [-] (>= the target, within k_tolerance)
  double flight_angle = NAN;  ///< of the last period [rad]; 0 without a flight; NaN: infeasible
  std::string reason;         ///< why infeasible (empty when feasible)
};

struct FeederDriveDesign {
  bool feasible = false;
  FeederDriveCandidate best;                      ///< the feasible candidate with the least K
  std::vector<FeederDriveCandidate> candidates;   ///< one per vibration angle, in order
};

/// Throws InvalidParameter naming the first bad option ("incline", "mu_static", "mu_kinetic",
/// "g", "period", "target_speed", "max_flight_angle", "vibration_angles", "k_max", "k_samples",
/// "k_tolerance", "periods", "restitution", "threads"). An infeasible target is a result
/// (feasible false, NaN numbers, a reason per angle), not an error.
FeederDriveDesign design_feeder_drive(const FeederDriveOptions& options);

}  // namespace selfalign
