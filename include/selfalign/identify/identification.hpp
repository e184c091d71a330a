#pragma once
/// \file identification.hpp
/// Friction identified from measured motion (issue 25; docs/identification.md): the model's
/// free parameters (a subset of its parameter view, io/parameter_view.hpp) fitted by least
/// squares of predicted minus measured positions, with multiple shooting.
///
/// The fit, per docs/identification.md:
///   - each run's samples are cut into shooting windows of `window_periods` table periods;
///     each window restarts from its own state (x_k, v_k) at its first sample, estimated with
///     the parameters (2 nuisance parameters per window), so a small error in mu does not
///     accumulate into a large phase error over the run;
///   - the residual of sample i in window k is x_model(t_i + tau_r; theta, x_k, v_k) - x_i [m],
///     x_model from the config's solver (the exact solver wherever it applies);
///   - global stage: NLopt MLSL with low-discrepancy starts (GN_MLSL_LDS, local LN_BOBYQA)
///     over the bounds of the free parameters, the window states fixed at estimates from the
///     data (a local line fit at each window's start);
///   - local stage: Ceres' Levenberg-Marquardt with the Schur complement over the window
///     states (the bundle-adjustment structure: theta shared, one small block per window), a
///     robust loss on request; derivatives by central differences, which straddle the
///     events where the stick/slip sequence changes (the objective is continuous there);
///   - covariance sigma^2 (J^T J)^-1 of the parameters with the window states eliminated
///     (the Schur complement), sigma^2 = RSS / (samples - estimated parameters);
///   - a parameter whose column of J is zero or lies in the span of the others (relative
///     singular value below kIdentifiabilityTolerance) is reported not identifiable, with the
///     reason when the data show it (the part never sticks: mu_static; the part never
///     reaches the rough region: c_mu, x_mu, width);
///   - profile likelihood for the chosen parameters: the others refitted at each of a grid of
///     values, the interval where RSS rises by at most chi2_1(confidence) sigma^2.

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "selfalign/io/measured_motion.hpp"
#include "selfalign/io/simulate_config.hpp"

