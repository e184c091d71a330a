#include "selfalign/planar/planar_patch_integrator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <utility>

#include <boost/math/tools/toms748_solve.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>

#include "acceleration_pieces.hpp"
#include "selfalign/error.hpp"
#include "selfalign/special_values.hpp"

namespace selfalign {
namespace {
namespace integrated {  // its own namespace: the library is built as a unity build

namespace odeint = boost::numeric::odeint;
constexpr double kEps = std::numeric_limits<double>::epsilon();
using Slip = std::array<double, 6>;   // xi_x, xi_y, phi, u_x, u_y, w
using Pivot = std::array<double, 4>;  // xi_x, xi_y, phi, s

// The part on the current window: its contacts' levers and bounds at a pose, and the window's
// table acceleration (constant on it).
struct Patch {
  const PlanarField& field;
  const ContactPatch& points;
  double inertia = 0;
  double kinetic = 1, stat = 1;  // k, s
  bool uniform = false;
  double level = 1;  // the uniform level
  double ax = 0, ay = 0;
  // Workspace at the last pose: levers d_i (world = table axes) and kinetic bounds k m_i w_i.
  mutable std::vector<double> dx, dy, bound;

  Patch(const PlanarField& f, const RigidPart& part, const FrictionLaw& law)
      : field(f), points(part.patch), inertia(part.inertia), kinetic(law.kinetic_forward()),
        stat(law.static_coefficient()) {
    if (const auto* u = std::get_if<UniformPlanarField>(&f)) uniform = true, level = u->level;
    dx.resize(points.size()), dy.resize(points.size()), bound.resize(points.size());
  }
  std::size_t size() const noexcept { return points.size(); }

  // Levers and kinetic bounds at the pose (xi, phi).
  void at(double xi_x, double xi_y, double phi) const {
    const double c = std::cos(phi), s = std::sin(phi);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const ContactPoint& r = points[i];
      dx[i] = c * r.x - s * r.y, dy[i] = s * r.x + c * r.y;
      const double m = uniform ? level : planar_level(field, xi_x + dx[i], xi_y + dy[i]);
      bound[i] = kinetic * m * r.load;
    }
  }
  // The contacts of the acceleration-level problem at the current levers (PatchImpulseSolver
  // with h = 1): static bounds for the stick test, kinetic for the slip.
  void contacts(std::vector<PatchContact>& out) const {
    out.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      out[i] = {dx[i], dy[i], bound[i] * stat / kinetic, bound[i]};
  }
};

// Slip velocity of contact i for the twist (u, w) at the current levers.
inline std::array<double, 2> slip_of(const Patch& p, std::size_t i, double ux, double uy,
                                     double w) {
  return {ux - w * p.dy[i], uy + w * p.dx[i]};
}

// The slip mode's right-hand side (the header's ODE). A contact whose slip is exactly 0 slides
// along its departure direction (the limit of g / |g| as the slip starts).
struct SlipRhs {
  const Patch& p;
  const std::vector<double>& departure;
  long long* evaluations;
  void operator()(const Slip& y, Slip& dy, double /*t*/) const {
    p.at(y[0], y[1], y[2]);
    double Fx = 0, Fy = 0, tau = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const auto g = slip_of(p, i, y[3], y[4], y[5]);
      const double n = std::hypot(g[0], g[1]);
      double ex = 0, ey = 0;
      if (n > 0) ex = g[0] / n, ey = g[1] / n;
      else if (!departure.empty()) ex = departure[2 * i], ey = departure[2 * i + 1];
      const double fx = -p.bound[i] * ex, fy = -p.bound[i] * ey;
      Fx += fx, Fy += fy, tau += p.dx[i] * fy - p.dy[i] * fx;
    }
    dy = {y[3], y[4], y[5], -p.ax + Fx, -p.ay + Fy, tau / p.inertia};
    ++*evaluations;
  }
};

// The pivot mode about contact j with spin direction sense: the reduced ODE and contact j's
// friction lambda_j (docs/planar-integrator.md).
struct PivotRhs {
  const Patch& p;
  std::size_t j;
  double sense;
  long long* evaluations;
  // dP at P, contact j's friction lambda_j, and the drive with the others' friction F_o.
  struct Forces {
    Pivot dy;
    double lx, ly;       // lambda_j
    double Fx, Fy, tau;  // F_o
  };
  Forces eval(const Pivot& y) const {
    p.at(y[0], y[1], y[2]);
    const double djx = p.dx[j], djy = p.dy[j];
    double Fx = -p.ax, Fy = -p.ay, tau = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (i == j) continue;
      const double gx = djy - p.dy[i], gy = p.dx[i] - djx;  // slip per unit spin
      const double n = std::hypot(gx, gy);
      if (!(n > 0)) continue;  // a point on the pivot itself: no slip, no kinetic force
      const double fx = -p.bound[i] * sense * gx / n, fy = -p.bound[i] * sense * gy / n;
      Fx += fx, Fy += fy, tau += p.dx[i] * fy - p.dy[i] * fx;
    }
    const double s = y[3];
    const double sd = (djy * Fx - djx * Fy + tau) / (djx * djx + djy * djy + p.inertia);
    ++*evaluations;
    // lambda_j = M (s' r_j + s r_j')_xy - F_o,xy, r_j' = s (d_jx, d_jy, 0).
    return {{s * djy, -s * djx, s, sd},
            sd * djy + s * s * djx - Fx,
            -sd * djx + s * s * djy - Fy,
            Fx, Fy, tau};
  }
  void operator()(const Pivot& y, Pivot& dy, double /*t*/) const { dy = eval(y).dy; }
  // Events: spin sense * s (> 0 while pivoting) and the friction margin c_j - |lambda_j|.
  std::array<double, 2> events(const Pivot& y) const {
    const Forces f = eval(y);
    return {sense * y[3], p.bound[j] - std::hypot(f.lx, f.ly)};
  }
};

