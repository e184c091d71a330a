#pragma once
/// \file process_design.hpp
/// `selfalign design`: from SI actuator limits and an object to a recommended three-phase table
/// profile that minimises the process time T_p (Sect. 2's first objective) subject to a
/// positioning requirement (Sect. 7): accumulation (Δx_d = 0) or a given tolerance.
///
/// The search (deterministic, parallel over chunks of the grid, streamed: it keeps each chunk's
/// best candidate, not the grid; DesignGrid): periods from 1/f_max to 1/f_min,
/// strokes up to the actuator stroke, and (y2'', y3'') in (1, min(c_mu, a_max)] x
/// (0, min(c_mu, a_max)] (y2'' > 1 moves the object; <= c_mu lets it stop for good, eq. 41),
/// keeping profiles whose exact velocity extrema y'_ini and y'_ini - D respect v_max. Each
/// candidate's steady state (v̄ > 0) and positioning accuracy (eq. 39 over N steady entries)
/// give its feasibility and an estimate of T_p = (x_mu)/v̄ + settling; the best candidate's
/// T_p, end position and band then come from an exact stopping run from rest.
/// Dimensionless inside with L = object width (so w = 1); SI in and out.

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "selfalign/analysis/motion_case.hpp"
#include "selfalign/analysis/stopping.hpp"

#include "selfalign/analysis/sweep.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/profiles/three_phase.hpp"

namespace selfalign {

/// A design request, in SI units.
struct DesignRequest {
  double mass = 1.0;               ///< object mass [kg] (reported; it cancels from eq. 6)
  double width = 0.01;             ///< object width w~ [m], > 0
  double mu = 0.3;                 ///< low-friction coefficient mu_1 [-], > 0
  double c_mu = 2.5;               ///< mu_2/mu_1 [-], > 1
  double gravity = 9.81;           ///< g~ [m/s^2]
  double distance = 0.1;           ///< desired end position from the start position [m], > 0
  double stroke_max = 0.002;       ///< actuator stroke limit [m], > 0
  double frequency_min = 5;        ///< lowest table frequency [Hz], > 0
  double frequency_max = 50;       ///< highest table frequency [Hz], >= frequency_min
  double velocity_max = 0.2;       ///< |y'~| limit [m/s], > 0
  double acceleration_max = 10;    ///< |y''~| limit [m/s^2], > 0
  /// Table jerk limit [m/s^3], > 0: every switch of the profile becomes a ramp at this jerk
  /// (the jerk-limited three-phase profile); +inf: the paper's jump accelerations.
  double jerk_max = std::numeric_limits<double>::infinity();
  /// Static friction coefficient [-] (absolute, like mu), >= mu and mu_backward; none: equal
  /// to mu. A NaN is refused (validate), never read as "not given".
  std::optional<double> mu_static;
  /// Kinetic coefficient of backward slip [-] (absolute, like mu), > 0; none: equal to mu.
  std::optional<double> mu_backward;
  double tolerance = 0;            ///< allowed Δx_d~ [m]; 0: require accumulation (Δx_d = 0)
  int acceleration_grid = 24;      ///< candidates per acceleration axis, in [2, 200]
  int period_grid = 6;             ///< candidate periods, in [1, 100]
  int stroke_grid = 3;             ///< candidate strokes (stroke_max, 2/3, 1/3 of it), [1, 20]
  int entries = 40;                ///< steady entries per candidate (Sect. 7.1), in [2, 1000]
};

/// Throws InvalidParameter naming the first field out of range (positive scales in [1e-50,
/// 1e50]).
void validate(const DesignRequest& request);

/// The request's friction law in model units (ratios to mu): law_of_coefficients(mu,
/// mu_static, mu_backward). Throws InvalidParameter naming mu, mu_static or mu_backward.
FrictionLaw friction_law(const DesignRequest& request);

struct DesignResult {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  bool feasible = false;
  std::string message;             ///< why not, naming the binding limit, when infeasible
  // The recommended profile, SI (NaN when infeasible: no value, never 0):
  double period = kNaN;            ///< Δt~ [s]
  double stroke = kNaN;            ///< Δy~ [m]
  double a2 = kNaN, a3 = kNaN;     ///< y2''~, y3''~ [m/s^2]
  double t1 = kNaN, t2 = kNaN, t3 = kNaN;  ///< switch times [s]
  double y_ini = kNaN, y_dot_ini = kNaN;  ///< [m], [m/s]
  double velocity_peak = kNaN;     ///< max |y'~| [m/s]
  StickSlipCase motion_case = StickSlipCase::non_physical;
  // Predictions, SI (NaN when infeasible):
  double v_bar = kNaN;             ///< steady average velocity [m/s]
  double x_mu = kNaN;              ///< where the high-friction region must start [m]
  double end_position = kNaN;      ///< predicted end position x_d~ [m] (= distance)
  double error_band = kNaN;        ///< half-width of the end-position band [m]
  double process_time = kNaN;      ///< T_p~: time to come within the band for good [s]
  StopKind stop = StopKind::not_stopped;
  int candidates = 0, feasible_candidates = 0;
  /// The request limits the profile sits on (DesignGrid::pinned_limits), e.g. "frequency at
  /// frequency_min = 5 Hz (the default)"; empty when it is inside the grid.
  std::vector<std::string> limits;
  ThreePhaseParameters dimensionless{};  ///< the same profile in model units (L = width)
  /// Its jerk limit in model units (+inf: jump accelerations) and in SI [m/s^3].
  double jerk_dimensionless = std::numeric_limits<double>::infinity();
  double jerk = std::numeric_limits<double>::infinity();
  double x_mu_dimensionless = kNaN;
};

/// The candidate grid of design_process, in model units (L = width, accelerations in mu g):
/// periods log-spaced from 1/frequency_max to 1/frequency_min, strokes k/stroke_grid of
/// stroke_max, (y2'', y3'') in (1, min(c_mu, a_max)] x (0, min(c_mu, a_max)], keeping the
/// physical profiles within velocity_max. Enumerated lazily, one index at a time, so that a
/// search over it needs memory for what it keeps, not for the grid (size() reaches 8e7).
class DesignGrid {
 public:
  /// Validates the request.
  explicit DesignGrid(const DesignRequest& request);
  /// acceleration_grid^2 x period_grid x stroke_grid (0 when acceleration_max <= mu g).
  std::size_t size() const noexcept { return size_; }
  /// Why an index is not a candidate.
  enum class Skip { none, non_physical, too_fast };
  /// The profile at index i < size(), or nullopt with `why` (non-physical: case 0; too fast:
  /// its velocity extrema exceed velocity_max).
  std::optional<ThreePhaseParameters> at(std::size_t i, Skip* why = nullptr) const;
  double jerk() const noexcept { return jerk_; }  ///< the jerk limit [-] (+inf: jumps)
  /// Which limits bind when no index is a candidate, given the counts of the skipped ones.
  std::string empty_message(std::size_t non_physical, std::size_t too_fast) const;
  /// The limits the profile at a grid point sits on, e.g. "frequency at frequency_min = 5 Hz
  /// (the default)": grid edges that are request limits (frequency_min, frequency_max,
  /// stroke_max, acceleration_max) and the top of the acceleration axis c_mu mu g; "(the
  /// default)" marks a value equal to DesignRequest's default. A design pinned there might do
  /// better with that limit relaxed.
  std::vector<std::string> pinned_limits(const ThreePhaseParameters& profile) const;

