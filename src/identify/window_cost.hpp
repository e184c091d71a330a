#pragma once
// One shooting window's residuals and their central-difference Jacobian, for Ceres (the local
// stage) and for the covariance (one rule for both). Internal to src/identify.

#include <ceres/cost_function.h>

#include <cstddef>
#include <span>
#include <vector>

#include "shooting.hpp"

namespace selfalign::identify_detail {

/// Central-difference step of a parameter of value v: 1e-6 max(|v|, floor) (the square root
/// of the solver's 1e-12 relative rounding is the usual choice for central differences of a
/// smooth function; the exact solver is accurate to rounding, and the step straddles an
/// event where the stick/slip sequence changes, giving the mean of the one-sided slopes).
inline constexpr double kRelativeStep = 1e-6;

/// Central differences (the covariance) or forward ones (the local stage: half the model
/// evaluations; the estimate depends on the residuals, not on the Jacobian's accuracy).
/// Parameter blocks of a window: theta (model parameters, p), tau (1: the run's offset), the
/// window's state (2: x, v at its first sample, data units).
class WindowCost final : public ceres::CostFunction {
 public:
  /// `floors` are the absolute step floors of theta, then tau, then x and v.
  WindowCost(const ShootingRun& run, const Window& window, std::size_t p,
             std::vector<double> floors, bool central = true);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

  /// Residuals at the given blocks; false where the model cannot be built or advanced.
  bool residuals(const double* theta, double tau, const double* state, double* r) const;

 private:
  const ShootingRun& run_;
  Window window_;
  std::size_t p_;
  std::vector<double> floors_;
  bool central_;
};

}  // namespace selfalign::identify_detail