namespace selfalign {

/// One measured run and the model of that run (its drive settings): the config's units are
/// the data's (SI configs take the data in SI; a dimensionless config takes the data's
/// numbers as model units). x is the part's position relative to the table (the model's x).
struct IdentificationRun {
  MeasuredMotion data;
  SimulateConfig config;
};

/// The loss on each residual r [m]: squared (least squares), or a robust one with scale s [m]
/// (Ceres' HuberLoss / CauchyLoss: quadratic below s).
struct SquaredLoss {};
struct HuberLoss {
  double scale;
};
struct CauchyLoss {
  double scale;
};
using IdentificationLoss = std::variant<SquaredLoss, HuberLoss, CauchyLoss>;

/// The name of the time offset between the data and the model (one per run, in seconds of
/// the data: the model's time is t_data + offset), a nuisance parameter in `free`.
inline constexpr const char* kTimeOffset = "time_offset";

/// Relative singular value (of J with columns scaled to unit norm, window states eliminated)
/// below which a parameter is not identifiable: 1e-6, far below the 1e-3 .. 1 of the runs in
/// the tests and far above the 1e-10 a column that is zero up to finite-difference rounding
/// gives.
inline constexpr double kIdentifiabilityTolerance = 1e-6;

/// The default box of a free parameter about its config value v: v (1 -+ 0.3), the 10-20 %
/// a friction coefficient is typically known to, with margin.
inline constexpr double kDefaultBoxWidth = 0.3;

struct IdentificationBounds {
  double lower;
  double upper;
};

struct IdentificationOptions {
  /// Names free in the fit: parameters of the model's view (mu_static, mu, mu_backward,
  /// stribeck_velocity, c_mu, x_mu, width, amplitude_scale, ...) and kTimeOffset. The initial
  /// state (t0, x0, v0) is not a name here: every window's state is estimated.
  std::vector<std::string> free;
  /// The global stage's box per free parameter (also Ceres' bounds); a name without one gets
  /// v (1 -+ kDefaultBoxWidth) about its config value v ([-1, 1] for v = 0), and time_offset
  /// [-period/2, period/2] (the first run's period).
  std::map<std::string, IdentificationBounds> bounds;
  double window_periods = 2;             ///< shooting window length [table periods], > 0
  IdentificationLoss loss = SquaredLoss{};
  int starts = 16;  ///< global stage: MLSL starting points (0: skip it; start at the config)
  int global_evaluations = 4000;  ///< global stage budget of objective evaluations (each one
                                  ///< pass of position-reset shooting over the data)
  int max_iterations = 100;      ///< Levenberg-Marquardt iterations
  /// Parameters whose profile likelihood is computed (free and identifiable ones only).
  std::vector<std::string> profile;
  int profile_points = 13;  ///< grid points per profile, >= 3 (odd: the estimate is one)
  double confidence = 0.95;  ///< of the intervals, in (0, 1)
  int threads = 2;           ///< Ceres' evaluation threads, >= 1
};

struct IdentifiedParameter {
  std::string name;
  double initial = 0;   ///< the value the fit started from (config or global stage)
  double estimate = 0;  ///< NaN when not identifiable
  double standard_error = 0;  ///< NaN when not identifiable
  double lower = 0, upper = 0;  ///< Wald interval estimate -+ z se (NaN: not identifiable)
  /// Profile-likelihood interval (NaN when not profiled, or an end beyond the grid).
  double profile_lower = 0, profile_upper = 0;
  bool identifiable = true;
  std::string reason;  ///< why not identifiable (empty when it is)
};

/// RSS of the refit with one parameter held at each value of a grid.
struct ProfileLikelihood {
  std::string name;
  std::vector<double> values;
  std::vector<double> rss;  ///< [m^2]; NaN where the model cannot be built (e.g. mu_s < mu)
};

/// One run's fit: the data, the model's positions at the estimate, per sample.
struct FittedRun {
  std::string source;
  std::vector<double> t, x_measured, x_fitted, residual;  ///< [s], [m], [m], [m]
  std::vector<int> window;          ///< the sample's shooting window (0-based, per run)
  std::vector<unsigned char> stick; ///< 1 where the fitted part sticks on the table
  double time_offset = 0;           ///< [s] (0 unless free)
  double time_offset_standard_error = 0;  ///< [s] (NaN unless free)
  double rms = 0;                   ///< of this run's residuals [m]
  std::size_t skipped = 0;          ///< rows the data file skipped (a missing value)
};

struct Identification {
  std::vector<IdentifiedParameter> parameters;  ///< in the order of options.free (not offsets)
  /// Covariance of the parameters, row-major n x n (n = parameters.size()); rows and columns
  /// of a parameter that is not identifiable are NaN.
  std::vector<double> covariance;
  std::vector<double> correlation;  ///< as covariance, unit diagonal
  std::vector<ProfileLikelihood> profiles;
  std::vector<FittedRun> runs;
  std::size_t samples = 0;    ///< residuals
  std::size_t windows = 0;    ///< shooting windows, all runs
  std::size_t estimated = 0;  ///< parameters estimated: free + offsets + 2 per window
  double rss = 0;             ///< sum of squared residuals [m^2]
  double sigma = 0;           ///< sqrt(rss / (samples - estimated)) [m]
  double max_abs_residual = 0;  ///< [m]
  double z = 0;               ///< the normal quantile of the intervals
  int iterations = 0;         ///< Levenberg-Marquardt iterations
  bool converged = false;
  std::string termination;    ///< Ceres' message
  double global_best_rss = 0; ///< best RSS the global stage found (NaN when skipped)
  int global_evaluations = 0;
  std::vector<std::string> warnings;  ///< plain-text warnings (identifiability, convergence)
};

/// Fits the free parameters to the runs. Throws InvalidParameter naming: a free name that is
/// not a parameter of a run's model (or is t0, x0, v0), a repeated one, no free parameter,
/// bad options, bounds that do not contain the starting value, fewer samples than estimated
/// parameters (naming the data file), a window the data cannot fill. Results that are
/// expected outcomes (a parameter not identifiable, a fit that did not converge) are in the
/// result, not thrown.
Identification identify(const std::vector<IdentificationRun>& runs,
                        const IdentificationOptions& options);

}  // namespace selfalign