// The time after an accepted step ending at t_out: the window's end when the step reached it
// (to 4 roundings), and the next step: the controller's proposal, except that a step cut short
// (by an arrival or the window) does not shrink it.
inline double accepted_time(double t_out, double window_end) {
  return t_out >= window_end || window_end - t_out <= 4 * kEps * std::abs(window_end) ? window_end
                                                                                      : t_out;
}
inline double next_step(double h, double dt, double proposed) {
  return h < dt ? std::max(dt, proposed) : proposed;
}

struct Run {
  const PiecewisePolynomialProfile* p1;
  const PiecewisePolynomialProfile* p2;
  const IntegratorOptions& options;
  Patch patch;
  double radius = 0;  // the patch's radius: 0 for a point at the centre of mass
  PatchImpulseSolver solver;
  std::vector<PatchContact> contacts;
  IntegratorStatistics stats;
  double budget = 0;  // step attempts allowed in this call

  Run(const PiecewisePolynomialProfile* a, const PiecewisePolynomialProfile* b,
      const IntegratorOptions& o, Patch p)
      : p1(a), p2(b), options(o), patch(std::move(p)) {}

  void spend() {
    if (static_cast<double>(stats.steps + stats.rejected + stats.events) > budget)
      throw InvalidParameter("relative_tolerance", options.relative_tolerance,
                             "the patch integrator needs more than max_steps_per_period (" +
                                 format_number(options.max_steps_per_period) +
                                 ") steps per table period: loosen the tolerances");
  }

  // One controlled step attempt of size h from (t, y), counted against the budget: true with
  // (out, dout) at t_out and the controller's next step in `next`; false on a rejection, with
  // the controller's smaller step in dt.
  template <class Stepper, class Rhs, class State>
  bool attempt(Stepper& stepper, const Rhs& rhs, const State& y, const State& dy, double t,
               double h, State& out, State& dout, double& t_out, double& next, double& dt) {
    t_out = t, next = h;
    ++stats.steps;
    spend();
    if (stepper.try_step(rhs, y, dy, t_out, out, dout, next) == odeint::success) return true;
    --stats.steps, ++stats.rejected;
    dt = next;
    return false;
  }

