#pragma once
/// \file period_map.hpp
/// The one period map every analysis uses: a table profile, the friction level m(x) of the
/// table's field over the object's footprint, and the friction law, integrated over one table
/// period (or any horizon) by an exact solver where a closed form exists (piecewise-polynomial
/// acceleration on a piecewise-affine level: simulate/exact.hpp; a smooth motion such as a
/// Fourier series on a piecewise-constant level: simulate/smooth_exact.hpp), by the slip
/// integrator for a velocity-dependent law and for a smooth motion other than a Fourier series
/// on sloped pieces (exact sticks, Odeint dopri5 slips with event location:
/// simulate/slip_integrator.hpp), by Moreau time-stepping otherwise.
///
///   P : (x, x') at t0  ->  (x, x') at t0 + Δt,
/// with its arcs (exact), its stick/slip census, and its sensitivity dP/d(x, x'): the monodromy
/// matrix by saltation (arcs' transition matrices coupled at events) or by central finite
/// differences. Steady state, Floquet, convergence, stopping, positioning and the sweeps take a
/// PeriodMap (or the profile and law to build one); none builds a friction law or a period loop
/// itself.

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "selfalign/analysis/motion_case.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_map.hpp"
#include "selfalign/profiles/table_profile.hpp"
#include "selfalign/simulate/exact.hpp"
#include "selfalign/simulate/simulate.hpp"
#include "selfalign/simulate/slip_integrator.hpp"
#include "selfalign/simulate/smooth_exact.hpp"
#include "selfalign/simulate/stepper.hpp"
#include "selfalign/simulate/time_stepping.hpp"

namespace selfalign {

struct PeriodMapOptions {
  /// Time-stepping (profiles or levels the exact solver cannot take): h = Δt / steps_per_period.
  int steps_per_period = 4000;
  double theta = 0.5;  ///< time-stepping theta, in [0, 1]
  IntegratorOptions integrator{};  ///< tolerances of the slip integrator (velocity-dependent laws)
  /// The stepper asked for (StepperRequest::method); nullopt (the default): the best the
  /// problem allows.
  std::optional<Method> method{};
};

class PeriodMap {
 public:
  /// The uniform low-friction table (m = 1) under `law`. Borrows profile.
  explicit PeriodMap(const TableProfile& profile, const FrictionLaw& law = {},
                     const PeriodMapOptions& options = {});
  /// A table whose level is `friction` (borrowed: it must outlive the map) under `law`.
  PeriodMap(const TableProfile& profile, const FrictionMap& friction, const FrictionLaw& law,
            const PeriodMapOptions& options = {});
  PeriodMap(const PeriodMap&) = delete;
  PeriodMap& operator=(const PeriodMap&) = delete;

  const TableProfile& profile() const noexcept { return profile_; }
  const FrictionMap& friction() const noexcept { return *friction_; }
  const FrictionLaw& law() const noexcept { return law_; }
  Method method() const noexcept { return method_of(stepper_); }
  /// The solver this map runs, as chosen by choose_stepper() (stepper.hpp).
  const Stepper& stepper() const noexcept { return stepper_; }
  /// The integrator's tolerances (method() == integrator).
  const IntegratorOptions& integrator_options() const noexcept { return options_.integrator; }
  /// What the integrator did over every call of this map so far (zeros for other methods).
  IntegratorStatistics integrator_statistics() const;
  /// True when the map is exact and so has arcs (piecewise-polynomial profiles, or smooth
  /// motions on piecewise-constant levels).
  bool has_arcs() const noexcept { return selfalign::has_arcs(stepper_); }
  double period() const noexcept { return profile_.period(); }
  /// Time-stepping step h [-] (0 for the exact solvers and the integrator).
  double step() const noexcept { return stepping().step; }
  /// Time-stepping's options (a zero step for the other methods).
  const TimeSteppingOptions& stepping() const noexcept;

  /// State at t0 + Δt from (x0, x'0) at t0 (t0 = 0: the profile's phase 0). The observer
  /// receives every piece of the period's motion (arcs with their closed form when the map is
  /// exact); a census the stick/slip classes of the period. Any method.
  ObjectState operator()(double x0, double v0, MotionObserver* observer = nullptr,
                         MotionCensus* census = nullptr) const;
  /// The arcs of one period from (x0, x'0) at phase 0 (has_arcs() only; throws otherwise).
  std::vector<Arc> arcs(double x0, double v0) const;
  /// Monodromy matrix of the period from (x0, x'0) by saltation: the arcs' transition
  /// matrices (arc.hpp) coupled by the saltation matrices of their events (has_arcs() only).
  Eigen::Matrix2d saltation_monodromy(double x0, double v0) const;
  /// Monodromy matrix by central finite differences of step h in x and x' (either method).
  Eigen::Matrix2d finite_difference_monodromy(double x0, double v0, double h) const;

