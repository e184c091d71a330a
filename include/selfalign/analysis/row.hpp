#pragma once
/// \file row.hpp
/// Queues of parts (issue 24, docs/rows.md): a row of 1-D parts on the table, conveyed on a
/// uniform table (cluster structure and throughput) or stopping at a friction step (each part's
/// end position, process time and positioning error, the spacing, whether the queue
/// accumulates behind the first part). Solved exactly (simulate/row_exact.hpp) or by the
/// contact core's Moreau step with part contacts (core/step.hpp), as RowSolver says.
///
/// Units: the paper's dimensionless ones (Sect. 3.2): lengths x/L, times in table periods
/// when the profile's period is 1, accelerations in mu_1 g.

#include <span>
#include <vector>

#include "selfalign/core/model.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/simulate/method.hpp"
#include "selfalign/simulate/row_exact.hpp"

namespace selfalign {

/// One part of a queue: its length along the table (> 0), mass (> 0; only ratios matter), its
/// friction law with the table, and where it starts (leading edge x [-], velocity relative to
/// the table [-]).
struct RowPart {
  double length = 0.3;
  double mass = 1;
  FrictionLaw law{};
  double x = 0, v = 0;
};

/// A queue: parts from the rear to the front (each one's x ahead of the previous one's by at
/// least its length: no overlap), and Newton's restitution e in [0, 1] between neighbours.
struct RowQueue {
  std::vector<RowPart> parts;
  double restitution = 0;
};

/// How a queue is solved: Method::exact (a piecewise-constant table acceleration and a field
/// of steps) or Method::time_stepping (Moreau, `steps_per_period` steps per period; the exact
/// solver ignores it).
struct RowSolver {
  Method method = Method::exact;
  long long steps_per_period = 2000;
};

/// The contact-core model of `queue` on `profile` (along e1) and the friction level `field`
/// along the table (null: uniform level 1): bodies in the queue's order, one PartContact
/// between each pair of neighbours. Throws InvalidParameter naming "parts[i].length",
/// "parts[i].mass", "parts[i].law" or "restitution"; the profile must outlive the model.
core::Model row_model(const TableProfile& profile, const RowQueue& queue,
                      const FrictionField* field, long long steps_per_period);

/// A conveying run: `periods` periods from the queue's start.
struct RowRun {
  std::vector<double> x, v;            ///< each part at the end [-]
  std::vector<double> mean_velocity;   ///< each part's mean velocity over the last period [-]
  double queue_velocity = 0;           ///< the parts' mean of it [-]
  /// The clusters at the end, rear to front: their sizes (touching parts: the exact solver's
  /// closed contacts; Moreau: a gap at most touch_gap).
  std::vector<int> clusters;
  double pitch = 0;        ///< the queue's mean spacing of leading edges at the start [-]
  /// Parts per period past a point of the table at the queue's velocity and pitch:
  /// queue_velocity * period / pitch (NaN for one part: no pitch).
  double throughput_per_period = 0;
  long long collisions = 0, separations = 0;  ///< exact solver (0 for Moreau)
  /// Sampled trajectories: times [-] and x of every part at each time (samples x parts).
  std::vector<double> times;
  std::vector<std::vector<double>> positions;
};

/// Moreau's cluster report: neighbours at most this far apart touch [-].
inline constexpr double kRowTouchGap = 1e-9;

/// Runs the queue for `periods` (>= 1) periods, sampling `samples_per_period` (>= 1) times a
/// period. Throws InvalidParameter for bad input (the model's checks, "periods",
/// "samples_per_period", "method", "steps_per_period").
RowRun row_run(const TableProfile& profile, const RowQueue& queue, const FrictionField* field,
               long long periods, const RowSolver& solver, long long samples_per_period = 20);

/// A queue stopping at the friction step: run period by period until no part moves through a
/// whole period (the drive is periodic: then it never moves again) or max_periods.
struct RowStop {
  bool stopped = false;
  double stop_time = 0;          ///< end of the last motion [-] (NaN: not stopped)
  long long periods = 0;         ///< periods run
  std::vector<double> x;         ///< each part's end position [-]
  std::vector<double> process_time;  ///< each part's last motion [-] (NaN: it never moved)
  std::vector<double> gaps;      ///< the spacing: gap behind each part but the rear one [-]
  /// Whether the queue accumulates behind the first (front) part: every gap below touch_gap.
  bool accumulated = false;
  /// Each part's positioning error [-]: x - target, target = `step` for the front part and
  /// the packed position behind it, step - (lengths of the parts ahead), for the others.
  std::vector<double> error;
  long long collisions = 0, separations = 0;
  std::vector<double> times;
  std::vector<std::vector<double>> positions;
};

/// Stops the queue on `field` (its first node is the friction step `step` the errors refer
/// to). Throws InvalidParameter as row_run, and "max_periods".
RowStop row_stop(const TableProfile& profile, const RowQueue& queue, const FrictionField& field,
                 long long max_periods, const RowSolver& solver, long long samples_per_period = 20);

}  // namespace selfalign
