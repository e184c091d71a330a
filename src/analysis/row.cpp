#include "selfalign/analysis/row.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <variant>

#include "selfalign/core/step.hpp"
#include "selfalign/error.hpp"

namespace selfalign {

namespace row_analysis {

constexpr double kRowNaN = std::numeric_limits<double>::quiet_NaN();

// Each part's last motion: the end of its last piece that moved.
struct LastMotion final : MotionObserver {
  std::vector<double> last;
  void on_motion(const MotionInterval& p, const Arc*) override {
    if (p.x1 != p.x0 || p.xd0 != 0 || p.xd1 != 0) last[static_cast<std::size_t>(p.body)] = p.t1;
  }
};

// The queue advanced by one of the two solvers, on the same model.
class RowRunner {
 public:
  RowRunner(const core::Model& model, const RowQueue& q, const RowSolver& solver)
      : model_(model), exact_(solver.method == Method::exact) {
    std::vector<double> x, v;
    for (const RowPart& p : q.parts) x.push_back(p.x), v.push_back(p.v);
    watch_.last.assign(x.size(), kRowNaN);
    if (exact_) {
      exact_state_ = make_row_exact_state(model_, 0.0, x, v);
    } else {
      std::vector<PlanarPose> poses;
      std::vector<PlanarTwist> twists;
      for (std::size_t i = 0; i < x.size(); ++i)
        poses.push_back({x[i], 0, 0}), twists.push_back({v[i], 0, 0});
      core_state_ = core::make_state(model_, 0.0, poses, twists);
    }
  }
  void advance_to(double t) {
    if (exact_) {
      advance_row_exact(model_, exact_state_, t, &watch_);
    } else {
      const double h = model_.options.step;
      const auto target = static_cast<long long>(std::llround(t / h));
      core::step(model_, core_state_, target - core_state_.step_index, &watch_);
    }
  }
  double x(std::size_t i) const { return exact_ ? exact_state_.x[i] : core_state_.bodies[i].pose.x; }
  double v(std::size_t i) const { return exact_ ? exact_state_.v[i] : core_state_.bodies[i].twist.ux; }
  std::size_t size() const { return model_.bodies.size(); }
  double gap(std::size_t j) const {
    const core::PartContact& pc = model_.part_contacts[j];
    return core::part_gap(model_, pc, x(static_cast<std::size_t>(pc.rear)),
                          x(static_cast<std::size_t>(pc.front)));
  }
  bool touching(std::size_t j) const {
    return exact_ ? exact_state_.touching[j] != 0 : gap(j) <= kRowTouchGap;
  }
  long long collisions() const { return exact_ ? exact_state_.statistics.collisions : 0; }
  long long separations() const { return exact_ ? exact_state_.statistics.separations : 0; }
  const std::vector<double>& last_motion() const { return watch_.last; }

