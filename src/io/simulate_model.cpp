#include "selfalign/io/simulate_model.hpp"

#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/profiles/make_three_phase_profile.hpp"
#include "selfalign/profiles/piecewise_polynomial.hpp"
#include "selfalign/profiles/sampled.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/simulate/time_stepping.hpp"
#include "selfalign/special_values.hpp"

namespace selfalign {
namespace {

// The samples CSV, converted to [-] in SI runs ((s, m/s^2) -> (t/T, y''/(mu g))).
AccelerationSamples load_samples(const SimulateConfig& c, UnitSystem units, const Scales& scales) {
  if (!c.samples)
    throw InvalidParameter("samples", "none", "must name a CSV file of 't,ydd' rows when "
                                              "profile = samples");
  AccelerationSamples s = read_acceleration_samples(*c.samples);
  if (units == UnitSystem::si) {
    for (double& t : s.t) t = scales.time_from_si(t);
    for (double& a : s.ydd) a = scales.acceleration_from_si(a);
  }
  return s;
}

ThreePhaseParameters three_phase_parameters(const SimulateConfig& c) {
  return {*c.period, *c.stroke, *c.a2, *c.a3};
}

// The table profile named by `profile`, from dimensionless values.
std::unique_ptr<TableProfile> make_profile(const SimulateConfig& c, UnitSystem units,
                                           const Scales& scales) {
  const std::string& kind = *c.profile;
  if (kind == "three-phase") {
    return make_three_phase_profile(three_phase_parameters(c), c.jerk ? *c.jerk : kInf);
  }
  if (kind == "piecewise-linear") {
    if (!c.times || c.times->empty())
      throw InvalidParameter("times", "none",
                             "must list the breakpoint times when profile = piecewise-linear");
    return std::make_unique<PiecewisePolynomialProfile>(PiecewisePolynomialProfile::from_breakpoints(
        *c.times, *c.accelerations, *c.period));
  }
  if (kind == "quadratic-sequence") {
    if (c.durations->empty())
      throw InvalidParameter("durations", "none",
                             "must list the segment durations when profile = quadratic-sequence");
    return std::make_unique<PiecewisePolynomialProfile>(
        PiecewisePolynomialProfile::from_accelerations(*c.durations, *c.accelerations));
  }
  if (kind == "fourier")
    return std::make_unique<FourierProfile>(*c.period, *c.fourier_cos, *c.fourier_sin);
  if (kind == "samples") {
    const Interpolation interpolation = parse_interpolation(*c.interpolation);
    const AccelerationSamples samples = load_samples(c, units, scales);
    try {
      return make_sampled_profile(samples, interpolation);
    } catch (const InvalidParameter& e) {  // name the file the user gave, not an internal
      throw InvalidParameter("samples", *c.samples, e.name() + " " + e.value() + ": " + e.allowed());
    }
  }
  throw InvalidParameter("profile", kind,
                         "must be one of: three-phase, quadratic-sequence, piecewise-linear, "
                         "fourier, samples");
}

// The field of field_positions and field_levels (already in [-]): the rows of a field_file.
FrictionField inline_field(const SimulateConfig& c, FieldInterpolation interpolation) {
  if (!c.field_positions || !c.field_levels)
    throw InvalidParameter(c.field_positions ? "field_levels" : "field_positions", "none",
                           "must be given with " +
                               std::string(c.field_positions ? "field_positions" : "field_levels") +
                               ", one level per position");
  const std::vector<double>& x = *c.field_positions;
  const std::vector<double>& level = *c.field_levels;
  if (x.empty() || x.size() != level.size())
    throw InvalidParameter("field_levels", std::to_string(level.size()) + " values",
                           "must give one level per position (" + std::to_string(x.size()) +
                               " field_positions), at least one");
  for (std::size_t i = 0; i < x.size(); ++i) {
    std::string at = "[";  // built by appends: GCC 12 warns (-Wrestrict) on "[" + ... + "]"
    at += std::to_string(i);
    at += ']';
    if (i > 0 && !(x[i] > x[i - 1]))
      throw InvalidParameter("field_positions" + at, x[i],
                             "must be > field_positions[" + std::to_string(i - 1) +
                                 "] = " + format_number(x[i - 1]) + " (strictly increasing)");
    if (!(level[i] >= 0)) throw InvalidParameter("field_levels" + at, level[i], "must be >= 0");
  }
  return FrictionField::samples(x, level, interpolation);
}

// The table's field from field_file, positions converted to [-] in SI runs (m -> x/L), or from
// field_positions and field_levels (converted with the config).
FrictionField load_field(const SimulateConfig& c, UnitSystem units, const Scales& scales) {
  if (!c.field_file && (c.field_positions || c.field_levels)) {
    constexpr UserName kNames[] = {{"interpolation", "field_interpolation"},
                                   {"friction field levels", "field_levels"}};
    return with_user_names(kNames, [&] {
      return inline_field(c, parse_field_interpolation(*c.field_interpolation));
    });
  }
  if (!c.field_file)
    throw InvalidParameter("field_file", "none",
                           "must name a CSV file of 'position,level' rows (or give "
                           "field_positions and field_levels) when friction = field");
  // The field's own parameter "interpolation" is the key field_interpolation here (the
  // samples profile's key is interpolation).
  constexpr UserName kFieldNames[] = {{"interpolation", "field_interpolation"}};
  const FieldInterpolation interpolation = with_user_names(
      kFieldNames, [&] { return parse_field_interpolation(*c.field_interpolation); });
  const FrictionField field = FrictionField::from_csv(*c.field_file, interpolation);
  return units == UnitSystem::dimensionless ? field : field.in_units_of(scales.length());
}

Footprint make_footprint(const SimulateConfig& c) {
  if (*c.footprint == "uniform") return UniformFootprint{require_positive_moderate("width", *c.width)};
  if (*c.footprint == "point") return PointFootprint{};
  throw InvalidParameter("footprint", *c.footprint, "must be one of: uniform, point");
}

// The friction map m(x) named by `friction` (eqs. 7-9), from dimensionless values.
std::unique_ptr<FrictionMap> make_friction(const SimulateConfig& c, UnitSystem units,
                                           const Scales& scales) {
  if (*c.friction == "two-region")
    return std::make_unique<FieldFriction>(TwoRegionTable(*c.x_mu, *c.width, *c.c_mu));
  if (*c.friction == "uniform") return std::make_unique<UniformFriction>(1.0);
  if (*c.friction == "field")
    return std::make_unique<FieldFriction>(load_field(c, units, scales), make_footprint(c));
  throw InvalidParameter("friction", *c.friction, "must be one of: two-region, uniform, field");
}

}  // namespace

namespace {

// The law of a resolved config.
FrictionLaw law_of_resolved(const SimulateConfig& r) {
  FrictionLaw law = law_of_coefficients(*r.mu, r.mu_static, r.mu_backward);
  if (r.stribeck_velocity) law = law.with_stribeck(*r.stribeck_velocity, *r.stribeck_exponent);
  if (r.viscous) law = law.with_viscous(*r.viscous);
  return law;
}

}  // namespace

FrictionLaw friction_law(const SimulateConfig& c) {
  return law_of_resolved(resolve_simulate_config(c));
}

namespace {

void build_physics(const SimulateConfig& c, SimulateModel& m) {
  m.periods = require_positive("periods", *c.periods);
  if (!(m.periods <= kMaxSimulatedPeriods))
    throw InvalidParameter("periods", m.periods, "must be in (0, 1e8]");
  m.options.method = parse_method(*c.method);
  validate(TimeSteppingOptions{*c.step, *c.theta});  // checked for both methods: misuse is misuse
  m.options.step = *c.step;
  m.options.theta = *c.theta;
  m.options.output_step = require_non_negative("output_step", *c.output_step);
  m.options.integrator = {*c.relative_tolerance, *c.absolute_tolerance};
  validate(m.options.integrator);
  m.friction = make_friction(c, m.units, m.scales);
  m.law = law_of_resolved(c);
  m.profile = make_profile(c, m.units, m.scales);
  m.initial = {require_finite("t0", *c.t0), require_finite("x0", *c.x0),
               require_finite("v0", *c.v0)};
  m.options.duration = m.periods * m.profile->period();
}

// The library checks dimensionless values. For an SI run, restate a failed check of one
// dimensional key with the SI value the user gave; otherwise name the scales that converted it.
InvalidParameter in_si_terms(const InvalidParameter& e, const SimulateConfig& si,
                             const Scales& scales) {
  const ConfigKey* key = find_simulate_config_key(e.name());
  if (key && key->dimension == Dimension::none) return e;  // same value in both systems
  if (key) {
    if (const auto* f = std::get_if<NumberField>(&key->field); f && (si.**f))
      return InvalidParameter(e.name(), format_number(*(si.**f)) + " " + std::string(key->unit_si),
                              e.allowed() + " (dimensionless value " + e.value() + ")");
  }
  return InvalidParameter(e.name(), e.value(),
                          e.allowed() + " (checked in dimensionless units: L = " +
                              format_number(scales.length()) + " m, T = " +
                              format_number(scales.time()) + " s, mu g = " +
                              format_number(scales.acceleration()) + " m/s^2)");
}

}  // namespace

SimulateModel build_simulate_model(const SimulateConfig& config) {
  const SimulateConfig resolved = resolve_simulate_config(config);
  const UnitSystem units = parse_unit_system(*resolved.units);
  SimulateModel m{units,
                  Scales(*resolved.length_scale, *resolved.mu, *resolved.g),
                  require_positive("mass", *resolved.mass),
                  0.0, nullptr, nullptr, {}, {}, {}};
  if (units == UnitSystem::dimensionless) {
    build_physics(resolved, m);
    return m;
  }
  try {
    build_physics(to_dimensionless(resolved, m.scales), m);
  } catch (const InvalidParameter& e) {
    throw in_si_terms(e, resolved, m.scales);
  }
  return m;
}

ProfileModel build_profile_model(const SimulateConfig& config, NonPhysicalProfile non_physical) {
  const SimulateConfig resolved = resolve_simulate_config(config);
  ProfileModel m{parse_unit_system(*resolved.units),
                 Scales(*resolved.length_scale, *resolved.mu, *resolved.g), nullptr, {}, {}, {}};
  const bool si = m.units == UnitSystem::si;
  try {
    const SimulateConfig c = si ? to_dimensionless(resolved, m.scales) : resolved;
    m.law = law_of_resolved(c);
    m.integrator = {*c.relative_tolerance, *c.absolute_tolerance};
    validate(m.integrator);
    if (*c.profile == "three-phase") {
      const ThreePhaseParameters p = three_phase_parameters(c);
      validate(p);
      m.three_phase = p;
      if (c.jerk) {  // case 0 of a jerk-limited profile is refused, naming jerk
        validate(JerkLimitedThreePhaseParameters{p.period, p.stroke, p.a2, p.a3, *c.jerk});
        m.jerk = *c.jerk;
        m.profile = make_profile(c, m.units, m.scales);
        return m;
      }
      if (non_physical == NonPhysicalProfile::allow && !solve_three_phase(p).physical) return m;
    }
    m.profile = make_profile(c, m.units, m.scales);
  } catch (const InvalidParameter& e) {
    if (si) throw in_si_terms(e, resolved, m.scales);
    throw;
  }
  return m;
}

std::unique_ptr<FrictionMap> build_friction_map(const SimulateConfig& config) {
  const SimulateConfig resolved = resolve_simulate_config(config);
  const UnitSystem units = parse_unit_system(*resolved.units);
  const Scales scales(*resolved.length_scale, *resolved.mu, *resolved.g);
  if (units == UnitSystem::dimensionless) return make_friction(resolved, units, scales);
  try {
    return make_friction(to_dimensionless(resolved, scales), units, scales);
  } catch (const InvalidParameter& e) {
    throw in_si_terms(e, resolved, scales);
  }
}

}  // namespace selfalign
