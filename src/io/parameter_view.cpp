#include "selfalign/io/parameter_view.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <variant>

#include "selfalign/error.hpp"
#include "selfalign/io/spelling.hpp"
#include "selfalign/overloaded.hpp"

namespace selfalign {
namespace parameter_view_detail {  // named: ParameterView::Handles holds these

// A factor on the table's motion, y(t) -> a y(t / p).
enum class Factor { amplitude, time };

// Where a parameter lives: a number key, an element of an array key, or a factor.
struct Element {
  NumberListField field;
  std::size_t index;
};
using Handle = std::variant<NumberField, Element, Factor>;

}  // namespace parameter_view_detail

namespace {

using C = SimulateConfig;
using parameter_view_detail::Element;
using parameter_view_detail::Factor;
using parameter_view_detail::Handle;

struct Entry {
  std::string name;
  Handle handle;
  const ConfigKey* key;  // null for the factors
};

const ConfigKey& key_of(std::string_view name) { return *find_simulate_config_key(name); }

void add_key(std::vector<Entry>& out, std::string_view name) {
  const ConfigKey& k = key_of(name);
  out.push_back({std::string(name), std::get<NumberField>(k.field), &k});
}

void add_elements(std::vector<Entry>& out, const C& c, std::string_view name) {
  const ConfigKey& k = key_of(name);
  const NumberListField f = std::get<NumberListField>(k.field);
  for (std::size_t i = 0; i < (c.*f)->size(); ++i) {
    std::string element(name);  // by appends: GCC 12 warns (-Wrestrict) on a + "[" + ... chain
    element += '[';
    element += std::to_string(i);
    element += ']';
    out.push_back({std::move(element), Element{f, i}, &k});
  }
}

// The parameters of a resolved config, in view order.
std::vector<Entry> entries(const C& c) {
  std::vector<Entry> out;
  for (const char* k : {"mu", "mu_static", "mu_backward", "stribeck_velocity",
                        "stribeck_exponent", "viscous"})
    add_key(out, k);
  if (*c.units == "si") add_key(out, "g");

  const std::string& friction = *c.friction;
  if (friction == "two-region") {
    for (const char* k : {"x_mu", "width", "c_mu"}) add_key(out, k);
  } else if (friction == "field") {
    if (c.field_positions && c.field_levels) {
      add_elements(out, c, "field_positions");
      add_elements(out, c, "field_levels");
    }
    if (*c.footprint == "uniform") add_key(out, "width");
  } else if (friction != "uniform") {
    throw InvalidParameter("friction", friction, "must be one of: two-region, uniform, field");
  }

  const std::string& profile = *c.profile;
  if (profile == "three-phase") {
    for (const char* k : {"period", "stroke", "a2", "a3"}) add_key(out, k);
    if (c.jerk) add_key(out, "jerk");
  } else if (profile == "fourier") {
    add_key(out, "period");
    add_elements(out, c, "fourier_cos");
    add_elements(out, c, "fourier_sin");
  } else if (profile == "quadratic-sequence") {
    add_elements(out, c, "durations");
    add_elements(out, c, "accelerations");
  } else if (profile == "piecewise-linear") {
    if (c.times) add_elements(out, c, "times");
    add_elements(out, c, "accelerations");
    add_key(out, "period");
  } else if (profile != "samples") {
    throw InvalidParameter("profile", profile,
                           "must be one of: three-phase, quadratic-sequence, piecewise-linear, "
                           "fourier, samples");
  }
  if (profile != "samples") {
    out.push_back({"amplitude_scale", Factor::amplitude, nullptr});
    out.push_back({"time_scale", Factor::time, nullptr});
  }
  for (const char* k : {"t0", "x0", "v0"}) add_key(out, k);
  return out;
}

double value_of(const C& c, const Handle& h) {
  return std::visit(
      Overloaded{[&](NumberField f) {
                   if (c.*f) return *(c.*f);
                   // Unset law keys: mu_static and mu_backward default to mu; no Stribeck
                   // decay (NaN: absent); no viscous term (c = 0).
                   if (f == &C::mu_static || f == &C::mu_backward) return *c.mu;
                   if (f == &C::viscous) return 0.0;
                   return std::numeric_limits<double>::quiet_NaN();
                 },
                 [&](const Element& e) { return (*(c.*e.field))[e.index]; },
                 [](Factor) { return 1.0; }},
      h);
}

void scale_list(std::optional<std::vector<double>>& values, double factor) {
  if (values)
    for (double& v : *values) v *= factor;
}

void scale_number(std::optional<double>& value, double factor) {
  if (value) *value *= factor;
}

// y(t) -> a y(t / p) on the profile's keys: lengths x a, times x p, accelerations x a/p^2,
// jerks x a/p^3 (the new profile's y, y'' and y''' at t are a, a/p^2 and a/p^3 times the old
// profile's at t/p).
void scale_motion(C& c, double a, double p) {
  const double acceleration = a / (p * p);
  scale_number(c.stroke, a);
  scale_list(c.fourier_cos, a);
  scale_list(c.fourier_sin, a);
  scale_number(c.period, p);
  scale_list(c.durations, p);
  scale_list(c.times, p);
  scale_number(c.a2, acceleration);
  scale_number(c.a3, acceleration);
  scale_list(c.accelerations, acceleration);
  scale_number(c.jerk, acceleration / p);
}

void set_value(C& c, const Handle& h, double value) {
  std::visit(Overloaded{[&](NumberField f) { c.*f = value; },
                        [&](const Element& e) { (*(c.*e.field))[e.index] = value; },
                        [&](Factor f) {
                          if (f == Factor::amplitude) scale_motion(c, value, 1.0);
                          else scale_motion(c, 1.0, value);
                        }},
             h);
}

bool is_setting(const ConfigKey& key) {
  return key.group == "run" || key.group == "solver" || key.group == "output" ||
         key.name == "length_scale" || key.name == "mass";
}

// Why `name` is not a parameter of the model of `c`.
InvalidParameter not_a_parameter(const C& c, const std::string& name,
                                 const std::vector<Entry>& view) {
  const std::string base = name.substr(0, name.find('['));
  if (const ConfigKey* key = find_simulate_config_key(base)) {
    if (is_setting(*key))
      return InvalidParameter(name, "a setting",
                              "is a setting of the run, not a model parameter "
                              "(`selfalign parameters` lists the model's)");
    if (const auto* list = std::get_if<NumberListField>(&key->field)) {
      if (base == name)
        return InvalidParameter(name, "an array", "give one element, " + base +
                                                      "[i] (indices from 0)");
      for (const Entry& e : view)
        if (e.key == key)
          return InvalidParameter(name, "index out of range",
                                  "has indices 0.." + std::to_string((c.**list)->size() - 1));
    }
    return InvalidParameter(name, "not in this model",
                            "is not a parameter of this model (profile = " + *c.profile +
                                ", friction = " + *c.friction + ", units = " + *c.units + ")");
  }
  if (name == "amplitude_scale" || name == "time_scale")
    return InvalidParameter(name, "not in this model",
                            "is not a parameter of this model (profile = " + *c.profile +
                                ": its motion is in its file)");
  std::vector<std::string> names;
  for (const Entry& e : view) names.push_back(e.name);
  const std::string best = closest_name(name, names);
  return InvalidParameter(
      name, "unknown parameter",
      "is not a parameter" + (best.empty() ? std::string() : " (did you mean " + best + "?)") +
          "; `selfalign parameters` lists the model's");
}

const std::string kFactorMeaning[2] = {
    "factor a on the table's motion, y(t) -> a y(t): strokes, accelerations, jerks and "
    "Fourier coefficients x a, > 0",
    "factor p on the table's period, y(t) -> y(t / p): period, durations and times x p, "
    "accelerations x 1/p^2, jerks x 1/p^3, > 0"};

}  // namespace

std::vector<ModelParameter> model_parameters(const SimulateConfig& config) {
  const C c = resolve_simulate_config(config);
  const bool si = *c.units == "si";
  std::vector<ModelParameter> out;
  for (const Entry& e : entries(c)) {
    if (!e.key) {
      const bool time = std::get<Factor>(e.handle) == Factor::time;
      out.push_back({e.name, 1.0, Dimension::none, "[-]", "profile", kFactorMeaning[time]});
      continue;
    }
    out.push_back({e.name, value_of(c, e.handle), e.key->dimension,
                   std::string(si ? e.key->unit_si : e.key->unit), std::string(e.key->group),
                   std::string(e.key->help)});
  }
  return out;
}

struct ParameterView::Handles {
  std::vector<Handle> handles;
};

ParameterView::ParameterView(const SimulateConfig& config, const std::vector<std::string>& free)
    : config_(resolve_simulate_config(config)), names_(free), handles_(std::make_unique<Handles>()) {
  const std::vector<Entry> view = entries(config_);
  for (const std::string& name : free) {
    if (name.empty())
      throw InvalidParameter("parameter", "\"\"",
                             "must name a parameter of the model (selfalign parameters lists "
                             "them)");
    const Entry* found = nullptr;
    for (const Entry& e : view)
      if (e.name == name) found = &e;
    if (!found) throw not_a_parameter(config_, name, view);
    handles_->handles.push_back(found->handle);
  }
}

ParameterView::~ParameterView() = default;
ParameterView::ParameterView(ParameterView&&) noexcept = default;
ParameterView& ParameterView::operator=(ParameterView&&) noexcept = default;

std::vector<double> ParameterView::values() const {
  std::vector<double> out;
  for (const Handle& h : handles_->handles) out.push_back(value_of(config_, h));
  return out;
}

SimulateConfig ParameterView::with(const std::vector<double>& values) const {
  if (values.size() != names_.size())
    throw InvalidParameter("values", std::to_string(values.size()) + " values",
                           "must give one value per free parameter (" +
                               std::to_string(names_.size()) + ")");
  SimulateConfig c = config_;
  for (std::size_t k = 0; k < values.size(); ++k) {
    const Handle& h = handles_->handles[k];
    if (std::holds_alternative<Factor>(h)) require_positive(names_[k], values[k]);
    else require_finite(names_[k], values[k]);
    set_value(c, h, values[k]);
  }
  return c;
}

SimulateConfig with_parameters(const SimulateConfig& config, const ParameterValues& values) {
  std::vector<std::string> names;
  std::vector<double> numbers;
  for (const auto& [name, value] : values) names.push_back(name), numbers.push_back(value);
  return ParameterView(config, names).with(numbers);
}

}  // namespace selfalign