  /// A run from `start` across as many periods as wanted (stopping, positioning, convergence).
  class Run {
   public:
    /// Advances to t_end >= the current time (time-stepping: whole steps, ending at the step
    /// nearest t_end); every piece of the motion goes to observer, and every crossing of a
    /// position in `watch` (sorted) to observer->on_crossing (a non-empty watch: integrator
    /// only; throws InvalidParameter naming "method" for other methods).
    const ObjectState& advance_to(double t_end, MotionObserver* observer = nullptr,
                                  std::span<const double> watch = {});
    const ObjectState& state() const noexcept { return object_of(state_); }
    /// The exact solver's state (segment and period index; exact only, else a default one).
    const ExactState& exact_state() const noexcept;
    /// Moves the run `periods` >= 1 table periods on at once, its position by `displacement`:
    /// the state one would reach by advancing, where the caller knows the motion repeats every
    /// period with that displacement (a part at rest at the same phase each period on a level
    /// that does not change where it moves; see stopping_run). Exact solver only, and only at
    /// a segment switch (the state as a look at a switch left it): returns false, changing
    /// nothing, otherwise. The new time is formed as the solver forms a switch's.
    bool jump_periods(long long periods, double displacement);

   private:
    friend class PeriodMap;
    Run(const PeriodMap& map, const ObjectState& start);
    const PeriodMap* map_;
    StepperState state_;
  };
  Run start(const ObjectState& state) const { return Run(*this, state); }

  /// The exact solver's setup (exact only; throws otherwise).
  const ExactSetup& exact_setup() const;

 private:
  const TableProfile& profile_;
  std::unique_ptr<FrictionMap> owned_;
  const FrictionMap* friction_;
  FrictionLaw law_;
  PeriodMapOptions options_;
  Stepper stepper_;  // after friction_, law_ and options_: made from them
  mutable std::mutex statistics_mutex_;
  mutable IntegratorStatistics statistics_;
  void add(const IntegratorStatistics& s) const;
};

/// The profile as the exact solver's piecewise-polynomial form, or InvalidParameter("profile",
/// its kind, "<analysis> needs a piecewise-constant or piecewise-linear table acceleration"):
/// the one capability check of the analyses that need the exact solver's arcs.
const PiecewisePolynomialProfile& require_exact_profile(const TableProfile& profile,
                                                        const std::string& analysis);

/// The monodromy matrix of a stream of arcs (a MotionObserver of a closed-form stepper; a
/// piece without its arc throws InvalidParameter naming "method"): each arc's transition matrix, coupled
/// to the next arc's by the saltation matrix of the event between them,
///   M = S(a_n, a_1) Φ_n ... S(a_1, a_2) Φ_1,
/// the last event coupled to `next` given to finish() (a period's own first arc for a periodic
/// solution, as saltation_monodromy() does). Used where the arcs are computed anyway: the
/// steady-state search reads dP/dx'0 = M(1, 1) off the period it simulates.
class SaltationProduct final : public MotionObserver {
 public:
  explicit SaltationProduct(const FrictionLaw& law) : law_(&law) {}
  void on_motion(const MotionInterval& piece, const Arc* arc) override;
  /// The next arc.
  void add(const Arc& a);
  /// The product so far with the saltation of the last arc's end into `next`. Identity when
  /// no arc was received.
  Eigen::Matrix2d finish(const Arc& next) const;
  /// finish() with the first arc received as `next` (the periodic coupling).
  Eigen::Matrix2d finish_periodic() const { return count_ ? finish(first_) : product_; }

 private:
  const FrictionLaw* law_;
  Eigen::Matrix2d product_ = Eigen::Matrix2d::Identity();  // up to the last arc's Φ
  Arc first_{}, last_{};
  std::size_t count_ = 0;
};

/// The saltation matrix at the end of arc `a` when arc `next` follows (Leine & Nijmeijer): the
/// jump of the linearised flow across the event that ended `a`.
///   velocity_zero:      [[1, 0], [0, a+/a-]]  (0 when next sticks)          (eqs. 28-31)
///   friction_boundary:  [[1, 0], [(a+ - a-)/x', 1]]
///   stick_break:        [[1, 0], [-a+ s k / (sign(A) J), 1]]  (k = dm/dx, J the table jerk)
///   segment ends:       identity (the event time does not depend on the state)
Eigen::Matrix2d saltation(const Arc& a, const Arc& next, const FrictionLaw& law);

}  // namespace selfalign
