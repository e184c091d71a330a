#include "selfalign/simulate/slip_integrator.hpp"
#include "selfalign/simulate/stick_slip_decision.hpp"

#include <algorithm>
#include <array>
#include <boost/math/tools/toms748_solve.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

#include "selfalign/error.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/simulate/exact.hpp"
#include "arc_events.hpp"
#include "smooth_stick.hpp"

namespace selfalign {

namespace {

namespace odeint = boost::numeric::odeint;
using State = std::array<double, 2>;  // (x, x')
using detail::kInf;
constexpr int kSamplesPerStep = 4;         // sign checks of every step's dense output
constexpr double kMaxStepPerPeriod = 1.0 / 32;  // longest step, in table periods
// The work budget of one call is IntegratorOptions::max_steps_per_period times the table
// periods of its horizon (at least one period), for step attempts (accepted and rejected)
// and for intervals alike (D26).
constexpr int kEventPasses = 8;  // re-integrations that place a velocity zero (F06)
constexpr std::size_t kNoWatch = static_cast<std::size_t>(-1);

using detail::time_resolution;

// The table acceleration on one integration window, extended smoothly past the window's end:
// a segment's polynomial a0 + j (t - tb) of a piecewise-polynomial profile, or the smooth
// motion itself (one window without end).
class Forcing {
 public:
  explicit Forcing(const TableProfile& p)
      : pwp_(p.piecewise_polynomial()), smooth_(pwp_ ? nullptr : p.smooth()), period_(p.period()) {}

  // Opens the window that contains t (segments are closed on the left: y'' right-continuous)
  // and returns its end.
  double open(double t) {
    if (!pwp_) return kInf;
    const auto segs = pwp_->segments();
    double n = std::floor(t / period_);
    std::size_t i = pwp_->segment_at(t - n * period_);
    auto end_of = [&] {  // segment i of period n ends where the next begins
      return i + 1 < segs.size() ? n * period_ + segs[i + 1].begin : (n + 1) * period_;
    };
    for (int pass = 0; pass < 2 && !(end_of() - t > time_resolution(t)); ++pass)
      if (++i == segs.size()) i = 0, n += 1;  // t at a window's end up to rounding: the next
    const AccelerationSegment& s = segs[i];
    begin_ = n * period_ + s.begin;
    a0_ = s.accel;
    jerk_ = s.jerk;
    return end_of();
  }
  double accel(double t) const {
    return pwp_ ? a0_ + jerk_ * (t - begin_) : smooth_->derivatives(t)[2];
  }

  // The first time >= t at which y'' leaves [-ms, ms], or t_end (direction 0).
  detail::StickEnd stick_end(double ms, double t, double t_end) {
    if (!pwp_) return detail::smooth_stick_end(*smooth_, ms, t, t_end);
    for (double tc = t; tc < t_end;) {
      const double end = open(tc), a = accel(tc);
      if (const int slip = decide_at_rest(a, ms); slip != 0) return {tc, slip};
      if (jerk_ != 0) {  // y'' = a0 + j tau reaches sign(j) ms at tau (closed form)
        const double tb = begin_ + (std::copysign(ms, jerk_) - a0_) / jerk_;
        if (tb >= tc && tb < end) return tb < t_end ? detail::StickEnd{tb, jerk_ > 0 ? -1 : 1}
                                                    : detail::StickEnd{t_end, 0};
      }
      tc = end;
    }
    return {t_end, 0};
  }

