#pragma once
/// \file sweep.hpp
/// Parameter studies (Sect. 4.4.1, 5.2): f and the motion case over a (y2'', y3'') grid
/// (Figs. 10, 11, 17A-B), and f against Δt at fixed Δy or against Δy at fixed Δt (Figs. 4, 5)
/// for any profile family.
///
/// Cells are independent: they are computed in parallel (oneTBB) and each result is written to
/// its own slot, so the output is identical for any thread count.

#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "selfalign/analysis/motion_case.hpp"
#include "selfalign/analysis/steady_state.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign {

/// The most values a grid (and cells a study) may have: 80 MB of values, hours of work.
inline constexpr int kMaxGridPoints = 10'000'000;

/// n values from lo to hi inclusive, evenly spaced (1 <= n <= 1e7; n = 1 gives lo); exact ends,
/// no overflow for ends near the largest doubles.
std::vector<double> linear_grid(double lo, double hi, int n);
/// n values from lo to hi inclusive, evenly spaced in log (lo, hi > 0; 1 <= n <= 1e7).
std::vector<double> log_grid(double lo, double hi, int n);

/// Called as cells complete: (done, total). Called from worker threads, one call at a time.
using ProgressCallback = std::function<void(std::size_t done, std::size_t total)>;

struct SweepOptions {
  int threads = 0;              ///< worker threads, >= 0; 0: all cores (see worker_threads)
  ProgressCallback progress;    ///< optional
  SteadyStateOptions steady;    ///< per-cell steady-state search
  FrictionLaw law;          ///< the friction law of every cell (the paper's by default)
  /// sweep_accelerations: the jerk limit of every cell's three-phase profile [-], > 0; +inf:
  /// the paper's jump accelerations. A cell with no jerk-limited profile is case 0.
  double jerk = std::numeric_limits<double>::infinity();
  /// sweep_accelerations: a cell with jump accelerations under a Coulomb law is the closed-form
  /// steady state (three_phase_steady_state.hpp: a formula, no periods simulated); false: the
  /// fixed-point search of steady_state() on every cell (`steady`'s options), e.g. to check it.
  /// Other cells (finite jerk, velocity-dependent laws) always take the search.
  bool closed_form = true;
};

/// The number of workers a study runs on for `requested` threads: all the cores available to
/// this process (oneTBB's default concurrency, which honours the affinity mask) for 0, else
/// min(requested, cores): asking for more workers than cores gives no speed-up and only
/// oversubscribes. Throws InvalidParameter("threads", ...) for requested < 0.
int worker_threads(int requested);

/// One cell of a (y2'', y3'') study of the three-phase profile.
struct AccelerationCell {
  double a2 = 0, a3 = 0;                                   ///< y2'', y3'' [-]
  /// a priori (Fig. 8 rules: jump accelerations under the paper's law, whatever the options)
  StickSlipCase predicted = StickSlipCase::non_physical;
  /// a posteriori: of the steady period (closed form or search, SweepOptions::closed_form)
  StickSlipCase observed = StickSlipCase::non_physical;
  double v_bar = 0;    ///< eq. (10) [-]; NaN for case 0
  double f = 0;        ///< eq. (11) [-]; +inf for v̄ = 0, NaN for case 0
  double x_dot_0s = 0; ///< steady-state x' at t0 [-]; NaN for case 0
  bool converged = false;  ///< the steady state was found (always, by the closed form)
  /// Empty when the cell was computed; otherwise why it could not be (its numbers are NaN).
  /// One failing cell never aborts the study.
  std::string failure;
};

/// The number of cells of an a2 × a3 study, len(a2) len(a3). Throws InvalidParameter naming
/// "cells" when it exceeds kMaxGridPoints (a front end checks before allocating its output).
std::size_t acceleration_cells(const std::vector<double>& a2, const std::vector<double>& a3);

/// True when sweep_accelerations computes its cells by the closed form under these options:
/// options.closed_form, jump accelerations (jerk +inf) and a Coulomb law.
bool closed_form_cells(const SweepOptions& options) noexcept;

/// f and case over the grid a2 × a3 at fixed (Δt, Δy); row-major: cell (i, j) is at
/// index i * a3.size() + j with a2[i], a3[j]. Throws InvalidParameter on bad inputs.
std::vector<AccelerationCell> sweep_accelerations(double period, double stroke,
                                                  const std::vector<double>& a2,
                                                  const std::vector<double>& a3,
                                                  const SweepOptions& options = {});

/// Receives the cells of sweep_accelerations as they are computed: sink(k, cell) for each cell
/// index k (row-major as above) exactly once, from the worker threads, several at a time, in no
/// particular order. It must not throw.
using AccelerationSink = std::function<void(std::size_t k, const AccelerationCell& cell)>;

