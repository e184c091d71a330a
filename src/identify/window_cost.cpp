// One shooting window's residuals and central-difference Jacobian.

#include "window_cost.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace selfalign::identify_detail {

WindowCost::WindowCost(const ShootingRun& run, const Window& window, std::size_t p,
                       std::vector<double> floors, bool central)
    : run_(run), window_(window), p_(p), floors_(std::move(floors)), central_(central) {
  set_num_residuals(static_cast<int>(window.end - window.first));
  mutable_parameter_block_sizes()->assign({static_cast<int>(p), 1, 2});
}

bool WindowCost::residuals(const double* theta, double tau, const double* state,
                           double* r) const {
  const auto model = run_.model(std::span<const double>(theta, p_));
  return model && predict_window(*model, run_.data(), window_, tau, state, r);
}

bool WindowCost::Evaluate(double const* const* parameters, double* r, double** jacobians) const {
  const std::size_t n = window_.end - window_.first;
  std::vector<double> theta(parameters[0], parameters[0] + p_);
  double tau = parameters[1][0];
  double state[2] = {parameters[2][0], parameters[2][1]};
  if (!residuals(theta.data(), tau, state, r)) return false;
  if (!jacobians) return true;
  std::vector<double> plus(n), minus(n);
  // Column j of block b, by central differences in the one coordinate `value` points at.
  auto column = [&](double* value, std::size_t floor_index, double* jac, int stride, int col) {
    const double v = *value;
    const double h = kRelativeStep * std::max(std::abs(v), floors_[floor_index]);
    *value = v + h;
    bool ok_plus = residuals(theta.data(), tau, state, plus.data());
    bool ok_minus = false;
    if (central_ || !ok_plus) {
      *value = v - h;
      ok_minus = residuals(theta.data(), tau, state, minus.data());
    }
    *value = v;
    if (!ok_plus && !ok_minus) return false;
    // One-sided at the edge of the model's range (a bound such as mu_static >= mu).
    const double* hi = ok_plus ? plus.data() : r;
    const double* lo = ok_minus ? minus.data() : r;
    const double width = (ok_plus ? h : 0.0) + (ok_minus ? h : 0.0);
    for (std::size_t i = 0; i < n; ++i) jac[i * stride + col] = (hi[i] - lo[i]) / width;
    return true;
  };
  if (jacobians[0])
    for (std::size_t j = 0; j < p_; ++j)
      if (!column(&theta[j], j, jacobians[0], static_cast<int>(p_), static_cast<int>(j)))
        return false;
  if (jacobians[1] && !column(&tau, p_, jacobians[1], 1, 0)) return false;
  if (jacobians[2])
    for (int j = 0; j < 2; ++j)
      if (!column(&state[j], p_ + 1 + j, jacobians[2], 2, j)) return false;
  return true;
}

}  // namespace selfalign::identify_detail
