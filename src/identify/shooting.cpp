// Multiple shooting for identification: windows, cached models, a window's prediction.

#include "shooting.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <utility>

#include "selfalign/error.hpp"
#include "selfalign/units.hpp"

namespace selfalign::identify_detail {
namespace {

StepperRequest request_of(const SimulateModel& m) {
  StepperRequest r;
  r.method = m.options.method;
  r.integrator = m.options.integrator;
  r.stepping = TimeSteppingOptions{m.options.step, m.options.theta};
  return r;
}

std::shared_ptr<const BuiltModel> build(const ParameterView& view, std::span<const double> theta) {
  SimulateModel m = build_simulate_model(view.with({theta.begin(), theta.end()}));
  const Stepper stepper = choose_stepper(*m.profile, *m.friction, m.law, request_of(m));
  // The stepper borrows *m.profile and *m.friction, which stay where they are when m moves.
  auto b = std::make_shared<BuiltModel>(BuiltModel{std::move(m), stepper, InputUnits(), OutputUnits()});
  b->in = InputUnits(b->model.units, b->model.scales);
  b->out = b->model.output_units();
  return b;
}

}  // namespace

ShootingRun::ShootingRun(const IdentificationRun& run, const std::vector<std::string>& model_free)
    : data_(run.data), view_(run.config, model_free) {}

std::shared_ptr<const BuiltModel> ShootingRun::model_or_throw(std::span<const double> theta) const {
  std::vector<double> key(theta.begin(), theta.end());
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (auto it = cache_.find(key); it != cache_.end() && it->second) return it->second;
  }
  auto b = build(view_, theta);
  std::lock_guard<std::mutex> lock(mutex_);
  // Bounded: an iteration asks for 2p + 1 values; old ones are not asked for again.
  if (cache_.size() >= 256) cache_.clear();
  cache_[std::move(key)] = b;
  return b;
}

std::shared_ptr<const BuiltModel> ShootingRun::model(std::span<const double> theta) const {
  try {
    return model_or_throw(theta);
  } catch (const std::exception&) {
    return nullptr;
  }
}

std::vector<Window> cut_windows(std::size_t run, std::span<const double> t, double length) {
  std::vector<Window> windows;
  std::size_t first = 0;
  double boundary = t.empty() ? 0 : t[0] + length;
  while (first < t.size()) {
    std::size_t end = first;
    while (end < t.size() && t[end] < boundary) ++end;
    boundary += length;
    if (end == first) continue;  // no sample in this span
    windows.push_back({run, first, end});
    first = end;
  }
  // Too short to fix their own state: merged into a neighbour (the one before, or after).
  for (std::size_t k = 0; k < windows.size() && windows.size() > 1;) {
    if (windows[k].end - windows[k].first >= kMinWindowSamples) {
      ++k;
      continue;
    }
    if (k > 0) {
      windows[k - 1].end = windows[k].end;
    } else {
      windows[1].first = windows[0].first;
    }
    windows.erase(windows.begin() + static_cast<long>(k));
  }
  return windows;
}

void estimate_window_state(const MeasuredMotion& data, const Window& w, double* state) {
  const std::size_t n = std::min<std::size_t>(5, w.end - w.first);
  const double t0 = data.t[w.first];
  double st = 0, sx = 0, stt = 0, stx = 0;
  for (std::size_t i = w.first; i < w.first + n; ++i) {
    const double dt = data.t[i] - t0;
    st += dt, sx += data.x[i], stt += dt * dt, stx += dt * data.x[i];
  }
  const double nn = static_cast<double>(n), det = nn * stt - st * st;
  const double v = n > 1 && det > 0 ? (nn * stx - st * sx) / det : 0.0;
  state[0] = (sx - v * st) / nn;
  state[1] = v;
}

bool predict_window(const BuiltModel& b, const MeasuredMotion& data, const Window& w, double tau,
                    const double* state, double* residuals, unsigned char* stick,
                    double* x_model, double next, double* next_state) {
  try {
    const ObjectState start{b.in(Dimension::time, data.t[w.first] + tau),
                            b.in(Dimension::length, state[0]), b.in(Dimension::velocity, state[1])};
    if (!std::isfinite(start.t) || !std::isfinite(start.x) || !std::isfinite(start.xd))
      return false;
    StepperState s = make_state(b.stepper, start);
    for (std::size_t i = w.first; i < w.end; ++i) {
      const double t = b.in(Dimension::time, data.t[i] + tau);
      if (i > w.first) advance(b.stepper, s, t);
      const ObjectState& o = object_of(s);
      const double x = b.out.length(o.x);
      if (!std::isfinite(x)) return false;
      residuals[i - w.first] = x - data.x[i];
      if (stick) stick[i - w.first] = o.xd == 0;
      if (x_model) x_model[i - w.first] = x;
    }
    if (next_state) {
      advance(b.stepper, s, b.in(Dimension::time, next + tau));
      next_state[0] = b.out.length(object_of(s).x);
      next_state[1] = b.out.velocity(object_of(s).xd);
    }
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

double reset_shooting(const BuiltModel& b, const MeasuredMotion& data,
                      std::span<const Window> windows, double tau, double* states) {
  double rss = 0;
  std::vector<double> r;
  for (std::size_t k = 0; k < windows.size(); ++k) {
    const Window& w = windows[k];
    double* state = states + 2 * k;
    const double v = state[1];
    estimate_window_state(data, w, state);
    if (k > 0) state[1] = v;  // the model's velocity at the end of the window before
    r.resize(w.end - w.first);
    double next[2];
    const bool more = k + 1 < windows.size();
    if (!predict_window(b, data, w, tau, state, r.data(), nullptr, nullptr,
                        more ? data.t[windows[k + 1].first] : 0.0, more ? next : nullptr))
      return std::numeric_limits<double>::quiet_NaN();
    for (double e : r) rss += e * e;
    if (more) states[2 * (k + 1) + 1] = next[1];
  }
  return rss;
}

}  // namespace selfalign::identify_detail