/// sweep_accelerations handing each cell to `sink` instead of storing it: a front end writes
/// the cells straight into its own output (NumPy arrays, a .npy file's records), in parallel,
/// so a study never holds its cells twice (10^6 AccelerationCells are 88 MB). The same cells
/// as the vector form, which is this with a sink storing them. Throws as the vector form.
void sweep_accelerations(double period, double stroke, const std::vector<double>& a2,
                         const std::vector<double>& a3, const SweepOptions& options,
                         const AccelerationSink& sink);

/// A family of table profiles indexed by period Δt and stroke Δy (Figs. 4, 5).
class ProfileFamily {
 public:
  virtual ~ProfileFamily() = default;
  /// The member with this period and stroke, or nullptr when it does not exist (case 0).
  virtual std::unique_ptr<TableProfile> make(double period, double stroke) const = 0;
  virtual std::string name() const = 0;
};

/// Three-phase profiles with fixed accelerations (y2'', y3'').
class ThreePhaseFamily final : public ProfileFamily {
 public:
  ThreePhaseFamily(double a2, double a3);
  std::unique_ptr<TableProfile> make(double period, double stroke) const override;
  std::string name() const override { return "three-phase"; }
  double a2() const noexcept { return a2_; }
  double a3() const noexcept { return a3_; }

 private:
  double a2_, a3_;
};

/// Jerk-limited three-phase profiles (trapezoidal acceleration) with fixed (y2'', y3'') and
/// jerk limit j; a member that does not exist (case 0, e.g. a jerk too low for the period
/// and stroke) is nullptr.
class JerkLimitedThreePhaseFamily final : public ProfileFamily {
 public:
  /// \param jerk j > 0 [-] (+inf: the ThreePhaseFamily). Throws InvalidParameter otherwise.
  JerkLimitedThreePhaseFamily(double a2, double a3, double jerk);
  std::unique_ptr<TableProfile> make(double period, double stroke) const override;
  std::string name() const override { return "jerk-limited-three-phase"; }
  double a2() const noexcept { return a2_; }
  double a3() const noexcept { return a3_; }
  double jerk() const noexcept { return jerk_; }

 private:
  double a2_, a3_, jerk_;
};

/// One shape of piecewise-polynomial acceleration (a Fig. 3 style sequence of quadratics),
/// stretched in time to the period and scaled in amplitude to the stroke: durations scale with
/// Δt, accelerations with Δy / Δt^2 (and a finite jerk with Δy / Δt^3).
class ScaledShapeFamily final : public ProfileFamily {
 public:
  explicit ScaledShapeFamily(PiecewisePolynomialProfile shape);
  /// The default shape: three-phase-like fractions (0.35, 0.35, 0.30) of the period with
  /// accelerations (0, -6/7, +1), i.e. velocity-periodic (0.35·6/7 = 0.30·1).
  static ScaledShapeFamily paper_like();
  std::unique_ptr<TableProfile> make(double period, double stroke) const override;
  std::string name() const override { return "scaled-shape"; }
  const PiecewisePolynomialProfile& shape() const noexcept { return shape_; }

 private:
  PiecewisePolynomialProfile shape_;
};

/// One Fourier shape (Sect. 4.4.2) with its coefficients scaled to the stroke: the members
/// share the harmonic content and differ in period and amplitude. Steady states of these
/// profiles use the exact smooth-profile solver (simulate/smooth_exact.hpp).
class ScaledFourierFamily final : public ProfileFamily {
 public:
  /// Coefficients of y(t) = sum A_k cos(k w t) + B_k sin(k w t), any amplitude (rescaled).
  ScaledFourierFamily(std::vector<double> cos_coeffs, std::vector<double> sin_coeffs);
  std::unique_ptr<TableProfile> make(double period, double stroke) const override;
  std::string name() const override { return "scaled-fourier"; }
  const std::vector<double>& cos_coeffs() const noexcept { return cos_; }
  const std::vector<double>& sin_coeffs() const noexcept { return sin_; }

 private:
  std::vector<double> cos_, sin_;
  double unit_stroke_;  // stroke of the given coefficients
};

/// One point of an f(Δt) or f(Δy) study.
struct FamilyPoint {
  double period = 0, stroke = 0;                         ///< Δt, Δy [-]
  bool physical = false;                                 ///< false: the family has no member
  StickSlipCase observed = StickSlipCase::non_physical;  ///< a posteriori case
  double v_bar = 0, f = 0;                               ///< eqs. (10), (11) [-]
  /// Empty when the point was computed; otherwise why it could not be (v̄ and f are NaN).
  std::string failure;
};

/// f against Δt at fixed Δy (Fig. 4).
std::vector<FamilyPoint> sweep_period(const ProfileFamily& family, double stroke,
                                      const std::vector<double>& periods,
                                      const SweepOptions& options = {});
/// f against Δy at fixed Δt (Fig. 5).
std::vector<FamilyPoint> sweep_stroke(const ProfileFamily& family, double period,
                                      const std::vector<double>& strokes,
                                      const SweepOptions& options = {});

}  // namespace selfalign
