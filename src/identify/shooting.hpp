#pragma once
// Multiple shooting for identification (docs/identification.md, "The fit"): the runs' samples
// cut into windows, the model of a run at given parameter values (built once per value and
// cached: Ceres' finite differences ask for the same 2p + 1 values across every window), and a
// window's prediction from its own start state. Internal to src/identify.

#include <cstddef>
#include <memory>
#include <mutex>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "selfalign/identify/identification.hpp"
#include "selfalign/io/parameter_view.hpp"
#include "selfalign/io/simulate_model.hpp"
#include "selfalign/simulate/stepper.hpp"

namespace selfalign::identify_detail {

/// The model of one run at one parameter value: the built model and its stepper (which
/// borrows the model's profile and friction map).
struct BuiltModel {
  SimulateModel model;
  Stepper stepper;
  InputUnits in;
  OutputUnits out;
};

/// A shooting window: samples [first, end) of run `run`.
struct Window {
  std::size_t run;
  std::size_t first;
  std::size_t end;
};

/// One run: its data, its parameter view over the free model parameters, and a cache of its
/// model by parameter value.
class ShootingRun {
 public:
  ShootingRun(const IdentificationRun& run, const std::vector<std::string>& model_free);

  const MeasuredMotion& data() const noexcept { return data_; }
  const ParameterView& view() const noexcept { return view_; }
  /// The model at `theta` (one value per model_free name); null when the model cannot be built
  /// there (a value out of its range: the fit treats that step as infeasible).
  std::shared_ptr<const BuiltModel> model(std::span<const double> theta) const;
  /// As model(), but throws what building throws (the starting values must be a model).
  std::shared_ptr<const BuiltModel> model_or_throw(std::span<const double> theta) const;

 private:
  MeasuredMotion data_;
  ParameterView view_;
  mutable std::mutex mutex_;
  mutable std::map<std::vector<double>, std::shared_ptr<const BuiltModel>> cache_;
};

/// The windows of one run: consecutive spans of `length` [data time] from its first sample;
/// a window with fewer than kMinWindowSamples samples is merged into a neighbour.
inline constexpr std::size_t kMinWindowSamples = 3;
std::vector<Window> cut_windows(std::size_t run, std::span<const double> t, double length);


/// A window's start state (x, v) in data units from the data: a least-squares line through
/// its first (up to) five samples, evaluated at its first sample.
void estimate_window_state(const MeasuredMotion& data, const Window& w, double* state);

/// Residuals x_model - x_data [data units] of window `w` from state (x, v) [data units] at its
/// first sample, with the model's time t_data + tau; `stick` (optional) gets 1 per sample in
/// stick. False when the model cannot advance (a state out of range). With `next` (a data
/// time after the window), `next_state` gets the model's (x, v) there [data units].
bool predict_window(const BuiltModel& b, const MeasuredMotion& data, const Window& w, double tau,
                    const double* state, double* residuals, unsigned char* stick = nullptr,
                    double* x_model = nullptr, double next = 0, double* next_state = nullptr);

/// The windows' start states of `windows` (one run's, consecutive) by position-reset shooting:
/// each window starts at the data's position estimate (estimate_window_state) with the
/// velocity the model has at its start when the window before is run from its own start (the
/// first window takes the data's velocity estimate). Consistent with the model at theta, so
/// the velocity is not the noisy difference of measured positions. Writes 2 per window into
/// states; returns the RSS of those windows (NaN when the model fails).
double reset_shooting(const BuiltModel& b, const MeasuredMotion& data,
                      std::span<const Window> windows, double tau, double* states);

}  // namespace selfalign::identify_detail
