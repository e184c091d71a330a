#include "selfalign/simulate/exact.hpp"
#include "selfalign/simulate/stick_slip_decision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "arc_events.hpp"
#include "selfalign/error.hpp"

namespace selfalign {
namespace {

using detail::kInf;

[[gnu::noinline]] void emit(MotionObserver& observer, const Arc& arc) {
  observer.on_motion(arc, &arc);
}

std::size_t piece_for_direction(const PiecewiseAffineFriction& f, double x, int sigma) {
  const auto pieces = f.pieces();
  std::size_t i = f.piece_index(x);  // begin <= x < end
  if (sigma < 0 && i > 0 && x == pieces[i].begin) --i;  // moving left from a boundary
  return i;
}

}  // namespace

ExactState make_exact_state(const ExactSetup& setup, const ObjectState& object) {
  validate(object);
  const PiecewisePolynomialProfile& p = setup.profile;
  constexpr double kMaxPeriodIndex = 1e15;  // period_index and its product with Δt stay exact
  if (!(std::abs(object.t / p.period()) <= kMaxPeriodIndex))
    throw InvalidParameter("t0", object.t, "must be within 1e15 table periods of 0");
  ExactState s;
  s.object = object;
  s.period_index = static_cast<long long>(std::floor(object.t / p.period()));
  double phase = object.t - static_cast<double>(s.period_index) * p.period();
  if (phase >= p.period()) {
    ++s.period_index;
    phase = 0;
  }
  s.segment = p.segment_at(std::max(phase, 0.0));
  return s;
}

namespace {

// The uniform solver: one constant friction piece and constant acceleration on every segment,
// the paper's case and the sweeps' hot loop. Parabolic arcs only (eqs. 15-21); the general
// solver below gives the same arcs (tests/test_friction_law.cpp checks both agree), this copy
// only drops the look-ups it does not need. It walks each segment in local time (the phase in
// the period, and the time left in the segment), as the independent floor of
// bench/floors.cpp does; absolute times are formed only at the segment switches (the same
// expression, period start + segment start, as the general solver) and for an observer's arcs.
std::size_t advance_uniform(const ExactSetup& setup, ExactState& state, double t_end,
                            MotionObserver* observer) {
  const auto segs = setup.profile.segments();
  const std::size_t nseg = segs.size();
  const double P = setup.profile.period();
  const double m = setup.friction.pieces()[0].bound_at_begin;
  const double m_static = setup.law.static_coefficient() * m;
  const double m_forward = setup.law.kinetic_forward() * m;
  const double m_backward = setup.law.kinetic_backward() * m;
  double t = state.object.t, x = state.object.x, v = state.object.xd;
  std::size_t si = state.segment;
  long long n = state.period_index;
  double period_start = static_cast<double>(n) * P;
  double phase = t - period_start;  // local time in the period
  std::size_t count = 0;

  while (t < t_end) {  // one acceleration segment per pass
    const double seg_end = si + 1 < nseg ? segs[si + 1].begin : P;  // local
    const double A = segs[si].accel;
    const bool to_switch = period_start + seg_end <= t_end;
    const double stop = to_switch ? seg_end : t_end - period_start;  // local
    const ArcEnd stop_end = to_switch ? ArcEnd::acceleration_switch : ArcEnd::horizon;
    double left = stop - phase;  // time left in the segment

    while (left > 0) {  // one arc per pass
      // The commonest arc: at rest and held for the rest of the segment.
      if (v == 0 && !observer && decide_at_rest(A, m_static) == 0) {
        ++count;
        break;
      }
      const int sigma = v == 0 ? decide_at_rest(A, m_static)  // stick, or slip against the push
                                : (v > 0 ? 1 : -1);
      double alpha = 0, x1 = x, v1 = 0, tau = left;
      ArcEnd end = stop_end;
      if (sigma != 0) {  // parabolic: x'' = -sigma k m - A (eqs. 15, 18)
        alpha = -sigma * (sigma > 0 ? m_forward : m_backward) - A;
        const double tau_v = detail::parabolic_stop(sigma * v, sigma * alpha);  // eq. (21)
        if (tau_v <= left) {
          tau = tau_v;
          end = ArcEnd::velocity_zero;
        }
        x1 = x + tau * (v + 0.5 * alpha * tau);
        v1 = end == ArcEnd::velocity_zero ? 0.0 : v + alpha * tau;
        // A velocity that crossed zero by rounding at a switch is a stop.
        if ((v1 > 0 && sigma < 0) || (v1 < 0 && sigma > 0)) v1 = 0;
      }
      const double phase1 = end == stop_end ? stop : phase + tau;
      if (observer) [[unlikely]] {
        const double t1 = end != stop_end ? period_start + phase1
                          : to_switch     ? period_start + seg_end
                                          : t_end;
        Arc arc{{period_start + phase, t1, x, v, x1, v1}, A, 0.0, m, 0.0, StickArc{}};
        if (sigma != 0) arc.shape = PolynomialArc{alpha, 0.0};
        arc.direction = static_cast<std::int8_t>(sigma);
        arc.end = end;
        arc.segment = si;
        emit(*observer, arc);
      }
      ++count;
      phase = phase1;
      left = stop - phase;
      x = x1;
      v = v1;
    }
    if (!to_switch) {  // the horizon, inside this segment
      t = t_end;
      break;
    }
    t = period_start + seg_end;
    phase = seg_end;
    if (++si == nseg) {
      si = 0;
      ++n;
      period_start = static_cast<double>(n) * P;
      phase = t - period_start;  // 0 up to rounding of n P
    }
  }
  state.object = {t, x, v};
  state.segment = si;
  state.period_index = n;
  return count;
}

// The general solver: any piecewise-affine friction level, any law, and table accelerations
// affine in time on each segment (finite jerk). One arc per pass; the arc's shape is chosen by
// the stick/slip decision and the friction piece, its next event by the shape (arc_events.hpp).
std::size_t advance_general(const ExactSetup& setup, ExactState& state, double t_end,
                            MotionObserver* observer) {
  const auto segs = setup.profile.segments();
  const auto pieces = setup.friction.pieces();
  const FrictionLaw& law = setup.law;
  const std::size_t nseg = segs.size();
  const double P = setup.profile.period();
  double t = state.object.t, x = state.object.x, v = state.object.xd;
  std::size_t si = state.segment;
  long long n = state.period_index;
  std::size_t count = 0;
  int breaking = 0;  // after a stick_break: the slip direction the broken stick takes
  // The last arc was a slip from rest that left t, x and x' unchanged: it lasted less than the
  // resolution of t (a steep ramp turning |y''| back below the static bound within ~1e-16 at
  // t ~ 600, so t + tau == t). The object stays stuck (the stick branch then holds it until
  // |y''| reaches the bound again); without this the stick test and that slip would alternate
  // forever at one instant (tests/test_finite_jerk.cpp, AStallingSlip...).
  bool stalled = false;

  while (t < t_end) {  // one acceleration segment per pass
    const double period_start = static_cast<double>(n) * P;
    const double seg_begin = period_start + segs[si].begin;
    const double seg_end = si + 1 < nseg ? period_start + segs[si + 1].begin : period_start + P;
    const double J = segs[si].jerk;
    const bool to_switch = seg_end <= t_end;
    const double t_stop = to_switch ? seg_end : t_end;
    const ArcEnd stop_end = to_switch ? ArcEnd::acceleration_switch : ArcEnd::horizon;

    while (t < t_stop) {  // one arc per pass
      const double A = J == 0 ? segs[si].accel : segs[si].accel + J * (t - seg_begin);
      int sigma = 0;
      std::size_t pi = 0;
      double m0 = 0, k = 0, x1 = x, v1 = 0, t1 = t_stop;
      ArcEnd end = stop_end;
      ArcShape shape;

      if (v == 0) {
        pi = setup.friction.piece_index(x);
        m0 = pieces[pi].bound(x);
        const double m_static = law.static_coefficient() * m0;
        sigma = decide_at_rest(A, m_static, breaking, stalled);
        if (sigma == 0 && J != 0) {  // held until |A + J tau| reaches the static bound
          const double tau_break = J > 0 ? (m_static - A) / J : (-m_static - A) / J;
          if (t + tau_break < t_stop) {
            t1 = t + std::max(tau_break, 0.0);
            end = ArcEnd::stick_break;
          }
        }
      } else {
        sigma = v > 0 ? 1 : -1;
      }
      breaking = 0;

      if (sigma != 0) {
        pi = piece_for_direction(setup.friction, x, sigma);
        const AffinePiece& pc = pieces[pi];
        m0 = pc.bound(x);
        k = pc.slope;
        const double X = sigma > 0 ? pc.end : pc.begin;
        const double kin = law.kinetic(sigma);
        double q0 = -sigma * (kin * m0) - A;  // x'' at the start
        if (v == 0 && sigma * q0 < 0) q0 = 0;  // a stick that just broke: rounding of |A| = s m
        const double T = t_stop - t, scale = std::abs(t) + T;
        detail::SlipEvent e;
        if (k == 0) {
          const PolynomialArc arc{q0, -J};
          e = detail::next_event(arc, x, v, sigma, X, T, scale);
          shape = arc;
        } else [[unlikely]] {
          // x'' = -kappa (x - x0) + q0 - J tau = -kappa (x - c - d tau) (eqs. 42-47).
          const double kappa = sigma * kin * k;
          const double omega = std::sqrt(std::abs(kappa));
          const double center = x + q0 / kappa, drift = J == 0 ? 0.0 : -J / kappa;
          if (kappa > 0) {
            const HarmonicArc arc{omega, center, drift};
            e = detail::next_event(arc, x, v, sigma, X, T, scale);
            shape = arc;
          } else {
            const HyperbolicArc arc{omega, center, drift};
            e = detail::next_event(arc, x, v, sigma, X, T, scale);
            shape = arc;
          }
        }
        const double tau = e.tau < T ? e.tau : T;
        if (e.end != ArcEnd::horizon && e.tau <= T) end = e.end;
        const PosVel st = std::visit([&](const auto& a) { return a.state(x, v, tau); }, shape);
        x1 = st.x;
        v1 = st.xd;
        if (end == ArcEnd::velocity_zero) v1 = 0;
        if (end == ArcEnd::friction_boundary) x1 = X;
        // A velocity that crossed zero by rounding at a switch is a stop.
        if ((v1 > 0 && sigma < 0) || (v1 < 0 && sigma > 0)) v1 = 0;
        if (end != stop_end) t1 = t + tau;
      } else if (end == ArcEnd::stick_break) {
        breaking = J > 0 ? -1 : 1;  // |A| grows through s m: slip against the push
      }

      if (observer) [[unlikely]] {
        Arc arc{{t, t1, x, v, x1, v1}, A, J, m0, k, shape};
        arc.direction = static_cast<std::int8_t>(sigma);
        arc.end = end;
        arc.segment = si;
        arc.piece = pi;
        emit(*observer, arc);
      }
      ++count;
      stalled = sigma != 0 && v == 0 && v1 == 0 && t1 == t && x1 == x;
      t = t1;
      x = x1;
      v = v1;
    }
    if (to_switch && ++si == nseg) {
      si = 0;
      ++n;
    }
  }
  state.object = {t, x, v};
  state.segment = si;
  state.period_index = n;
  return count;
}

}  // namespace

namespace {
// A state must be where make_exact_state / advance_exact left it: its segment exists and holds
// its time (to a tolerance far above rounding: this catches misuse, not precision).
void require_placed(const ExactSetup& setup, const ExactState& state) {
  const auto segs = setup.profile.segments();
  const double P = setup.profile.period(), t = state.object.t;
  if (state.segment >= segs.size())
    throw InvalidParameter("segment", static_cast<double>(state.segment),
                           "must be < " + std::to_string(segs.size()) +
                               " (the profile's segments); build the state with make_exact_state");
  const double begin = static_cast<double>(state.period_index) * P + segs[state.segment].begin;
  const double end = begin + segs[state.segment].duration;
  const double tol = 1e-9 * (P + std::abs(t));
  if (!(std::isfinite(t) && t >= begin - tol && t <= end + tol))
    throw InvalidParameter("state", "t = " + format_number(t),
                           "is not in its segment/period (" + format_number(begin) + " to " +
                               format_number(end) + "); build the state with make_exact_state");
}
}  // namespace

std::size_t advance_exact(const ExactSetup& setup, ExactState& state, double t_end,
                          MotionObserver* observer) {
  require_placed(setup, state);
  if (std::isinf(t_end)) throw InvalidParameter("t_end", t_end, "must be finite");
  const auto pieces = setup.friction.pieces();
  const bool uniform = pieces.size() == 1 && pieces[0].slope == 0;
  return uniform && setup.profile.piecewise_constant()
             ? advance_uniform(setup, state, t_end, observer)
             : advance_general(setup, state, t_end, observer);
}

}  // namespace selfalign
