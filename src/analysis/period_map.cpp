#include "selfalign/analysis/period_map.hpp"

#include <cmath>

#include "selfalign/error.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign {

namespace {

struct ArcList final : MotionObserver {
  std::vector<Arc> arcs;
  void on_motion(const MotionInterval&, const Arc* arc) override { arcs.push_back(*arc); }
};

// The census and the caller's observer, both fed every piece.
struct Both final : MotionObserver {
  MotionObserver* first;
  MotionObserver* second;
  Both(MotionObserver* a, MotionObserver* b) : first(a), second(b) {}
  void on_motion(const MotionInterval& piece, const Arc* arc) override {
    first->on_motion(piece, arc);
    if (second) second->on_motion(piece, arc);
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
  r.method = o.method;
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

ObjectState PeriodMap::operator()(double x0, double v0, MotionObserver* observer,
                                  MotionCensus* census) const {
  StepperState state = make_state(stepper_, {0, x0, v0});
  IntegratorStatistics stats;
  if (census) {
    census->begin_window();
    Both both(census, observer);
    advance(stepper_, state, profile_.period(), &both, &stats);
  } else {
    advance(stepper_, state, profile_.period(), observer, &stats);
  }
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
    case ArcEnd::time_step:  // (time steps have no arcs)
    case ArcEnd::part_contact:  // (rows have no arcs)
      break;
  }
  return s;
}

void SaltationProduct::on_motion(const MotionInterval&, const Arc* arc) {
  if (!arc)
    throw InvalidParameter("method", "not exact",
                           "saltation matrices need the closed-form arcs of an exact solver");
  add(*arc);
}

void SaltationProduct::add(const Arc& a) {
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
  for (const Arc& a : arcs(x0, v0)) product.add(a);
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

bool PeriodMap::Run::jump_periods(long long periods, double displacement) {
  auto* exact = std::get_if<ExactState>(&state_);
  if (!exact || periods < 1) return false;
  const PiecewisePolynomialProfile& p = map_->exact_setup().profile;
  const auto segs = p.segments();
  const auto at_switch = [&](long long n) {
    return static_cast<double>(n) * p.period() + segs[exact->segment].begin;
  };
  if (exact->object.t != at_switch(exact->period_index)) return false;
  exact->period_index += periods;
  exact->object.t = at_switch(exact->period_index);
  exact->object.x += displacement;
  return true;
}

const ObjectState& PeriodMap::Run::advance_to(double t_end, MotionObserver* observer,
                                              std::span<const double> watch) {
  IntegratorStatistics stats;
  advance(map_->stepper_, state_, t_end, observer, &stats, watch);
  if (map_->method() == Method::integrator) map_->add(stats);
  return state();
}

}  // namespace selfalign