  // At rest (twist 0) at the current pose: stick for the window, or the departure (slip along
  // the initial acceleration, or a pivot) from the acceleration-level problem.
  void decide_at_rest(PlanarPatchState& st, double window_end) {
    patch.at(st.pose.x, st.pose.y, st.pose.angle);
    patch.contacts(contacts);
    const PatchImpulseResult r = solver.solve(contacts, patch.inertia, {-patch.ax, -patch.ay, 0});
    st.twist.ux = st.twist.uy = 0;
    if (radius > 0) st.twist.omega = 0;
    st.departure.clear();
    st.pivot = -1, st.sense = 0;
    if (r.mode == PatchMode::stick ||
        (r.mode == PatchMode::pivot && r.twist[2] == 0)) {  // held for the whole window
      st.mode = PatchMode::stick;
      ++stats.sticks;
      st.pose.angle += st.twist.omega * (window_end - st.t);  // a point part keeps its spin
      st.t = window_end;
      return;
    }
    if (r.mode == PatchMode::pivot) {
      st.mode = PatchMode::pivot, st.pivot = r.pivot, st.sense = r.twist[2] > 0 ? 1 : -1;
      ++stats.pivots;
      return;
    }
    st.mode = PatchMode::slip;
    ++stats.slips;
    st.departure.assign(2 * patch.size(), 0.0);
    for (std::size_t i = 0; i < patch.size(); ++i) {
      const auto a = slip_of(patch, i, r.twist[0], r.twist[1], r.twist[2]);
      const double n = std::hypot(a[0], a[1]);
      if (n > 0) st.departure[2 * i] = a[0] / n, st.departure[2 * i + 1] = a[1] / n;
    }
  }

  // Contact j's slip is exactly 0 and the others slide (twist s r_j): pivot, or slip with j's
  // departure direction, from the acceleration-level problem of contact j alone (the others'
  // kinetic forces fixed by their slip directions).
  void decide_at_pivot(PlanarPatchState& st, std::size_t j) {
    const double s = st.twist.omega;
    const double sense = s > 0 ? 1.0 : s < 0 ? -1.0 : static_cast<double>(st.sense);
    const PivotRhs rhs{patch, j, sense, &stats.rhs_evaluations};
    // The others' forces F_o fixed (their slips are s G_i r_j); contact j alone:
    // minimise 1/2 |z - (M^-1 F_o - o)|_M^2 + c_j |G_j z|, o = (w^2 d_j, 0), z = delta' - o.
    const PivotRhs::Forces f = rhs.eval({st.pose.x, st.pose.y, st.pose.angle, s});  // levers
    const double djx = patch.dx[j], djy = patch.dy[j];
    const PatchContact c{djx, djy, patch.bound[j], patch.bound[j]};
    const PatchImpulseResult r = solver.solve(
        std::span<const PatchContact>(&c, 1), patch.inertia,
        {f.Fx - s * s * djx, f.Fy - s * s * djy, f.tau / patch.inertia});
    st.twist = {s * djy, -s * djx, s};
    st.departure.clear();
    if (r.mode != PatchMode::slip) {
      if (st.mode != PatchMode::pivot || st.pivot != static_cast<int>(j)) ++stats.pivots;
      st.mode = PatchMode::pivot, st.pivot = static_cast<int>(j), st.sense = sense > 0 ? 1 : -1;
      return;
    }
    const double gx = r.twist[0] - r.twist[2] * djy, gy = r.twist[1] + r.twist[2] * djx;
    const double n = std::hypot(gx, gy);
    st.mode = PatchMode::slip, st.pivot = -1, st.sense = 0;
    ++stats.slips;
    st.departure.assign(2 * patch.size(), 0.0);
    if (n > 0) st.departure[2 * j] = gx / n, st.departure[2 * j + 1] = gy / n;
  }

