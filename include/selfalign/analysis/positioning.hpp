#pragma once
/// \file positioning.hpp
/// Positioning accuracy (Sect. 7.1, eq. 39) and the Fig. 17 surfaces.
///
/// The object enters the high-friction region in its steady state. Following Sect. 7.1:
/// x_mu = Δx, the largest displacement in one steady period, and N steady-state entries
/// x_0s ∈ [-v̄Δt, 0] (with the steady x'_0s at phase 0) cover every way of arriving. Each
/// entry's stopping run gives an end position x_mu + Δx_overshoot; then
///   Δx_d = (Δx_overshoot,max - Δx_overshoot,min) / 2            (eq. 39)
///   x_d  = x_mu + Δx_overshoot,min + Δx_d.

#include <string>
#include <vector>

#include "selfalign/analysis/motion_case.hpp"
#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/analysis/stopping.hpp"
#include "selfalign/analysis/sweep.hpp"

namespace selfalign {

struct PositioningOptions {
  int entries = 100;          ///< number N of steady-state entries, in [1, 1e5]
  StoppingOptions stopping;   ///< per entry
  /// Skip the remaining entries once one does not stop (Δx_d is then undefined anyway);
  /// positioning_surfaces sets it.
  bool stop_at_first_failure = false;
  SteadyStateOptions steady;
};

/// Throws InvalidParameter unless entries >= 1 and stopping.max_periods >= 1.
void validate(const PositioningOptions& options);

struct PositioningAccuracy {
  bool reaches = false;  ///< false when v̄ <= 0: the object never walks into the region
  SteadyState steady;
  double x_mu = 0;         ///< = Δx, the largest displacement in one steady period [-]
  double x_stick_min = 0;  ///< eq. (41) [-]
  std::vector<double> entries;        ///< x_0s [-]
  std::vector<StoppingRun> runs;      ///< per entry: end position, kind, times to p
  double overshoot_min = 0, overshoot_max = 0;  ///< end - x_mu [-]
  double dx_d = 0;  ///< eq. (39) [-]
  double x_d = 0;   ///< desired end position [-]
  int accumulating_entries = 0;
  bool accumulates = false;  ///< every entry accumulates to x_stick,min
  bool all_stopped = false;  ///< every entry stopped (none hit max_periods)
};

/// Sect. 7.1 for a piecewise-constant profile on a two-region table of width w and ratio c_mu
/// (x_mu is placed at Δx). Throws InvalidParameter on bad inputs.
PositioningAccuracy positioning_accuracy(const TableProfile& profile, double width, double c_mu,
                                         const PositioningOptions& options = {});
/// The same under a Coulomb law (static >= kinetic, direction-dependent) and for any
/// piecewise-polynomial profile (finite jerk included): the steady state, Δx, x_stick,min
/// (s m(x) >= peak) and the stopping runs all take the law.
PositioningAccuracy positioning_accuracy(const TableProfile& profile, const FrictionLaw& law,
                                         double width, double c_mu,
                                         const PositioningOptions& options = {});
/// Sect. 7.1 on any piecewise-affine friction level that rises (a friction field: FieldFriction,
/// several steps, ramps under a point footprint; the two-region table too), the level where it
/// stands: x_mu is its rise X = friction_rise(friction) (PositioningAccuracy::x_mu = X), and
/// the entries lie in [X - Δx - v̄Δt, X - Δx] so that, as with the paper's x_mu = Δx, each
/// reaches the rise within its first steady period (on the two-region table with x_mu = Δx
/// these are the paper's entries, and the result is the overload above's). Overshoots are
/// end - X; x_stick_min is stick_position_min of the level's pieces. The part arrives in the
/// steady state of the uniform table m = 1, so the level must be 1 before its rise
/// (InvalidParameter naming "friction" otherwise, or for a level without a rise or not
/// piecewise affine).
PositioningAccuracy positioning_accuracy(const TableProfile& profile, const FrictionLaw& law,
                                         const FrictionMap& friction,
                                         const PositioningOptions& options = {});

/// One cell of the Fig. 17 surfaces.
struct PositioningCell {
  double a2 = 0, a3 = 0;  ///< y2'', y3'' [-]
  StickSlipCase motion_case = StickSlipCase::non_physical;  ///< (B), a posteriori
  double f = 0;            ///< (A) eq. (11) [-]
  bool accumulates = false;  ///< (C)
  double dx_d = 0;         ///< (D) eq. (39) [-]; NaN where the object does not arrive
  int accumulating_entries = 0;
  /// Largest number of periods from entry to p = 0.99 and p = 0.999 over the entries that
  /// accumulate (-1 if none).
  int max_periods_p99 = -1, max_periods_p999 = -1;
  /// Empty when the cell was computed; otherwise why it could not be (f and Δx_d are NaN).
  /// One failing cell never aborts the study.
  std::string failure;
};

/// Fig. 17 over the grid a2 x a3 (row-major, a2 outer) at (Δt, Δy, w, c_mu); parallel,
/// deterministic (SweepOptions as for sweep_accelerations, its law and jerk included). Cells whose object never comes to
/// rest (e.g. y3'' > y2'': it rattles in the transition region, never reaching the x where
/// m >= y3'') get Δx_d = NaN; options.stopping.max_periods bounds the search per entry (a few
/// hundred periods is far beyond the few periods a stop takes).
std::vector<PositioningCell> positioning_surfaces(double period, double stroke, double width,
                                                  double c_mu, const std::vector<double>& a2,
                                                  const std::vector<double>& a3,
                                                  const PositioningOptions& options = {},
                                                  const SweepOptions& sweep = {});
/// The same on a friction level where it stands (positioning_accuracy's FrictionMap overload
/// in every cell: x_mu is the level's rise; the level must be 1 before it, InvalidParameter
/// naming "friction" otherwise, checked before any cell runs). `friction` is read from every
/// worker thread (the maps are immutable).
std::vector<PositioningCell> positioning_surfaces(double period, double stroke,
                                                  const FrictionMap& friction,
                                                  const std::vector<double>& a2,
                                                  const std::vector<double>& a3,
                                                  const PositioningOptions& options = {},
                                                  const SweepOptions& sweep = {});

}  // namespace selfalign
