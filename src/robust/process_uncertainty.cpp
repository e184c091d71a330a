#include "selfalign/robust/process_uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "selfalign/error.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/io/parameter_view.hpp"
#include "selfalign/io/simulate_model.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/profiles/make_three_phase_profile.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/units.hpp"

namespace selfalign {
namespace {

double static_ratio_of(const DesignRequest& q) {
  return q.mu_static.value_or(q.mu) / q.mu;
}

const std::array<UncertainInput, kUncertainInputs> kInputs{{
    {"mu", "-", &ProcessUncertainty::mu, [](const DesignRequest& q) { return q.mu; }, 0, false,
     "kinetic friction coefficient of the smooth region"},
    {"c_mu", "-", &ProcessUncertainty::c_mu, [](const DesignRequest& q) { return q.c_mu; }, 1,
     false, "friction ratio of the rough region mu_2/mu_1"},
    {"static_ratio", "-", &ProcessUncertainty::static_ratio, static_ratio_of, 1, true,
     "static/kinetic ratio mu_static/mu_1"},
    {"width", "m", &ProcessUncertainty::width, [](const DesignRequest& q) { return q.width; }, 0,
     false, "transition width (the object's width)"},
    {"x_mu_offset", "m", &ProcessUncertainty::x_mu_offset,
     [](const DesignRequest&) { return 0.0; }, -std::numeric_limits<double>::infinity(), false,
     "error of the rough region's start"},
    {"amplitude", "-", &ProcessUncertainty::amplitude, [](const DesignRequest&) { return 1.0; },
     0, false, "factor on the table's displacement"},
    {"period_factor", "-", &ProcessUncertainty::period_factor,
     [](const DesignRequest&) { return 1.0; }, 0, false, "factor on the table's period"},
}};

std::uint64_t splitmix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

const std::array<UncertainInput, kUncertainInputs>& uncertain_inputs() { return kInputs; }

std::size_t uncertain_input_index(const std::string& name) {
  std::string names;
  for (std::size_t k = 0; k < kInputs.size(); ++k) {
    if (name == kInputs[k].name) return k;
    names += (k ? ", " : "") + std::string(kInputs[k].name);
  }
  throw InvalidParameter("uncertain", name, "must name one of: " + names);
}

void set_input(ProcessUncertainty& u, const std::string& name, const std::string& text) {
  u.*kInputs[uncertain_input_index(name)].member = parse_distribution(name, text);
}

void validate(const ProcessUncertainty& u) {
  for (const UncertainInput& in : kInputs) {
    const Distribution& d = u.*in.member;
    validate(in.name, d);
    if (!is_uncertain(d)) continue;
    // Every draw must be a valid input: the support (a normal's to ~8.3 sd) within the domain.
    const auto [lo, hi] = box(d, 0, kDrawSigmas);
    if (in.inclusive ? !(lo >= in.lowest) : !(lo > in.lowest))
      throw InvalidParameter(std::string(in.name) + ".lower", lo,
                             std::string("draws must be ") + (in.inclusive ? ">= " : "> ") +
                                 format_number(in.lowest) +
                                 " (truncate the normal with a lower bound)");
    require_moderate(std::string(in.name) + ".upper", hi);
  }
}

InputValues nominal_inputs(const DesignRequest& q, const ProcessUncertainty& u) {
  InputValues v{};
  for (std::size_t k = 0; k < kInputs.size(); ++k)
    v[k] = nominal(u.*kInputs[k].member, kInputs[k].known(q));
  return v;
}

double uniform_draw(std::uint64_t seed, std::uint64_t run, std::uint64_t input) {
  const std::uint64_t h =
      splitmix64(splitmix64(splitmix64(seed) ^ run) + 0x632be59bd9b4e019ULL * (input + 1));
  return (static_cast<double>(h >> 11) + 0.5) * 0x1.0p-53;
}

InputValues draw_inputs(const DesignRequest& q, const ProcessUncertainty& u, std::uint64_t seed,
                        std::uint64_t run) {
  InputValues known{};
  for (std::size_t k = 0; k < kInputs.size(); ++k) known[k] = kInputs[k].known(q);
  return draw_inputs(known, u, seed, run, 0);
}

InputValues draw_inputs(const InputValues& known, const ProcessUncertainty& u, std::uint64_t seed,
                        std::uint64_t run, std::uint64_t stream) {
  InputValues v{};
  for (std::size_t k = 0; k < kInputs.size(); ++k)
    v[k] = quantile(u.*kInputs[k].member, uniform_draw(seed, run, stream + k), known[k]);
  return v;
}

Process process_of(const DesignResult& d) {
  if (!d.feasible && !(d.period > 0))
    throw InvalidParameter("design", "infeasible", "has no process to evaluate");
  return {d.period, d.stroke, d.a2, d.a3, d.jerk, d.x_mu};
}

void validate(const Process& p) {
  require_positive_moderate("period", p.period);
  require_positive_moderate("stroke", p.stroke);
  require_positive_moderate("a2", p.a2);
  require_positive_moderate("a3", p.a3);
  if (!(p.jerk > 0) || std::isnan(p.jerk))
    throw InvalidParameter("jerk", p.jerk, "must be > 0 [m/s^3] (+inf: jump accelerations)");
  require_positive_moderate("x_mu", p.x_mu);
  // Case 0 does not depend on the units (eqs. 61-67 scale with the stroke and the period).
  const bool physical =
      std::isinf(p.jerk)
          ? solve_three_phase({p.period, p.stroke, p.a2, p.a3}).physical
          : solve_jerk_limited_three_phase({p.period, p.stroke, p.a2, p.a3, p.jerk}).physical;
  if (!physical)
    throw InvalidParameter("process", "a2 = " + format_number(p.a2) + ", a3 = " +
                                          format_number(p.a3),
                           "must be a physical three-phase profile for its period and stroke "
                           "(case 0: the table cannot reach the stroke)");
}

namespace {

// The process as a model config: SI, the three-phase table (jumps or the jerk limit), the
// two-region table at x_mu, the request's law and gravity, lengths in units of the nominal
// width (a draw's config takes its drawn width as the unit: ProcessFamily::config).
SimulateConfig process_config(const DesignRequest& q, const Process& p) {
  SimulateConfig c;
  c.units = "si";
  c.profile = "three-phase";
  c.period = p.period, c.stroke = p.stroke, c.a2 = p.a2, c.a3 = p.a3;
  if (!std::isinf(p.jerk)) c.jerk = p.jerk;
  c.friction = "two-region";
  c.x_mu = p.x_mu, c.width = q.width, c.c_mu = q.c_mu;
  c.mu = q.mu, c.mu_static = q.mu_static, c.mu_backward = q.mu_backward;
  c.g = q.gravity, c.length_scale = q.width;
  return c;
}

// The seven inputs as parameters of the process's model, in draw_values' order.
const std::vector<std::string> kDrawnParameters{"mu",    "c_mu", "mu_static",       "mu_backward",
                                                "width", "x_mu", "amplitude_scale", "time_scale"};

// A draw as values of kDrawnParameters: the absolute coefficients follow the drawn mu (the
// static one by the drawn ratio, the backward one by the request's ratio, capped by the static
// one), x_mu moves by the drawn offset, and the table's motion y(t) -> a y(t / p).
std::vector<double> draw_values(const DesignRequest& q, const Process& p, const InputValues& v) {
  const double mu = v[0], static_ratio = v[2];
  const double backward_ratio = std::min(q.mu_backward.value_or(q.mu) / q.mu, static_ratio);
  return {mu, v[1], static_ratio * mu, backward_ratio * mu, v[3], p.x_mu + v[4], v[5], v[6]};
}

}  // namespace

ProcessFamily::ProcessFamily(const DesignRequest& q, const Process& p)
    : request_(q), process_(p), view_(process_config(q, p), kDrawnParameters) {}

SimulateConfig ProcessFamily::config(const InputValues& v) const {
  SimulateConfig c = view_.with(draw_values(request_, process_, v));
  c.length_scale = v[3];  // the unit: L = the drawn width (Sect. 3.2)
  return c;
}

ProcessModel::ProcessModel(const DesignRequest& q, const Process& p, const InputValues& v)
    : ProcessModel(ProcessFamily(q, p), v) {}

ProcessModel::ProcessModel(const ProcessFamily& family, const InputValues& v)
    : scales(v[3], v[0], family.request().gravity) {
  SimulateModel m = build_simulate_model(family.config(v));
  profile = std::move(m.profile);
  law = m.law;
  const TwoRegionTable* table = m.friction->two_region();
  c_mu = table->c_mu();
  x_mu = table->x_mu();
}

namespace {

// Whether the model takes the draw `v`; else what it refused, in its own (model) terms.
std::optional<InvalidParameter> refusal(const DesignRequest& q, const Process& p,
                                        const InputValues& v) {
  try {
    // Building the model builds the rough region it would stop on too (the two-region table
    // of the draw's config), so its refusal is caught here as well.
    const ProcessModel m(q, p, v);
  } catch (const InvalidParameter& e) {
    return e;
  }
  return std::nullopt;
}

// What the model refused, after "give no process the model takes".
std::string refused(const InvalidParameter& e) {
  return " (in units of the drawn width, " + e.name() + " = " + e.value() + ": " + e.allowed() +
         ")";
}

}  // namespace

void validate_draws(const DesignRequest& q, const Process& p, const ProcessUncertainty& u) {
  const InputValues nominal = nominal_inputs(q, u);
  std::vector<std::size_t> uncertain;
  std::array<std::pair<double, double>, kUncertainInputs> ends{};
  for (std::size_t k = 0; k < kInputs.size(); ++k) {
    const Distribution& d = u.*kInputs[k].member;
    ends[k] = {nominal[k], nominal[k]};
    if (!is_uncertain(d)) continue;
    uncertain.push_back(k);
    ends[k] = box(d, 0, kDrawSigmas);
    // One input at a time, at either end of its draws: the message names it.
    for (const bool upper : {false, true}) {
      InputValues v = nominal;
      v[k] = upper ? ends[k].second : ends[k].first;
      if (const auto e = refusal(q, p, v))
        throw InvalidParameter(std::string(kInputs[k].name) + (upper ? ".upper" : ".lower"), v[k],
                               "draws this far give no process the model takes" + refused(*e));
    }
  }
  // Every corner of the box (at most 2^7 models, each a closed form): a combination of draws.
  if (uncertain.size() < 2) return;
  for (std::size_t corner = 0; corner < (std::size_t{1} << uncertain.size()); ++corner) {
    InputValues v = nominal;
    std::string names, values;
    for (std::size_t i = 0; i < uncertain.size(); ++i) {
      const std::size_t k = uncertain[i];
      v[k] = (corner >> i) & 1 ? ends[k].second : ends[k].first;
      names += (i ? ", " : "") + std::string(kInputs[k].name);
      values += (i ? ", " : "") + format_number(v[k]);
    }
    if (const auto e = refusal(q, p, v))
      throw InvalidParameter(names, values,
                             "these draws together give no process the model takes" + refused(*e));
  }
}

StoppingOptions ProcessModel::stopping(int max_periods) {
  StoppingOptions so;
  so.max_periods = max_periods;
  so.fractions = {0.999};  // accumulation "arrives" 0.999 of the way (as design_process)
  return so;
}

ProcessOutcome ProcessModel::outcome(const StoppingRun& run) const {
  ProcessOutcome o;
  o.kind = run.kind;
  o.entry_time = scales.time_to_si(run.entry_time);
  if (run.kind == StopKind::not_stopped) return o;
  o.end_position = scales.length_to_si(run.end_position);
  o.process_time = scales.time_to_si(run.kind == StopKind::accumulation ? run.time_to_fraction[0]
                                                                        : run.process_time);
  return o;
}

ProcessOutcome run_process(const DesignRequest& q, const Process& p, const InputValues& v,
                           int max_periods) {
  return run_process(ProcessFamily(q, p), v, max_periods);
}

ProcessOutcome run_process(const ProcessFamily& family, const InputValues& v, int max_periods) {
  const ProcessModel m(family, v);
  const FieldFriction friction = two_region_friction(m.x_mu, 1.0, m.c_mu);
  const StoppingOptions so = ProcessModel::stopping(max_periods);
  return m.outcome(stopping_run(*m.profile, friction, m.law, {0, 0, 0}, so));
}

}  // namespace selfalign