 private:
  DesignRequest request_;
  double jerk_ = std::numeric_limits<double>::infinity(), v_max_ = 0, a_hi_ = 0;
  std::vector<double> periods_, strokes_, a2s_, a3s_;
  std::size_t size_ = 0;
};

/// A DesignResult for one profile (model units) and rough-region start x_mu [-]: its SI
/// description, nominal steady state (motion case, v̄) and the exact stopping run from rest
/// (end position, T_p); dx_d [-] widens the reported band (0: the run's own).
DesignResult describe_design(const DesignRequest& request, const ThreePhaseParameters& profile,
                             double x_mu, double dx_d);

/// The most steady entries design_process evaluates: acceleration_grid^2 x period_grid x
/// stroke_grid x entries <= 1e9 (about 30 us each on one core: some 8 hours).
inline constexpr double kMaxDesignEntries = 1e9;

/// Runs the search. Infeasible requests return feasible = false with a message. Streams over
/// the grid (memory independent of its size); throws InvalidParameter("grid", ...) for a grid
/// beyond kMaxDesignEntries.
DesignResult design_process(const DesignRequest& request, const SweepOptions& sweep = {});

/// The recommended profile of a feasible result, in model units: a ThreePhaseProfile, or the
/// JerkLimitedThreePhaseProfile under a jerk limit.
std::unique_ptr<TableProfile> recommended_profile(const DesignResult& result);

}  // namespace selfalign
