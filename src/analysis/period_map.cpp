#include "selfalign/analysis/period_map.hpp"

#include <cmath>

#include "selfalign/error.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign {

namespace {

struct ArcList final : ArcSink {
  std::vector<Arc> arcs;
  void on_arc(const Arc& a) override { arcs.push_back(a); }
};

struct CensusSink final : ArcSink {
  ArcSink* inner;
  MotionCensus* census;
  void on_arc(const Arc& a) override {
    if (census) census->on_arc(a);
    if (inner) inner->on_arc(a);
  }
};

// Time-stepping census: a stick counts once x' = 0 holds for two consecutive steps: a slip
// reversal can land one step on x' = 0 (|v*| <= h m while the velocity crosses zero), which is
// not a stick of the response.
struct SampleCensus final : StepSink {
  MotionCensus* census;
  int zero_run = 0;
  void on_step(const TimeSteppingState& s) override {
    const double v = s.object.xd;
    zero_run = v == 0 ? zero_run + 1 : 0;
    if (v != 0 || zero_run == 2) {
      Arc a;
      a.t0 = s.object.t;
      a.t1 = s.object.t + 1;  // a class sample, not a timed arc
      if (v != 0) a.shape = PolynomialArc{};
      a.direction = static_cast<std::int8_t>(v > 0 ? 1 : v < 0 ? -1 : 0);
      census->on_arc(a);
    }
  }
};

// The integrator's intervals as census samples (a class and a direction, no closed form).
struct IntervalCensus final : IntervalSink {
  MotionCensus* census;
  void on_interval(const MotionInterval& i) override {
    Arc a;
    a.t0 = i.t0;
    a.t1 = i.t1;
    if (i.direction != 0) a.shape = PolynomialArc{};
    a.direction = i.direction;
    census->on_arc(a);
  }
};

}  // namespace

void PeriodMap::add(const IntegratorStatistics& s) const {
  const std::lock_guard<std::mutex> lock(statistics_mutex_);
  statistics_ += s;
}

IntegratorStatistics PeriodMap::integrator_statistics() const {
  const std::lock_guard<std::mutex> lock(statistics_mutex_);
  return statistics_;
}

PeriodMap::PeriodMap(const TableProfile& profile, const FrictionLaw& law,
                     const PeriodMapOptions& options)
    : profile_(profile),
      owned_(std::make_unique<UniformFriction>(1.0)),
      friction_(owned_.get()),
      law_(law),
      options_(options) {
  choose_solver();
}

PeriodMap::PeriodMap(const TableProfile& profile, const FrictionMap& friction,
                     const FrictionLaw& law, const PeriodMapOptions& options)
    : profile_(profile), friction_(&friction), law_(law), options_(options) {
  choose_solver();
}

// Exact where a closed form exists: piecewise-polynomial acceleration on a piecewise-affine
// level, or a smooth motion on a piecewise-constant level; the slip integrator for a
// velocity-dependent law (piecewise-polynomial or smooth profiles on piecewise-affine levels)
// and for a smooth motion other than a Fourier series on a level with slopes; time-stepping
// otherwise.
void PeriodMap::choose_solver() {
  const PiecewisePolynomialProfile* pwp = profile_.piecewise_polynomial();
  const SmoothMotion* motion = profile_.smooth();
  const PiecewiseAffineFriction* affine = friction_->piecewise_affine();
  const bool closed_form = !law_.velocity_dependent();
  if (closed_form && pwp && affine) {
    exact_ = std::make_unique<ExactSetup>(ExactSetup{*pwp, *affine, law_});
  } else if (closed_form && motion && affine && smooth_solver_applies(*motion, *affine)) {
    smooth_ = std::make_unique<SmoothSetup>(SmoothSetup{*motion, *affine, law_});
  } else if (affine && integrable_profile(profile_)) {
    // A speed-dependent law, or a smooth motion on slopes the smooth solver cannot take.
    validate(options_.integrator);
    integrator_ = std::make_unique<IntegratorSetup>(
        IntegratorSetup{profile_, *affine, law_, options_.integrator});
  } else {
    if (options_.steps_per_period < 1)
      throw InvalidParameter("steps_per_period", options_.steps_per_period, "must be >= 1");
    stepping_ = {profile_.period() / options_.steps_per_period, options_.theta};
    validate(stepping_);
  }
}