  // Slip until the window ends or a contact arrives at zero slip (then decided).
  void slip(PlanarPatchState& st, double window_end) {
    auto stepper = odeint::make_controlled(options.absolute_tolerance, options.relative_tolerance,
                                           odeint::runge_kutta_dopri5<Slip>());
    const SlipRhs rhs{patch, st.departure, &stats.rhs_evaluations};
    Slip y{st.pose.x, st.pose.y, st.pose.angle, st.twist.ux, st.twist.uy, st.twist.omega};
    Slip dy, out, dout;
    double t = st.t;
    double dt = st.step_guess > 0 ? st.step_guess : 1e-3 * (window_end - t);
    std::vector<double> gx(patch.size()), gy(patch.size());
    const auto slips = [&](const Slip& q) {  // slip velocities at the levers of q (rhs(q) ran)
      double largest = 0;
      for (std::size_t i = 0; i < patch.size(); ++i) {
        const auto g = slip_of(patch, i, q[3], q[4], q[5]);
        gx[i] = g[0], gy[i] = g[1];
        largest = std::max(largest, std::hypot(g[0], g[1]));
      }
      return largest;
    };
    rhs(y, dy, t);
    while (t < window_end) {
      patch.at(y[0], y[1], y[2]);
      st.speed_scale = std::max(st.speed_scale, slips(y));
      // The contact arriving first at zero slip, by the linear prediction |g| / (-d|g|/dt).
      const double snap = options.absolute_tolerance + options.relative_tolerance * st.speed_scale;
      std::size_t first = patch.size();
      double tau_first = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < patch.size(); ++i) {
        const double w = y[5];
        const double ax = dy[3] - dy[5] * patch.dy[i] - w * w * patch.dx[i];
        const double ay = dy[4] + dy[5] * patch.dx[i] - w * w * patch.dy[i];
        const double closing = -(gx[i] * ax + gy[i] * ay);  // -g . g'
        const double g2 = gx[i] * gx[i] + gy[i] * gy[i];
        if (g2 > 0 && closing > 0 && g2 < tau_first * closing)
          tau_first = g2 / closing, first = i;
      }
      if (first < patch.size() &&
          std::hypot(gx[first], gy[first]) <= snap) {  // arrival: close it by one Euler step
        const double tau = std::min(tau_first, window_end - t);
        for (int k = 0; k < 6; ++k) y[k] += tau * dy[k];
        t += tau;
        ++stats.events;
        spend();
        st.t = t, st.pose = {y[0], y[1], y[2]}, st.twist = {y[3], y[4], y[5]};
        st.step_guess = dt;
        rhs(y, dy, t);
        arrive(st, first, slips(y), snap, window_end);
        return;
      }
      double h = std::min(dt, window_end - t);
      if (tau_first < h) h = 0.9 * tau_first;  // toward the arrival, never across it
      double tt, hh;
      if (!attempt(stepper, rhs, y, dy, t, h, out, dout, tt, hh, dt)) continue;
      // A step that turned a contact's slip back has crossed an arrival: halve it.
      patch.at(out[0], out[1], out[2]);
      bool crossed = false;
      for (std::size_t i = 0; i < patch.size() && !crossed; ++i) {
        const auto g = slip_of(patch, i, out[3], out[4], out[5]);
        crossed = g[0] * gx[i] + g[1] * gy[i] < 0;
      }
      if (crossed) {
        --stats.steps, ++stats.rejected;
        dt = 0.5 * h;
        continue;
      }
      y = out, dy = dout, t = accepted_time(tt, window_end);
      dt = next_step(h, dt, hh);
    }
    st.t = t, st.pose = {y[0], y[1], y[2]}, st.twist = {y[3], y[4], y[5]};
    st.step_guess = dt;
  }

  // A slip given without departure directions (a start): a contact whose slip is exactly 0
  // there is a pivot candidate, decided as an arrival.
  void start_slip(PlanarPatchState& st, double window_end) {
    patch.at(st.pose.x, st.pose.y, st.pose.angle);
    for (std::size_t i = 0; i < patch.size(); ++i) {
      const auto g = slip_of(patch, i, st.twist.ux, st.twist.uy, st.twist.omega);
      if (g[0] == 0 && g[1] == 0) {
        arrive(st, i, 1.0, 0.0, window_end);
        return;
      }
    }
  }

  // Contact `j` has arrived at zero slip (to the snap size): rest when every contact has,
  // otherwise the twist projected onto the pivot line of j and the pivot decided.
  void arrive(PlanarPatchState& st, std::size_t j, double largest, double snap,
              double window_end) {
    if (largest <= 4 * snap) {  // every contact at rest: the twist is exactly 0
      decide_at_rest(st, window_end);
      return;
    }
    // M-orthogonal projection onto s r_j: s = r_j^T M delta / r_j^T M r_j.
    const double djx = patch.dx[j], djy = patch.dy[j];
    const double s = (djy * st.twist.ux - djx * st.twist.uy + patch.inertia * st.twist.omega) /
                     (djx * djx + djy * djy + patch.inertia);
    if (s == 0) {
      decide_at_rest(st, window_end);
      return;
    }
    st.twist.omega = s;
    decide_at_pivot(st, j);
  }

  // Pivot until the window ends, the spin stops (rest) or contact j's friction leaves its disc
  // (slip, j departing against its friction).
  void pivot(PlanarPatchState& st, double window_end) {
    const std::size_t j = static_cast<std::size_t>(st.pivot);
    const double sense = st.sense;
    const PivotRhs rhs{patch, j, sense, &stats.rhs_evaluations};
    auto stepper = odeint::make_controlled(options.absolute_tolerance, options.relative_tolerance,
                                           odeint::runge_kutta_dopri5<Pivot>());
    odeint::runge_kutta_dopri5<Pivot> single;
    Pivot y{st.pose.x, st.pose.y, st.pose.angle, st.twist.omega}, dy, out, dout;
    double t = st.t;
    double dt = st.step_guess > 0 ? st.step_guess : 1e-3 * (window_end - t);
    rhs(y, dy, t);
    const auto finish = [&](const Pivot& q, double tq) {
      st.t = tq, st.pose = {q[0], q[1], q[2]};
      patch.at(q[0], q[1], q[2]);
      st.twist = {q[3] * patch.dy[j], -q[3] * patch.dx[j], q[3]};
      st.step_guess = dt;
    };
    while (t < window_end) {
      const double h = std::min(dt, window_end - t);
      double tt, hh;
      if (!attempt(stepper, rhs, y, dy, t, h, out, dout, tt, hh, dt)) continue;
      const double taken = tt - t;
      const auto e = rhs.events(out);
      if (e[0] <= 0 || e[1] < 0) {
        // The first event on the step: TOMS 748 on the event of a single step from y.
        const auto at = [&](double tau) {
          Pivot q, dq;
          single.do_step(rhs, y, dy, t, q, dq, tau);
          return q;
        };
        double tau_event = taken;
        int which = -1;
        for (int k = 0; k < 2; ++k) {
          if (!(k == 0 ? e[0] <= 0 : e[1] < 0)) continue;
          const auto f = [&](double tau) { return rhs.events(at(tau))[k]; };
          // The first sign change among 4 samples, then refined.
          double lo = 0, hi = taken;
          for (int m = 1; m <= 4; ++m) {
            const double tau = taken * m / 4;
            if (f(tau) <= 0) {
              hi = tau;
              break;
            }
            lo = tau;
          }
          double flo = f(lo);
          for (int m = 1; m <= 60 && !(flo > 0); ++m) lo = hi * std::ldexp(1.0, -m), flo = f(lo);
          double root = flo > 0 ? hi : lo;
          const double fhi = f(hi);
          if (flo > 0 && fhi < 0) {
            std::uintmax_t iterations = 100;
            const auto close = [](double a, double b) {
              return b - a <= 4 * kEps * std::max(std::abs(a), std::abs(b));
            };
            root = boost::math::tools::toms748_solve(f, lo, hi, flo, fhi, close, iterations).second;
          }
          if (root < tau_event || which < 0) tau_event = root, which = k;
        }
        Pivot q = at(tau_event);
        ++stats.events;
        spend();
        if (which == 0) {  // the spin stopped: rest
          q[3] = 0;
          finish(q, t + tau_event);
          decide_at_rest(st, window_end);
          return;
        }
        // Contact j's friction reached its disc: it departs against it.
        finish(q, t + tau_event);
        const PivotRhs::Forces f = rhs.eval(q);
        const double lx = f.lx, ly = f.ly, n = std::hypot(lx, ly);
        st.mode = PatchMode::slip, st.pivot = -1, st.sense = 0;
        ++stats.slips;
        st.departure.assign(2 * patch.size(), 0.0);
        if (n > 0) st.departure[2 * j] = -lx / n, st.departure[2 * j + 1] = -ly / n;
        return;
      }
      y = out, dy = dout, t = accepted_time(tt, window_end);
      dt = next_step(h, dt, hh);
    }
    finish(y, t);
  }
};

}  // namespace integrated
}  // namespace

