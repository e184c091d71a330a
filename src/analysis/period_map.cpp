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

namespace {
// PeriodMap's request: the best solver the problem allows, time-stepping on steps_per_period.
StepperRequest map_request(const PeriodMapOptions& o) {
  StepperRequest r;
  r.integrator = o.integrator;
  r.stepping = {0.0, o.theta};
  r.steps_per_period = o.steps_per_period;
  return r;
}
}  // namespace

PeriodMap::PeriodMap(const TableProfile& profile, const FrictionLaw& law,
                     const PeriodMapOptions& options)
    : profile_(profile),
      owned_(std::make_unique<UniformFriction>(1.0)),
      friction_(owned_.get()),
      law_(law),
      options_(options),
      stepper_(choose_stepper(profile_, *friction_, law_, map_request(options_))) {}

PeriodMap::PeriodMap(const TableProfile& profile, const FrictionMap& friction,
                     const FrictionLaw& law, const PeriodMapOptions& options)
    : profile_(profile),
      friction_(&friction),
      law_(law),
      options_(options),
      stepper_(choose_stepper(profile_, *friction_, law_, map_request(options_))) {}

const TimeSteppingOptions& PeriodMap::stepping() const noexcept {
  static const TimeSteppingOptions none{0.0, 0.5};
  const auto* ts = std::get_if<TimeSteppingSetup>(&stepper_);
  return ts ? ts->options : none;
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
  const auto* exact = std::get_if<ExactSetup>(&stepper_);
  if (!exact)
    throw InvalidParameter("profile", profile_.kind(),
                           "needs a piecewise-constant or piecewise-linear table acceleration and a "
                           "piecewise-affine friction level for the exact solver");
  return *exact;
}

ObjectState PeriodMap::operator()(double x0, double v0, ArcSink* sink,
                                  MotionCensus* census) const {
  if (sink && !has_arcs())  // a sink would stay empty (D22, D27)
    throw InvalidParameter("method", to_string(method()),
                           "has no closed-form arcs: only the exact solvers deliver them");
  const double P = profile_.period();
  StepperState state = make_state(stepper_, {0, x0, v0});
  // The census listens to the arcs (closed forms), the intervals (integrator) or the steps
  // (time-stepping); the map itself goes through the one advance().
  if (census) {
    if (const auto* integrator = std::get_if<IntegratorSetup>(&stepper_)) {
      IntervalCensus intervals;
      intervals.census = census;
      IntegratorStatistics stats;
      advance_integrated(*integrator, std::get<ObjectState>(state), P, &intervals, &stats);
      add(stats);
      return object_of(state);
    }
    if (const auto* ts = std::get_if<TimeSteppingSetup>(&stepper_)) {
      SampleCensus samples;
      samples.census = census;
      advance_time_stepping(ts->profile, ts->friction, ts->law, ts->options,
                            std::get<TimeSteppingState>(state), options_.steps_per_period,
                            &samples);
      return object_of(state);
    }
    CensusSink both;
    both.inner = sink;
    both.census = census;
    advance(stepper_, state, P, &both);
    return object_of(state);
  }
  IntegratorStatistics stats;
  advance(stepper_, state, P, sink, &stats);
  if (method() == Method::integrator) add(stats);
  return object_of(state);
}

std::vector<Arc> PeriodMap::arcs(double x0, double v0) const {
  if (!has_arcs()) exact_setup();  // throws, naming the profile
  ArcList list;
  StepperState state = make_state(stepper_, {0, x0, v0});
  advance(stepper_, state, profile_.period(), &list);
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

PeriodMap::Run::Run(const PeriodMap& map, const ObjectState& start)
    : map_(&map), state_(make_state(map.stepper_, start)) {}

const ExactState& PeriodMap::Run::exact_state() const noexcept {
  static const ExactState none{};
  const auto* exact = std::get_if<ExactState>(&state_);
  return exact ? *exact : none;
}

const ObjectState& PeriodMap::Run::advance_to(double t_end, IntervalSink* sink,
                                              std::span<const double> watch) {
  const auto* integrator = std::get_if<IntegratorSetup>(&map_->stepper_);
  if (!integrator)
    throw InvalidParameter("method", to_string(map_->method()),
                           "intervals and watched crossings come from the slip integrator only");
  IntegratorStatistics stats;
  advance_integrated(*integrator, std::get<ObjectState>(state_), t_end, sink, &stats, watch);
  map_->add(stats);
  return state();
}

const ObjectState& PeriodMap::Run::advance_to(double t_end, ArcSink* sink) {
  IntegratorStatistics stats;
  advance(map_->stepper_, state_, t_end, sink, &stats);
  if (map_->method() == Method::integrator) map_->add(stats);
  return state();
}

}  // namespace selfalign