 private:
  const PiecewisePolynomialProfile* pwp_;
  const SmoothMotion* smooth_;
  double period_, begin_ = 0, a0_ = 0, jerk_ = 0;
};

// The slip equation on one window: sigma, the friction piece (affine, extended) and the law.
struct SlipRhs {
  int sigma;
  const AffinePiece* piece;
  const FrictionLaw* law;
  const Forcing* forcing;
  long long* evaluations;
  void operator()(const State& s, State& d, double t) const {
    const double m = piece->bound(s[0]);
    d[0] = s[1];
    d[1] = -sigma * law->kinetic(sigma, std::abs(s[1])) * m - law->viscous() * s[1] -
           forcing->accel(t);
    ++*evaluations;
  }
};

// TOMS 748 refinement of a bracketed sign change of f on [a, b] (f(a) and f(b) of opposite
// signs or f(b) = 0) to 4 roundings of t.
template <class F>
double refine(F f, double a, double b) {
  if (!(a < b)) return b;  // a step shorter than the resolution of t (a stiff slip, D26)
  double fa = f(a), fb = f(b);
  if (fb == 0) return b;
  if (fa == 0) return a;
  std::uintmax_t iterations = 200;
  auto close = [](double lo, double hi) {
    return hi - lo <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(lo), std::abs(hi));
  };
  const auto r = boost::math::tools::toms748_solve(f, a, b, fa, fb, close, iterations);
  // The end on the event's side: f(hi) past the event (<= 0 for x', >= 0 for a boundary).
  return r.second;
}

// The budget is spent: names the parameter that most likely made the slip stiff (a viscous
// rate or a Stribeck slope far above the table's time scale), else the tolerances (D26).
// `budget` says what failed: the budget ("needs more than 1e6 ... per table period") or a
// state that left the finite numbers.
[[noreturn]] void fail_slip(const IntegratorSetup& setup, double m, const std::string& budget) {
  const FrictionLaw& law = setup.law;
  const double P = setup.profile.period();
  constexpr double kStiff = 1e5;  // stiffness x Δt beyond which an explicit step is the limit
  const double viscous = law.viscous() * P;
  // The Stribeck curve's slope at rest, (s - k) m / v_s for delta = 1 (steeper for delta < 1).
  const double k = std::min(law.kinetic_forward(), law.kinetic_backward());
  const double stribeck = law.stribeck_velocity() > 0
                              ? (law.static_coefficient() - k) * m / law.stribeck_velocity() * P
                              : 0.0;
  constexpr double kResolvable = 1e-14;  // tolerances below this ask more than doubles give
  const IntegratorOptions& o = setup.options;
  const bool unresolvable = o.relative_tolerance < kResolvable;
  if (!unresolvable && viscous >= stribeck && viscous > kStiff)
    throw InvalidParameter("viscous", law.viscous(),
                           budget + " (a stiff slip: c times the period = " +
                               format_number(viscous) + "); must keep c times the period below "
                               "about 3 max_steps_per_period = " +
                               format_number(3 * setup.options.max_steps_per_period));
  if (!unresolvable && stribeck > kStiff)
    throw InvalidParameter("stribeck_velocity", law.stribeck_velocity(),
                           budget + " (a stiff slip: the Stribeck slope (s - k) m / v_s times the "
                                    "period = " + format_number(stribeck) +
                               "); raise v_s or lower s - k");
  throw InvalidParameter("relative_tolerance", setup.options.relative_tolerance,
                         budget + "; the tolerances (relative " +
                             format_number(setup.options.relative_tolerance) + ", absolute " +
                             format_number(setup.options.absolute_tolerance) +
") may be below what double precision resolves, or too loose to follow the "
                             "slip: use values in [1e-14, 1e-3]");
}

[[noreturn]] void exceed_budget(const IntegratorSetup& setup, double m, const char* what) {
  fail_slip(setup, m, std::string("the slip integrator needs more than ") +
                          format_number(setup.options.max_steps_per_period) + " " + what +
                          " per table period here (max_steps_per_period)");
}

}  // namespace

void validate(const IntegratorOptions& o) {
  if (!(o.relative_tolerance > 0 && o.relative_tolerance < 1))
    throw InvalidParameter("relative_tolerance", o.relative_tolerance, "must be in (0, 1)");
  if (!(o.absolute_tolerance > 0 && o.absolute_tolerance < 1))
    throw InvalidParameter("absolute_tolerance", o.absolute_tolerance, "must be in (0, 1)");
  if (!(o.max_steps_per_period >= 1 && o.max_steps_per_period <= 1e9))
    throw InvalidParameter("max_steps_per_period", o.max_steps_per_period, "must be in [1, 1e9]");
}