 private:
  const core::Model& model_;
  bool exact_;
  RowExactState exact_state_;
  core::State core_state_;
  LastMotion watch_;
};

void check_run(const RowSolver& solver, long long periods, long long samples, const char* name) {
  if (solver.method != Method::exact && solver.method != Method::time_stepping)
    throw InvalidParameter("method", to_string(solver.method), "must be exact or time-stepping");
  if (!(periods >= 1 && periods <= 100'000'000)) throw InvalidParameter(name, periods, "must be in [1, 1e8]");
  if (!(samples >= 1 && samples <= 100'000))
    throw InvalidParameter("samples_per_period", samples, "must be in [1, 100000]");
}

void sample(const RowRunner& r, double t, std::vector<double>& times,
            std::vector<std::vector<double>>& positions) {
  times.push_back(t);
  std::vector<double> row(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) row[i] = r.x(i);
  positions.push_back(std::move(row));
}

// The model's step: Moreau's (the exact solver does not read it).
long long model_steps(const RowSolver& solver) {
  return solver.method == Method::exact ? 1 : solver.steps_per_period;
}

// Period p (from 1) of the run, sampled `samples` times; it ends exactly at p T.
void run_period(RowRunner& r, long long p, double T, long long samples, std::vector<double>& times,
                std::vector<std::vector<double>>& positions) {
  for (long long k = 1; k <= samples; ++k) {
    const double t = T * (static_cast<double>(p - 1) + static_cast<double>(k) / static_cast<double>(samples));
    r.advance_to(k == samples ? T * static_cast<double>(p) : t);
    sample(r, t, times, positions);
  }
}

}  // namespace row_analysis

using namespace row_analysis;

core::Model row_model(const TableProfile& profile, const RowQueue& q, const FrictionField* field,
                      long long steps_per_period) {
  if (q.parts.empty()) throw InvalidParameter("parts", "none", "needs at least one part");
  if (!(steps_per_period >= 1 && steps_per_period <= 1'000'000'000))
    throw InvalidParameter("steps_per_period", steps_per_period, "must be in [1, 1e9]");
  PlanarTableMotion motion;
  motion.first = &profile;
  core::Model m{motion, UniformPlanarField{}, {}, {profile.period() / static_cast<double>(steps_per_period), 0.5}};
  if (field) m.field = AxisField{*field};
  for (std::size_t i = 0; i < q.parts.size(); ++i) {
    const RowPart& p = q.parts[i];
    const std::string name = "parts[" + std::to_string(i) + "]";
    if (!(p.length > 0 && p.length <= 1e50)) throw InvalidParameter(name + ".length", p.length, "must be in (0, 1e50]");
    if (!(p.mass > 0 && p.mass <= 1e50)) throw InvalidParameter(name + ".mass", p.mass, "must be in (0, 1e50]");
    if (p.law.velocity_dependent())
      throw InvalidParameter(name + ".law", "velocity-dependent", "a part of a queue takes a Coulomb law");
    if (!std::isfinite(p.x)) throw InvalidParameter(name + ".x", p.x, "must be finite");
    if (!std::isfinite(p.v)) throw InvalidParameter(name + ".v", p.v, "must be finite");
    if (i > 0 && !((p.x - p.length) - q.parts[i - 1].x >= 0))
      throw InvalidParameter(name + ".x", p.x,
                             "overlaps parts[" + std::to_string(i - 1) +
                                 "]: x - length must be >= the rear part's x (" +
                                 std::to_string(q.parts[i - 1].x) + ")");
    core::SliderBody b;
    b.law = p.law;
    b.mass = p.mass;
    b.length = p.length;
    m.bodies.push_back(b);
    if (i > 0) m.part_contacts.push_back({static_cast<int>(i - 1), static_cast<int>(i), q.restitution});
  }
  if (!(q.restitution >= 0 && q.restitution <= 1))
    throw InvalidParameter("restitution", q.restitution, "must be in [0, 1]");
  core::validate(m);
  return m;
}

RowRun row_run(const TableProfile& profile, const RowQueue& queue, const FrictionField* field,
               long long periods, const RowSolver& solver, long long samples_per_period) {
  check_run(solver, periods, samples_per_period, "periods");
  const core::Model model = row_model(profile, queue, field, model_steps(solver));
  RowRunner r(model, queue, solver);
  const double T = profile.period();
  const std::size_t n = r.size();
  RowRun out;
  sample(r, 0.0, out.times, out.positions);
  std::vector<double> before(n);
  for (long long p = 1; p <= periods; ++p) {
    for (std::size_t i = 0; i < n; ++i) before[i] = r.x(i);
    run_period(r, p, T, samples_per_period, out.times, out.positions);
  }
  out.queue_velocity = 0;
  for (std::size_t i = 0; i < n; ++i) {
    out.x.push_back(r.x(i));
    out.v.push_back(r.v(i));
    out.mean_velocity.push_back((r.x(i) - before[i]) / T);
    out.queue_velocity += out.mean_velocity.back() / static_cast<double>(n);
  }
  int size = 1;
  for (std::size_t j = 0; j + 1 < n; ++j) {
    if (r.touching(j)) ++size;
    else out.clusters.push_back(size), size = 1;
  }
  out.clusters.push_back(size);
  out.pitch = n > 1 ? (queue.parts.back().x - queue.parts.front().x) / static_cast<double>(n - 1) : kRowNaN;
  out.throughput_per_period = n > 1 ? out.queue_velocity * T / out.pitch : kRowNaN;
  out.collisions = r.collisions();
  out.separations = r.separations();
  return out;
}

RowStop row_stop(const TableProfile& profile, const RowQueue& queue, const FrictionField& field,
                 long long max_periods, const RowSolver& solver, long long samples_per_period) {
  check_run(solver, max_periods, samples_per_period, "max_periods");
  const core::Model model = row_model(profile, queue, &field, model_steps(solver));
  RowRunner r(model, queue, solver);
  const double T = profile.period();
  const std::size_t n = r.size();
  RowStop out;
  sample(r, 0.0, out.times, out.positions);
  std::vector<double> before(n);
  for (long long p = 1; p <= max_periods && !out.stopped; ++p) {
    for (std::size_t i = 0; i < n; ++i) before[i] = r.x(i);
    const std::vector<double> last_before = r.last_motion();
    run_period(r, p, T, samples_per_period, out.times, out.positions);
    out.periods = p;
    // held through the whole period: no part's last motion changed, every part at rest
    bool held = true;
    for (std::size_t i = 0; i < n && held; ++i) {
      const double a = r.last_motion()[i], b = last_before[i];
      held = r.x(i) == before[i] && r.v(i) == 0 && (a == b || (std::isnan(a) && std::isnan(b)));
    }
    out.stopped = held;
  }
  const std::vector<double>& last = r.last_motion();
  out.stop_time = kRowNaN;
  if (out.stopped) {
    out.stop_time = 0;
    for (const double t : last)
      if (!std::isnan(t)) out.stop_time = std::max(out.stop_time, t);
  }
  const double step = field.nodes().front().position;
  double ahead = 0;  // lengths of the parts ahead of part i
  out.error.assign(n, 0);
  for (std::size_t q = n; q-- > 0;) {
    out.error[q] = r.x(q) - (step - ahead);
    ahead += queue.parts[q].length;
  }
  out.accumulated = true;
  for (std::size_t i = 0; i < n; ++i) {
    out.x.push_back(r.x(i));
    out.process_time.push_back(last[i]);
    if (i > 0) {
      out.gaps.push_back(r.gap(i - 1));
      out.accumulated = out.accumulated && out.gaps.back() <= kRowTouchGap;
    }
  }
  out.collisions = r.collisions();
  out.separations = r.separations();
  return out;
}

}  // namespace selfalign
