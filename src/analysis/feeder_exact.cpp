#include "selfalign/analysis/feeder_exact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "../planar/acceleration_pieces.hpp"
#include "feeder_exact_detail.hpp"
#include "selfalign/error.hpp"
#include "selfalign/special_values.hpp"

namespace selfalign {
namespace {

using detail::FeederConstants;
constexpr const char* kSolver = "the exact feeder solver";

// The first time tau in [0, limit] at which the height h + w tau - n tau^2 / 2 returns to 0
// (the landing), or +inf. h >= 0; the stable root of the quadratic (no cancellation).
double landing_time(double h, double w, double n, double limit) {
  double tau = kInf;
  if (n > 0) {  // falling back: one root >= 0
    const double disc = std::sqrt(w * w + 2 * n * h);
    tau = w >= 0 ? (w + disc) / n : 2 * h / (disc - w);
  } else if (n == 0) {
    if (w < 0) tau = -h / w;
  } else if (w < 0) {  // pushed away (n < 0) but moving down: lands if it reaches 0
    const double d = w * w + 2 * n * h;  // w^2 - 4 a h with a = -n / 2
    if (d >= 0) tau = 2 * h / (std::sqrt(d) - w);
  }
  return tau <= limit ? tau : kInf;
}


// True when the profile (null: none) has piecewise-constant acceleration, false when it is
// smooth; throws InvalidParameter naming `name` when it is neither.
bool constant_family(const TableProfile* p, const char* name) {
  if (!p || !p->smooth()) return (detail::constant_pieces(p, name, kSolver), true);
  return false;
}

}  // namespace

void validate(const FeederTrack& k) {
  if (k.along && k.normal && k.along->smooth() && !k.normal->smooth())
    throw InvalidParameter("normal", k.normal->kind(),
                           "must be smooth like the motion along the track for " +
                               std::string(kSolver));
  if (k.along && k.normal && !k.along->smooth() && k.normal->smooth())
    throw InvalidParameter("along", k.along->kind(),
                           "must be smooth like the normal motion for " + std::string(kSolver));
  constant_family(k.along, "along");
  constant_family(k.normal, "normal");
  require_positive_moderate("g", k.g);
  if (!(std::abs(k.incline) < 0.5 * std::numbers::pi))
    throw InvalidParameter("incline", k.incline, "must be in (-pi/2, pi/2) rad");
  require_positive_moderate("level", k.level);
  if (k.law.velocity_dependent())
    throw InvalidParameter("law", k.law.describe(),
                           "the exact feeder solver takes a Coulomb law (no Stribeck, no viscous "
                           "term)");
  if (!(k.restitution >= 0 && k.restitution <= 1))
    throw InvalidParameter("restitution", k.restitution, "must be in [0, 1]");
  if (k.field)
    for (const AffinePiece& p : k.field->pieces())
      if (p.slope != 0 || !(p.bound_at_begin > 0 && p.bound_at_begin <= 1e50))
        throw InvalidParameter("field", p.slope != 0 ? "a sloped piece" : "a level <= 0",
                               "the exact feeder solver takes a piecewise-constant level > 0 "
                               "(a friction step without a transition width)");
}

const char* feeder_mode_name(FeederMode mode) noexcept {
  switch (mode) {
    case FeederMode::stick: return "stick";
    case FeederMode::slip: return "slip";
    case FeederMode::flight: return "flight";
  }
  return "stick";
}

namespace {

// The piecewise-constant family: on each window between switches of either profile every
// quantity is constant, so every arc is a parabola (header).
void advance_feeder_constant(const FeederTrack& k, FeederExactState& st, double t_end,
                             FeederExactStatistics& stats) {
  const PiecewisePolynomialProfile* pa = k.along ? k.along->piecewise_polynomial() : nullptr;
  const PiecewisePolynomialProfile* pn = k.normal ? k.normal->piecewise_polynomial() : nullptr;
  const detail::FeederConstants c(k);
  double t = st.t, x = st.x, u = st.u, h = st.h, w = st.w;
  FeederMode mode = h > 0 ? FeederMode::flight : st.mode;
  while (t < t_end) {
    const detail::Piece a = detail::piece_at(pa, t), b = detail::piece_at(pn, t);
    const double end = std::min({a.next, b.next, t_end});
    const double n = c.gc + b.accel;  // the normal load per unit mass the track must supply
    const double f = a.accel + c.gs;  // the friction force per unit mass that holds the part
    ++stats.arcs;
    if (mode == FeederMode::flight) {
      const double tau_land = landing_time(h, w, n, end - t);
      const double dur = std::min(tau_land, end - t);
      x += dur * (u - 0.5 * f * dur);
      u -= f * dur;
      h += dur * (w - 0.5 * n * dur);
      w -= n * dur;
      detail::record_census(stats, mode, dur, t + dur);
      t = tau_land <= end - t ? t + tau_land : end;
      if (tau_land == dur) {  // landing
        h = 0;
        if (!detail::feeder_landing(c, t, x, n, u, w, stats))
          mode = u == 0 ? FeederMode::stick : FeederMode::slip;
      }
      continue;
    }
    if (n < 0) {  // the track falls away faster than gravity: lift-off
      mode = FeederMode::flight;
      detail::record_lift_off(stats, t);
      continue;
    }
    double sigma;
    if (u == 0) {
      if (std::abs(f) <= c.static_bound(n, c.level_at(x))) {
        mode = FeederMode::stick;
        detail::record_census(stats, mode, end - t, end);
        t = end;
        continue;
      }
      sigma = f > 0 ? -1.0 : 1.0;  // it slides against the friction it would need
      detail::record_slip_start(stats, t, static_cast<int>(sigma));
    } else {
      sigma = u > 0 ? 1.0 : -1.0;
    }
    const int dir = sigma > 0 ? 1 : -1;
    const FeederConstants::SlipPiece piece = c.slip_piece(x, dir);
    const double acc = -f - sigma * c.kinetic(dir, n, piece.m);
    const double tau_stop = u != 0 && acc * sigma < 0 ? -u / acc : kInf;
    // the boundary ahead: sigma x rises at sigma u > 0 with sigma acc (closed form, eq. 21's
    // reach); from rest the slip starts with sigma u = 0 and sigma acc > 0
    const double tau_reach = std::isinf(piece.boundary)
                                 ? kInf
                                 : detail::parabolic_reach(sigma * u, sigma * acc,
                                                           sigma * (piece.boundary - x));
    const double dur = std::min({tau_stop, tau_reach, end - t});
    const bool stops = dur == tau_stop, reaches = !stops && dur == tau_reach;
    x = reaches ? piece.boundary : x + dur * (u + 0.5 * acc * dur);
    u = stops ? 0.0 : u + acc * dur;
    t = dur == end - t && !stops && !reaches ? end : t + dur;
    mode = FeederMode::slip;
    detail::record_census(stats, mode, dur, t);
  }
  st.t = t, st.x = x, st.u = u, st.h = h, st.w = w;
  st.mode = mode == FeederMode::slip && u == 0 ? FeederMode::stick : mode;
}

}  // namespace

void advance_feeder_exact(const FeederTrack& k, FeederExactState& st, double t_end,
                          FeederExactStatistics* statistics) {
  validate(k);
  if (!std::isfinite(t_end) || t_end < st.t)
    throw InvalidParameter("t_end", t_end, "must be finite and >= the state's time");
  if (!(std::isfinite(st.x) && std::isfinite(st.u) && std::isfinite(st.w) && st.h >= 0 &&
        std::isfinite(st.h)))
    throw InvalidParameter("state", st.h, "needs finite values and a height h >= 0");
  FeederExactStatistics local;
  FeederExactStatistics& stats = statistics ? *statistics : local;
  const bool smooth = (k.along && k.along->smooth()) || (k.normal && k.normal->smooth());
  if (smooth)
    detail::advance_feeder_smooth(k, st, t_end, stats);
  else
    advance_feeder_constant(k, st, t_end, stats);
}

}  // namespace selfalign
