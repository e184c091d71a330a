#include "selfalign/design/actuator_samples.hpp"

#include <algorithm>
#include <cmath>

#include "selfalign/error.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/units.hpp"

namespace selfalign {
namespace {

// y''' at phase t [-]: the jerk of the piecewise-polynomial segment holding t.
double jerk_at(const PiecewisePolynomialProfile& pp, double t) {
  double jerk = 0;
  for (const AccelerationSegment& s : pp.segments())
    if (s.begin <= t) jerk = s.jerk;
  return jerk;
}

}  // namespace

ActuatorSamples actuator_samples(const DesignRequest& q, const DesignResult& d, double rate,
                                 double moving_mass) {
  constexpr double kMaxRows = 1e7;
  if (!(rate > 0) || !(d.period * rate <= kMaxRows))
    throw InvalidParameter("sample_rate", rate,
                           "must be > 0 with at most 1e7 samples a period (rate x period)");
  if (!std::isnan(moving_mass) && !(moving_mass > 0 && std::isfinite(moving_mass)))
    throw InvalidParameter("moving_mass", moving_mass, "must be > 0 [kg] (NaN: no force)");
  const Scales sc(q.width, q.mu, q.gravity);
  const std::unique_ptr<TableProfile> profile = recommended_profile(d);
  const PiecewisePolynomialProfile* pp = profile->piecewise_polynomial();
  ActuatorSamples s;
  s.requested_rate = rate;
  s.moving_mass = moving_mass;
  s.samples_per_period = std::max(2LL, std::llround(d.period * rate));
  const auto n = static_cast<std::size_t>(s.samples_per_period);
  s.sample_rate = static_cast<double>(n) / d.period;
  const double jerk_si = sc.acceleration_to_si(1) / sc.time();
  for (std::size_t i = 0; i < n; ++i) {
    const double t = d.period * static_cast<double>(i) / static_cast<double>(n);
    const double tm = sc.time_from_si(t);
    const TableState st = profile->state(tm);
    s.t.push_back(t);
    s.y.push_back(sc.length_to_si(st.y));
    s.y_dot.push_back(sc.velocity_to_si(st.yd));
    s.y_ddot.push_back(sc.acceleration_to_si(st.ydd));
    s.y_dddot.push_back(jerk_at(*pp, tm) * jerk_si);
    if (!std::isnan(moving_mass)) s.force.push_back(moving_mass * s.y_ddot.back());
  }
  return s;
}

}  // namespace selfalign