PlanarPatchState make_planar_patch_state(double t, const PlanarPose& pose,
                                         const PlanarTwist& twist) {
  PlanarPatchState s;
  s.t = t, s.pose = pose, s.twist = twist;
  s.mode = twist.ux == 0 && twist.uy == 0 && twist.omega == 0 ? PatchMode::stick
                                                               : PatchMode::slip;
  return s;
}

void advance_planar_integrated(const PlanarTableMotion& motion, const PlanarField& field,
                               const FrictionLaw& law, const RigidPart& part,
                               const IntegratorOptions& options, PlanarPatchState& st,
                               double t_end, IntegratorStatistics* stats) {
  validate(motion);
  if (motion.rotation)
    throw InvalidParameter("rotation", motion.rotation->kind(),
                           "the patch integrator needs a translating table (use time-stepping)");
  require_no_normal_motion(motion, "the patch integrator");
  validate(field);
  validate(part);
  validate(options);
  require_planar_law(law);
  if (!std::isfinite(t_end) || t_end < st.t)
    throw InvalidParameter("t_end", t_end, "must be finite and >= the state's time");
  integrated::Run run(detail::constant_pieces(motion.first, "first", "the patch integrator"),
                     detail::constant_pieces(motion.second, "second", "the patch integrator"),
                     options, integrated::Patch(field, part, law));
  run.radius = patch_radius(part.patch);
  // The budget's period: the longest profile's (the periods need not divide one another).
  double period = 0;
  for (const TableProfile* p : {motion.first, motion.second})
    if (p) period = std::max(period, p->period());
  if (!(period > 0)) period = std::max(t_end - st.t, 1e-300);
  run.budget = options.max_steps_per_period * std::max(1.0, (t_end - st.t) / period);
  if (st.pivot >= static_cast<int>(part.patch.size())) st.pivot = -1, st.mode = PatchMode::slip;
  while (st.t < t_end) {
    const detail::AccelerationWindow a =
        detail::acceleration_window(motion, run.p1, run.p2, st.t, t_end);
    run.patch.ax = a.ax, run.patch.ay = a.ay;
    const bool at_rest = st.twist.ux == 0 && st.twist.uy == 0 &&
                         (st.twist.omega == 0 || run.radius == 0) && st.mode != PatchMode::pivot;
    if (st.mode == PatchMode::stick || (at_rest && st.departure.empty())) {
      run.decide_at_rest(st, a.end);
      if (st.mode == PatchMode::stick) continue;
    } else if (st.mode == PatchMode::pivot) {
      run.decide_at_pivot(st, static_cast<std::size_t>(st.pivot));  // the window's new drive
    }
    if (st.mode == PatchMode::slip && st.departure.empty()) run.start_slip(st, a.end);
    if (st.mode == PatchMode::slip) run.slip(st, a.end);
    else if (st.mode == PatchMode::pivot) run.pivot(st, a.end);
    if (!(std::isfinite(st.pose.x) && std::isfinite(st.pose.y) && std::isfinite(st.twist.ux) &&
          std::isfinite(st.twist.uy) && std::isfinite(st.twist.omega)))
      throw InvalidParameter("state", "non-finite",
                             "the patch integrator's state left the finite numbers");
  }
  if (stats) *stats += run.stats;
}

}  // namespace selfalign