const PiecewisePolynomialProfile& require_exact_profile(const TableProfile& profile,
                                                        const std::string& analysis) {
  const PiecewisePolynomialProfile* p = profile.piecewise_polynomial();
  if (!p)
    throw InvalidParameter("profile", profile.kind(),
                           analysis + " needs a piecewise-constant or piecewise-linear table "
                                      "acceleration");
  return *p;
}

const ExactSetup& PeriodMap::exact_setup() const {
  if (!exact_)
    throw InvalidParameter("profile", profile_.kind(),
                           "needs a piecewise-constant or piecewise-linear table acceleration and a "
                           "piecewise-affine friction level for the exact solver");
  return *exact_;
}

ObjectState PeriodMap::operator()(double x0, double v0, ArcSink* sink,
                                  MotionCensus* census) const {
  if (sink && !has_arcs())  // a sink would stay empty (D22, D27)
    throw InvalidParameter("method", to_string(method()),
                           "has no closed-form arcs: only the exact solvers deliver them");
  const double P = profile_.period();
  if (exact_) {
    ExactState s = make_exact_state(*exact_, {0, x0, v0});
    if (census) {
      CensusSink both;
      both.inner = sink;
      both.census = census;
      advance_exact(*exact_, s, P, &both);
    } else {
      advance_exact(*exact_, s, P, sink);
    }
    return s.object;
  }
  if (smooth_) {
    ObjectState s{0, x0, v0};
    CensusSink both;
    both.inner = sink;
    both.census = census;
    advance_smooth(*smooth_, s, P, census ? &both : sink);
    return s;
  }
  if (integrator_) {
    ObjectState s{0, x0, v0};
    IntervalCensus intervals;
    intervals.census = census;
    IntegratorStatistics stats;
    advance_integrated(*integrator_, s, P, census ? &intervals : nullptr, &stats);
    add(stats);
    return s;
  }
  TimeSteppingState s = make_time_stepping_state(profile_, {0, x0, v0});
  SampleCensus samples;
  samples.census = census;
  advance_time_stepping(profile_, *friction_, law_, stepping_, s, options_.steps_per_period,
                        census ? &samples : nullptr);
  return s.object;
}

std::vector<Arc> PeriodMap::arcs(double x0, double v0) const {
  ArcList list;
  if (smooth_) {
    ObjectState s{0, x0, v0};
    advance_smooth(*smooth_, s, profile_.period(), &list);
    return std::move(list.arcs);
  }
  const ExactSetup& setup = exact_setup();
  ExactState s = make_exact_state(setup, {0, x0, v0});
  advance_exact(setup, s, profile_.period(), &list);
  return std::move(list.arcs);
}

Eigen::Matrix2d saltation(const Arc& a, const Arc& next, const FrictionLaw& law) {
  Eigen::Matrix2d s = Eigen::Matrix2d::Identity();
  switch (a.end) {
    case ArcEnd::velocity_zero: {
      const double before = a.end_acceleration(), after = next.start_acceleration();
      s(1, 1) = next.kind() == ArcKind::stick || before == 0 ? 0.0 : after / before;
      break;
    }
    case ArcEnd::friction_boundary:
      if (a.xd1 != 0) s(1, 0) = (next.start_acceleration() - a.end_acceleration()) / a.xd1;
      break;
    case ArcEnd::stick_break: {
      // h = s m(x) - sign(A) A(t): dh/dx = s k, dh/dt = -sign(A) J along the stick (x' = 0).
      const double A = next.table_accel, J = a.table_jerk;
      const double k = next.slope;
      if (J != 0 && A != 0)
        s(1, 0) = -next.start_acceleration() * law.static_coefficient() * k /
                  (std::copysign(1.0, A) * J);
      break;
    }
    case ArcEnd::acceleration_switch:
    case ArcEnd::horizon:
      break;
  }
  return s;
}