IntegratorStatistics& IntegratorStatistics::operator+=(const IntegratorStatistics& o) noexcept {
  steps += o.steps;
  rejected += o.rejected;
  rhs_evaluations += o.rhs_evaluations;
  events += o.events;
  slips += o.slips;
  sticks += o.sticks;
  pivots += o.pivots;
  return *this;
}

IntegratorStatistics& IntegratorStatistics::operator-=(const IntegratorStatistics& o) noexcept {
  steps -= o.steps;
  rejected -= o.rejected;
  rhs_evaluations -= o.rhs_evaluations;
  events -= o.events;
  slips -= o.slips;
  sticks -= o.sticks;
  pivots -= o.pivots;
  return *this;
}

bool integrable_profile(const TableProfile& profile) noexcept {
  return profile.piecewise_polynomial() != nullptr || profile.smooth() != nullptr;
}

std::size_t advance_integrated(const IntegratorSetup& setup, ObjectState& state, double t_end,
                               MotionObserver* observer, IntegratorStatistics* stats,
                               std::span<const double> watch) {
  if (!std::is_sorted(watch.begin(), watch.end()))
    throw InvalidParameter("watch", "unsorted", "watched positions must be sorted ascending");
  if (!integrable_profile(setup.profile))
    throw InvalidParameter("profile", setup.profile.kind(),
                           "the slip integrator needs a piecewise-polynomial or smooth table "
                           "motion (use time-stepping)");
  validate(setup.options);
  validate(state);
  if (!std::isfinite(t_end)) throw InvalidParameter("t_end", t_end, "must be finite");
  const FrictionLaw& law = setup.law;
  const auto pieces = setup.friction.pieces();
  const double P = setup.profile.period();
  Forcing forcing(setup.profile);
  IntegratorStatistics st;
  auto dense = odeint::make_dense_output(setup.options.absolute_tolerance,
                                         setup.options.relative_tolerance, kMaxStepPerPeriod * P,
                                         odeint::runge_kutta_dopri5<State>());
  // A separate controlled stepper places velocity zeros (F06: re-integration up to the zero).
  auto controlled = odeint::make_controlled(setup.options.absolute_tolerance,
                                            setup.options.relative_tolerance,
                                            odeint::runge_kutta_dopri5<State>());
  double t = state.t, x = state.x, v = state.xd, dt = 1e-3 * P;
  const double horizon = std::max(1.0, (t_end - t) / P);  // periods the budget is sized for
  const double max_attempts = setup.options.max_steps_per_period * horizon;
  const double max_intervals = setup.options.max_steps_per_period * horizon;
  long long attempts = 0;  // Runge-Kutta step attempts of this call, accepted or not
  int breaking = 0;  // after a stick break: the direction of the slip that follows
  std::size_t count = 0;
  auto emit = [&](double t1, double x1, double v1, int direction, ArcEnd end) {
    if (observer)
      observer->on_motion({t, t1, x, v, x1, v1, static_cast<std::int8_t>(direction), end}, nullptr);
    ++count;
    if (end != ArcEnd::horizon && end != ArcEnd::acceleration_switch) ++st.events;
    t = t1;
    x = x1;
    v = v1;
  };
  for (long long intervals = 0; t < t_end; ++intervals) {
    if (static_cast<double>(intervals) >= max_intervals)
      exceed_budget(setup, setup.friction.bound(x), "intervals");
    int sigma = v > 0 ? 1 : v < 0 ? -1 : 0;
    if (sigma == 0) {
      const double ms = law.static_coefficient() * setup.friction.bound(x);
      if (breaking == 0) forcing.open(t);
      sigma = decide_at_rest(breaking == 0 ? forcing.accel(t) : 0.0, ms, breaking);
      breaking = 0;
      if (sigma == 0) {  // held exactly (x' = 0) until y'' leaves the static bound
        const detail::StickEnd e = forcing.stick_end(ms, t, t_end);
        ++st.sticks;
        emit(e.t, x, 0.0, 0, e.direction != 0 ? ArcEnd::stick_break : ArcEnd::horizon);
        breaking = e.direction;
        continue;
      }
    }
    // Slip in direction sigma on the friction piece ahead, up to the window's end.
    std::size_t pi = setup.friction.piece_index(x);
    if (sigma < 0 && pi > 0 && x == pieces[pi].begin) --pi;  // moving left from a boundary
    const AffinePiece& piece = pieces[pi];
    const double X = sigma > 0 ? piece.end : piece.begin;
    const double window_end = std::min(forcing.open(t), t_end);
    long long evaluations = 0, event_evaluations = 0;
    const SlipRhs rhs{sigma, &piece, &law, &forcing, &evaluations};
    const SlipRhs event_rhs{sigma, &piece, &law, &forcing, &event_evaluations};
    dense.initialize(State{x, v}, t, std::min(dt, window_end - t));
    // The first watched position strictly ahead of x in the slip direction.
    std::size_t watch_index = kNoWatch;
    if (sigma > 0) {
      const auto it = std::upper_bound(watch.begin(), watch.end(), x);
      if (it != watch.end()) watch_index = static_cast<std::size_t>(it - watch.begin());
    } else {
      const auto it = std::lower_bound(watch.begin(), watch.end(), x);
      if (it != watch.begin()) watch_index = static_cast<std::size_t>(it - watch.begin()) - 1;
    }
    auto next_watch = [&](std::size_t i) {
      if (sigma > 0) return i + 1 < watch.size() ? i + 1 : kNoWatch;
      return i > 0 ? i - 1 : kNoWatch;
    };
    bool had_positive = sigma * v > 0;  // x' = 0 counts only after x' has left 0
    double prev_t = t;
    long long window_steps = 0;
    double t1 = window_end;
    ArcEnd end = ArcEnd::acceleration_switch;
    State s1{x, v};
    // Places the velocity zero located near te on the interpolant of a step that started at
    // ta (F06): that step's stages lie past the zero, where the slip equation of direction
    // sigma meets the kink of a speed-dependent law (|x'| in S2), and its interpolant carries
    // the kink's error into the zero (2e-5 in x over 4 periods at rtol 1e-12, where output
    // samples that happened to shorten the steps gave 1e-13). So the slip is integrated again
    // from ta with steps that end at te, and te corrected by Newton on x'(t) = 0 from the
    // accurate state there, until the correction is below the resolution of t: the steps never
    // reach past the zero by more than the last correction.
    auto place_velocity_zero = [&](double ta, double te, State& q) {
      State qc;  // the latest accurate state before the zero, at tc
      dense.calc_state(ta, qc);
      double tc = ta, h = te - ta;
      for (int pass = 0; pass < kEventPasses; ++pass) {
        q = qc;
        controlled.reset();
        for (double tt = tc; te - tt > time_resolution(te);) {
          double step = std::min(h, te - tt);
          const bool ok = controlled.try_step(event_rhs, q, tt, step) == odeint::success;
          if (!std::isfinite(q[0]) || !std::isfinite(q[1]))
            fail_slip(setup, piece.bound(x), "the slip integrator's state left the finite numbers");
          h = ok ? step : std::min(step, h);
          if (static_cast<double>(++attempts) > max_attempts)
            exceed_budget(setup, piece.bound(q[0]), "Runge-Kutta steps");
        }
        State d;
        event_rhs(q, d, te);
        const double g = sigma * q[1], rate = sigma * d[1];
        if (g > 0) tc = te, qc = q;
        if (g == 0 || !(rate < 0)) break;  // on the zero, or a tangency: te stands
        double tn = te - g / rate;
        if (std::abs(tn - te) <= time_resolution(te)) break;
        if (!(tn > tc)) tn = 0.5 * (tc + te);  // Newton past the last state before the zero
        te = tn;
      }
      return te;
    };
    for (bool done = false; !done;) {
      const auto [ta, tb] = dense.do_step(rhs);
      ++window_steps;
      if (static_cast<double>(attempts + (evaluations - 1) / 6) > max_attempts)
        exceed_budget(setup, piece.bound(x), "Runge-Kutta steps");
      if (!std::isfinite(dense.current_state()[0]) || !std::isfinite(dense.current_state()[1]))
        fail_slip(setup, piece.bound(x), "the slip integrator's state left the finite numbers");
      const double hi = std::min(tb, window_end);
      for (int k = 1; k <= kSamplesPerStep && !done; ++k) {
        const double ts = k == kSamplesPerStep ? hi : ta + (hi - ta) * k / kSamplesPerStep;
        State q;
        dense.calc_state(ts, q);
        const double g = sigma * q[1], p = std::isfinite(X) ? sigma * (q[0] - X) : -kInf;
        const bool stopped = had_positive && g <= 0, crossed = p >= 0;
        if (stopped || crossed) {
          auto velocity = [&](double tt) { State z; dense.calc_state(tt, z); return sigma * z[1]; };
          auto position = [&](double tt) { State z; dense.calc_state(tt, z); return sigma * (z[0] - X); };
          double tv = stopped ? refine(velocity, prev_t, ts) : kInf;
          const double tx = crossed ? refine(position, prev_t, ts) : kInf;
          State zero{};
          if (tv <= tx) tv = place_velocity_zero(ta, tv, zero);
          t1 = std::min(tv, tx);
          end = tv <= tx ? ArcEnd::velocity_zero : ArcEnd::friction_boundary;
          if (end == ArcEnd::velocity_zero) s1 = zero;
          else dense.calc_state(t1, s1);
          done = true;
        }
        // Watched positions passed on (prev_t, min(ts, t1)]: reported, the slip goes on. Each
        // one ahead of x(prev_t) (the earlier ones were reported at earlier samples).
        for (const double upto = done ? t1 : ts; observer && watch_index != kNoWatch;) {
          const double W = watch[watch_index];
          State z;
          dense.calc_state(upto, z);
          if (done && end == ArcEnd::friction_boundary) z[0] = X;
          if (sigma * (z[0] - W) < 0) break;
          auto position = [&](double tt) {
            State q2;
            dense.calc_state(tt, q2);
            return tt == upto ? sigma * (z[0] - W) : sigma * (q2[0] - W);
          };
          observer->on_crossing(W, refine(position, prev_t, upto), sigma);
          watch_index = next_watch(watch_index);
        }
        if (done) break;
        had_positive = had_positive || g > 0;
        prev_t = ts;
      }
      if (!done && tb >= window_end) {
        dense.calc_state(window_end, s1);
        t1 = window_end;
        end = window_end >= t_end ? ArcEnd::horizon : ArcEnd::acceleration_switch;
        done = true;
      }
    }
    dt = dense.current_time_step();
    st.rhs_evaluations += evaluations + event_evaluations;
    const long long attempts_window = (evaluations - 1) / 6;  // FSAL dopri5: 6 new stages per try
    attempts += attempts_window;
    st.steps += window_steps;
    ++st.slips;
    double x1 = s1[0], v1 = s1[1];
    if (end == ArcEnd::velocity_zero) v1 = 0;
    if (end == ArcEnd::friction_boundary) x1 = X;
    if (sigma * v1 < 0) v1 = 0;  // rounding of the interpolant at the event
    st.rejected += attempts_window - window_steps;
    emit(t1, x1, v1, sigma, end);
  }
  state = {t, x, v};
  if (stats) *stats += st;
  return count;
}

}  // namespace selfalign
