#include "selfalign/planar/planar_exact_point.hpp"
#include "selfalign/special_values.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "selfalign/error.hpp"
#include "acceleration_pieces.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"

namespace selfalign {
namespace {

using detail::constant_pieces;


// (w^e - w0^e) / e, its limit ln(w / w0) at e = 0, without cancellation for e near 0.
double dpow(double w, double w0, double e) {
  const double L = std::log(w / w0);
  const double eL = e * L;
  const double factor = std::abs(eL) < 1e-8 ? L * (1 + 0.5 * eL) : std::expm1(eL) / e;
  return std::pow(w0, e) * factor;
}

}  // namespace

long long advance_planar_exact_point(const PlanarTableMotion& motion,
                                     const UniformPlanarField& field, const FrictionLaw& law,
                                     PlanarExactState& st, double t_end) {
  validate(motion);
  if (motion.rotation)
    throw InvalidParameter("rotation", motion.rotation->kind(),
                           "the exact point solver needs a translating table");
  require_no_normal_motion(motion, "the exact point solver");
  validate(PlanarField(field));
  require_planar_law(law);
  if (!std::isfinite(t_end) || t_end < st.t)
    throw InvalidParameter("t_end", t_end, "must be finite and >= the state's time");
  const PiecewisePolynomialProfile* p1 = constant_pieces(motion.first, "first", "the exact planar solver");
  const PiecewisePolynomialProfile* p2 = constant_pieces(motion.second, "second", "the exact planar solver");
  const double hold = law.static_coefficient() * field.level;
  const double mu = law.kinetic_forward() * field.level;
  double t = st.t, x = st.x, y = st.y, ux = st.ux, uy = st.uy;
  long long arcs = 0;
  while (t < t_end) {
    const detail::AccelerationWindow window = detail::acceleration_window(motion, p1, p2, t, t_end);
    const double Ax = window.ax, Ay = window.ay, t_next = window.end;
    const double tau_max = t_next - t;
    const double Fx = -Ax, Fy = -Ay, F = std::hypot(Fx, Fy);
    ++arcs;
    const double V = std::hypot(ux, uy);
    if (V == 0) {
      if (F <= hold) {  // stick: the whole segment
        t = t_next;
        continue;
      }
      // Slip from rest along the drive: V' = |F| - mu > 0, direction F / |F|.
      const double g = F - mu, ex = Fx / F, ey = Fy / F;
      x += ex * 0.5 * g * tau_max * tau_max, y += ey * 0.5 * g * tau_max * tau_max;
      ux = ex * g * tau_max, uy = ey * g * tau_max;
      t = t_next;
      continue;
    }
    // Sliding. Frame: e along F (or along u when F = 0), n perpendicular on u's side.
    double ex = F > 0 ? Fx / F : ux / V, ey = F > 0 ? Fy / F : uy / V;
    const double along = (ux * ex + uy * ey) / V;       // cos(phi)
    double across = (-ux * ey + uy * ex) / V;           // sin(phi) with the side's sign
    const double side = across < 0 ? -1.0 : 1.0;
    across = std::abs(across);
    const double nx = -ey * side, ny = ex * side;        // unit vector toward u's side
    const double phi = std::atan2(across, along);
    // Straight arcs: u parallel to the drive (phi = 0 or pi), or no drive.
    if (F == 0 || across == 0) {
      // V' = F cos(phi) - mu with cos(phi) = +-1 (F = 0: V' = -mu).
      const double Vdot = (along >= 0 ? F : -F) - mu;
      const double tau_stop = Vdot < 0 ? V / -Vdot : kInf;
      const double tau = std::min(tau_stop, tau_max);
      const double V1 = tau == tau_stop ? 0.0 : V + Vdot * tau;
      const double s = V * tau + 0.5 * Vdot * tau * tau;
      const double ux0 = ux / V, uy0 = uy / V;
      x += ux0 * s, y += uy0 * s;
      ux = ux0 * V1, uy = uy0 * V1;
      t = tau == tau_stop ? t + tau : t_next;
      continue;
    }
    // The turning slip (docs/planar.md): K = mu / |F|, w = tan(phi / 2).
    const double K = mu / F, w0 = std::tan(0.5 * phi);
    const double C = V * across / std::pow(w0, K);
    const double scale = C / (2 * F);
    double tau_stop = kInf;
    if (K > 1) tau_stop = scale * (std::pow(w0, K - 1) / (K - 1) + std::pow(w0, K + 1) / (K + 1));
    double w = 0;
    double tau = tau_max;
    if (tau_stop <= tau_max) {
      tau = tau_stop;  // the stick event |u| -> 0
    } else {
      // G(w) - G(w0) = -tau / scale, G increasing in w: bisection on log w.
      const auto f = [&](double ww) {
        return dpow(ww, w0, K - 1) + dpow(ww, w0, K + 1) + tau_max / scale;
      };
      // Bracket [lo, hi] with f(lo) <= 0 < f(hi), then Newton (f' = w^(K-2) (1 + w^2))
      // safeguarded by bisection in log w, to round-off.
      double hi = w0, lo = w0;
      for (int i = 0; i < 2000 && f(lo) > 0; ++i) hi = lo, lo *= 0.5;
      w = hi;
      for (int i = 0; i < 200; ++i) {
        const double fw = f(w);
        (fw > 0 ? hi : lo) = w;
        double next = w - fw / (std::pow(w, K - 2) * (1 + w * w));
        if (!(next > lo && next < hi)) next = std::sqrt(lo * hi);
        if (std::abs(next - w) <= 4e-16 * w || !(hi > lo)) {
          w = next;
          break;
        }
        w = next;
      }
    }
    double d_along, d_across, V1 = 0, phi1 = 0;
    if (w == 0) {  // stopped: the integrals to w = 0 (K > 1: every power is positive)
      d_along = (C * C / (4 * F)) * (std::pow(w0, 2 * K - 2) / (2 * K - 2) -
                                     std::pow(w0, 2 * K + 2) / (2 * K + 2));
      d_across = (C * C / (2 * F)) * (std::pow(w0, 2 * K - 1) / (2 * K - 1) +
                                      std::pow(w0, 2 * K + 1) / (2 * K + 1));
    } else {
      d_along = -(C * C / (4 * F)) * (dpow(w, w0, 2 * K - 2) - dpow(w, w0, 2 * K + 2));
      d_across = -(C * C / (2 * F)) * (dpow(w, w0, 2 * K - 1) + dpow(w, w0, 2 * K + 1));
      phi1 = 2 * std::atan(w);
      V1 = C * std::pow(w, K) / std::sin(phi1);
    }
    x += ex * d_along + nx * d_across, y += ey * d_along + ny * d_across;
    ux = V1 * (std::cos(phi1) * ex + std::sin(phi1) * nx);
    uy = V1 * (std::cos(phi1) * ey + std::sin(phi1) * ny);
    t = tau == tau_stop ? t + tau : t_next;
  }
  st.t = t, st.x = x, st.y = y, st.ux = ux, st.uy = uy;
  return arcs;
}

}  // namespace selfalign
