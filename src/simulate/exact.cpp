#include "selfalign/simulate/exact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "arc_math.hpp"
#include "selfalign/error.hpp"

namespace selfalign {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Event times of one slip arc, in the frame mirrored so that the slip velocity is >= 0:
// xi = sigma (x - ref), xi' = sigma x' >= 0. Each returns +inf when the event never happens.

// Parabolic arc xi'' = a (eqs. 15-21).
double parabolic_stop(double v, double a) { return a < 0 ? v / -a : kInf; }  // eq. (21)
double parabolic_reach(double v, double a, double dist) {
  if (a == 0) return v > 0 ? dist / v : kInf;
  const double disc = v * v + 2 * a * dist;
  if (disc < 0) return kInf;
  const double den = v + std::sqrt(disc);
  return den > 0 ? 2 * dist / den : kInf;  // smallest positive root, without cancellation
}

// Harmonic arc xi = C cos(w tau) + S sin(w tau), S >= 0: xi = R cos(w tau - phi).
double harmonic_stop(double C, double S, double w) {  // eq. (47), all quadrants
  return std::atan2(S, C) / w;
}
double harmonic_reach(double C, double S, double w, double target) {
  const double R = std::hypot(C, S);
  if (target > R) return kInf;
  const double theta = std::atan2(S, C) - std::acos(std::max(-1.0, target / R));
  return std::max(theta, 0.0) / w;
}

// Hyperbolic arc xi = C cosh(w tau) + S sinh(w tau), S >= 0.
double hyperbolic_stop(double C, double S, double w) {
  return (C < 0 && S < -C) ? std::atanh(S / -C) / w : kInf;
}
double hyperbolic_reach(double C, double S, double w, double target) {
  // With E = exp(w tau): (C + S) E^2 - 2 target E + (C - S) = 0; smallest root with E >= 1.
  const double a = C + S, c = C - S;
  double best = kInf;
  auto consider = [&](double E) {
    if (E >= 1.0 && std::isfinite(E)) best = std::min(best, std::log(E) / w);
  };
  if (a == 0) {
    if (target != 0) consider(c / (2 * target));
  } else {
    const double disc = target * target - a * c;
    if (disc < 0) return kInf;
    const double q = target + std::copysign(std::sqrt(disc), target);
    consider(q / a);
    if (q != 0) consider(c / q);
  }
  return best;
}

// Newton polish of the time at which an arc reaches position X (f = x - X, f' = x').
double polish_reach(ArcKind kind, double x0, double v0, double alpha, double omega,
                    double center, double X, double tau, double tau_max) {
  for (int i = 0; i < 2; ++i) {
    const detail::PosVel s = detail::arc_state(kind, x0, v0, alpha, omega, center, tau);
    if (s.xd == 0) break;
    const double next = tau - (s.x - X) / s.xd;
    if (!(next >= 0 && next <= tau_max)) break;
    tau = next;
  }
  return tau;
}

// Harmonic or hyperbolic arc on an affine friction piece (eqs. 42-47): its parameters and the
// times of x' = 0 and of reaching the boundary X. Kept out of line: the uniform-friction loop
// never needs it.
[[gnu::noinline]] void curved_arc(double kappa, int sigma, double m0, double A, double x,
                                  double v, double vs, double X, ArcKind& kind, double& omega,
                                  double& center, double& tau_v, double& tau_b) {
  kind = kappa < 0 ? ArcKind::harmonic : ArcKind::hyperbolic;
  omega = std::sqrt(std::abs(kappa));
  center = x + (sigma * m0 + A) / kappa;
  const double C = sigma * (x - center), S = vs / omega;
  if (kind == ArcKind::harmonic) {
    tau_v = harmonic_stop(C, S, omega);
    if (std::isfinite(X)) tau_b = harmonic_reach(C, S, omega, sigma * (X - center));
  } else {
    tau_v = hyperbolic_stop(C, S, omega);
    if (std::isfinite(X)) tau_b = hyperbolic_reach(C, S, omega, sigma * (X - center));
  }
  if (std::isfinite(tau_b))
    tau_b = polish_reach(kind, x, v, 0.0, omega, center, X, tau_b, std::min(tau_v, 2 * tau_b + 1));
}

[[gnu::noinline]] void emit(ArcSink& sink, const Arc& arc) { sink.on_arc(arc); }

std::size_t piece_for_direction(const PiecewiseAffineFriction& f, double x, int sigma) {
  const auto pieces = f.pieces();
  std::size_t i = f.piece_index(x);  // begin <= x < end
  if (sigma < 0 && i > 0 && x == pieces[i].begin) --i;  // moving left from a boundary
  return i;
}

}  // namespace