void SaltationProduct::on_arc(const Arc& a) {
  if (count_ == 0) first_ = a;
  else product_ = saltation(last_, a, *law_) * product_;
  const Transition t = a.transition();
  Eigen::Matrix2d phi;
  phi << t.xx, t.xv, t.vx, t.vv;
  product_ = phi * product_;
  last_ = a;
  ++count_;
}

Eigen::Matrix2d SaltationProduct::finish(const Arc& next) const {
  return count_ ? Eigen::Matrix2d(saltation(last_, next, *law_) * product_) : product_;
}

Eigen::Matrix2d PeriodMap::saltation_monodromy(double x0, double v0) const {
  // The arc that follows the period's last one is the next period's first.
  SaltationProduct product(law_);
  for (const Arc& a : arcs(x0, v0)) product.on_arc(a);
  return product.finish_periodic();
}

Eigen::Matrix2d PeriodMap::finite_difference_monodromy(double x0, double v0, double h) const {
  Eigen::Matrix2d fd;
  for (int col = 0; col < 2; ++col) {
    const double dx = col == 0 ? h : 0, dv = col == 1 ? h : 0;
    const ObjectState plus = (*this)(x0 + dx, v0 + dv);
    const ObjectState minus = (*this)(x0 - dx, v0 - dv);
    fd(0, col) = (plus.x - minus.x) / (2 * h);
    fd(1, col) = (plus.xd - minus.xd) / (2 * h);
  }
  return fd;
}

PeriodMap::Run::Run(const PeriodMap& map, const ObjectState& start) : map_(&map) {
  if (map.exact_) exact_ = make_exact_state(*map.exact_, start);
  else if (map.smooth_ || map.integrator_) smooth_state_ = start;
  else stepping_ = make_time_stepping_state(map.profile_, start);
}

const ObjectState& PeriodMap::Run::state() const noexcept {
  return map_->exact_                        ? exact_.object
         : map_->smooth_ || map_->integrator_ ? smooth_state_
                                              : stepping_.object;
}

const ObjectState& PeriodMap::Run::advance_to(double t_end, IntervalSink* sink,
                                              std::span<const double> watch) {
  if (!map_->integrator_)
    throw InvalidParameter("method", to_string(map_->method()),
                           "intervals and watched crossings come from the slip integrator only");
  IntegratorStatistics stats;
  advance_integrated(*map_->integrator_, smooth_state_, t_end, sink, &stats, watch);
  map_->add(stats);
  return smooth_state_;
}

const ObjectState& PeriodMap::Run::advance_to(double t_end, ArcSink* sink) {
  // Only the exact solvers have arcs: a sink given to another would stay empty (D22: the
  // convergence analysis read past an empty arc list under a Stribeck law).
  if (sink && !map_->has_arcs())
    throw InvalidParameter("method", to_string(map_->method()),
                           "has no closed-form arcs: only the exact solvers deliver them");
  if (map_->exact_) {
    advance_exact(*map_->exact_, exact_, t_end, sink);
    return exact_.object;
  }
  if (map_->smooth_) {
    advance_smooth(*map_->smooth_, smooth_state_, t_end, sink);
    return smooth_state_;
  }
  if (map_->integrator_) {
    IntegratorStatistics stats;
    advance_integrated(*map_->integrator_, smooth_state_, t_end, nullptr, &stats);
    map_->add(stats);
    return smooth_state_;
  }
  const double h = map_->stepping_.step;
  const long long target = std::llround((t_end - stepping_.t0) / h);
  if (target > stepping_.step_index)
    advance_time_stepping(map_->profile_, *map_->friction_, map_->law_, map_->stepping_,
                          stepping_, target - stepping_.step_index);
  return stepping_.object;
}

}  // namespace selfalign