ExactState make_exact_state(const ExactSetup& setup, const ObjectState& object) {
  require_finite("t0", object.t);
  require_moderate("x0", object.x);
  require_moderate("v0", object.xd);
  const PiecewiseConstantProfile& p = setup.profile;
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

// The solver proper. kUniform: a single constant friction piece (uniform friction), which needs
// no piece look-ups and has no boundary; the compiler drops those branches from that copy.
template <bool kUniform>
std::size_t advance(const ExactSetup& setup, ExactState& state, double t_end, ArcSink* sink) {
  const auto segs = setup.profile.segments();
  const auto pieces = setup.friction.pieces();
  const std::size_t nseg = segs.size();
  const double P = setup.profile.period();
  double t = state.object.t, x = state.object.x, v = state.object.xd;
  std::size_t si = state.segment;
  long long n = state.period_index;
  std::size_t count = 0;

  constexpr bool uniform = kUniform;
  const double m_uniform = pieces[0].bound_at_begin;

  while (t < t_end) {  // one acceleration segment per pass
    const double period_start = static_cast<double>(n) * P;
    const double seg_end = si + 1 < nseg ? period_start + segs[si + 1].begin : period_start + P;
    const double A = segs[si].accel;
    const bool to_switch = seg_end <= t_end;
    const double t_stop = to_switch ? seg_end : t_end;
    const ArcEnd stop_end = to_switch ? ArcEnd::acceleration_switch : ArcEnd::horizon;

    while (t < t_stop) {  // one arc per pass
      if constexpr (uniform) {
        // The commonest arc of a uniform table: at rest and held for the rest of the segment.
        if (v == 0 && !sink && sticks(A, m_uniform)) {
          ++count;
          t = t_stop;
          break;
        }
      }
      ArcKind kind = ArcKind::stick;
      int sigma = 0;
      std::size_t pi = 0;
      double m0 = m_uniform, k = 0, alpha = 0, omega = 0, center = 0;
      double x1 = x, v1 = 0, t1 = t_stop;
      ArcEnd end = stop_end;

      if (v == 0) {
        if constexpr (!uniform) {
          pi = setup.friction.piece_index(x);
          m0 = pieces[pi].bound(x);
        }
        if (!sticks(A, m0)) sigma = A > 0 ? -1 : 1;  // slip against the table's push
      } else {
        sigma = v > 0 ? 1 : -1;
      }

      if (sigma != 0) {
        double X = sigma * kInf, tau_v = kInf, tau_b = kInf;
        if constexpr (!uniform) {
          pi = piece_for_direction(setup.friction, x, sigma);
          const AffinePiece& pc = pieces[pi];
          m0 = pc.bound(x);
          k = pc.slope;
          X = sigma > 0 ? pc.end : pc.begin;
        }
        const double vs = sigma * v;  // >= 0
        if (k == 0) {  // parabolic: x'' = -sigma m - A (eqs. 15, 18)
          kind = ArcKind::parabolic;
          alpha = -sigma * m0 - A;
          tau_v = parabolic_stop(vs, sigma * alpha);
          if (!uniform && std::isfinite(X))
            tau_b = parabolic_reach(vs, sigma * alpha, sigma * (X - x));
        } else [[unlikely]] {
          curved_arc(-sigma * k, sigma, m0, A, x, v, vs, X, kind, omega, center, tau_v, tau_b);
        }
        double tau = t_stop - t;
        if (tau_b < tau) {
          tau = tau_b;
          end = ArcEnd::friction_boundary;
        }
        if (tau_v <= tau) {
          tau = tau_v;
          end = ArcEnd::velocity_zero;
        }
        if (kind == ArcKind::parabolic) {
          x1 = x + tau * (v + 0.5 * alpha * tau);
          v1 = v + alpha * tau;
        } else {
          const detail::PosVel st = detail::arc_state(kind, x, v, alpha, omega, center, tau);
          x1 = st.x;
          v1 = st.xd;
        }
        if (end == ArcEnd::velocity_zero) v1 = 0;
        if (end == ArcEnd::friction_boundary) x1 = X;
        // A velocity that crossed zero by rounding at a switch is a stop.
        if ((v1 > 0 && sigma < 0) || (v1 < 0 && sigma > 0)) v1 = 0;
        if (end != stop_end) t1 = t + tau;
      }

      if (sink) [[unlikely]]
        emit(*sink, {t, t1, x, v, x1, v1, A, m0, k, alpha, omega, center, kind,
                     static_cast<std::int8_t>(sigma), end, si, pi});
      ++count;
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
                          ArcSink* sink) {
  require_placed(setup, state);
  if (std::isinf(t_end)) throw InvalidParameter("t_end", t_end, "must be finite");
  const auto pieces = setup.friction.pieces();
  return pieces.size() == 1 && pieces[0].slope == 0 ? advance<true>(setup, state, t_end, sink)
                                                    : advance<false>(setup, state, t_end, sink);
}

}  // namespace selfalign
