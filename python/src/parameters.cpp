// The parameter view (io/parameter_view.hpp) for Python: a model described by its config keys
// (a dict, the keys of `selfalign simulate`'s config files), its named parameters, and the same
// model with some of them changed.

#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "arguments.hpp"
#include "bindings.hpp"
#include "record.hpp"
#include "repr.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/parameter_view.hpp"
#include "selfalign/io/planar_config.hpp"

namespace selfalign::python {
namespace {

// A number from Python, or InvalidParameter naming `name` (an int beyond double, a str, ...).
double number_of(const std::string& name, const py::handle& value) {
  if (!py::isinstance<py::bool_>(value)) {
    try {
      return value.cast<double>();
    } catch (const py::cast_error&) {
    } catch (const py::error_already_set&) {  // OverflowError of an int beyond double
    }
  }
  std::string text = py::repr(value);
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  throw InvalidParameter(name, text, "must be a finite number with |value| <= 1e50");
}

// One value of a config dict as the key's command-line text.
std::string text_of(const std::string& key, const py::handle& value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::bool_>(value))
    throw InvalidParameter(key, "a bool", "must be a string, a number or a list of numbers");
  if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value))
    return format_number(number_of(key, value));
  if (py::isinstance<py::sequence>(value) || py::hasattr(value, "__array__")) {
    std::string s;
    for (const py::handle& v : py::iter(value)) {
      if (!s.empty()) s += ',';
      s += format_number(number_of(key, v));
    }
    return s;
  }
  throw InvalidParameter(key, python_type_name(value),
                         "must be a string, a number or a list of numbers");
}

}  // namespace

SimulateConfig config_of(const py::dict& d) {
  SimulateConfig c;
  for (const auto& [k, v] : d) {
    const std::string key = py::str(k);
    set_simulate_config_value(c, key, text_of(key, v));
  }
  return c;
}

namespace {

py::dict dict_of(const SimulateConfig& c) {
  py::dict d;
  for (const ConfigKey& key : simulate_config_keys())
    std::visit(
        [&](auto field) {
          if (!(c.*field)) return;
          using V = std::decay_t<decltype(*(c.*field))>;
          if constexpr (std::is_same_v<V, std::vector<double>>)
            d[py::str(std::string(key.name))] = py::cast(*(c.*field));
          else
            d[py::str(std::string(key.name))] = *(c.*field);
        },
        key.field);
  return d;
}

}  // namespace

void bind_parameters(py::module_& m) {
  py::class_<ModelParameter> p(m, "ModelParameter", R"doc(
One named parameter of a model (C++ selfalign::ModelParameter): name ("mu_static",
"accelerations[2]", "amplitude_scale"), value in the run's unit system (NaN when absent: no
Stribeck decay), unit ("[-]" or the SI unit in an SI run), group ("law", "scales", "friction",
"profile", "initial") and meaning.)doc");
  p.def_readonly("name", &ModelParameter::name, "the name with_parameters takes")
      .def_readonly("value", &ModelParameter::value,
                    "value in the run's unit system; NaN when absent")
      .def_readonly("unit", &ModelParameter::unit, "\"[-]\", or the SI unit in an SI run")
      .def_readonly("group", &ModelParameter::group,
                    "law, scales, friction, profile or initial")
      .def_readonly("meaning", &ModelParameter::meaning, "what it is, one line")
      .def("__repr__", [](const ModelParameter& x) {
        return Repr("ModelParameter")
            .raw("name", "'" + x.name + "'")("value", x.value)
            .raw("unit", "'" + x.unit + "'")
            .str();
      });
  def_record(
      p,
      [](std::string name, double value, std::string unit, std::string group,
         std::string meaning) {
        return ModelParameter{std::move(name), value, Dimension::none, std::move(unit),
                              std::move(group), std::move(meaning)};
      },
      field("name", &ModelParameter::name), field("value", &ModelParameter::value),
      field("unit", &ModelParameter::unit), field("group", &ModelParameter::group),
      field("meaning", &ModelParameter::meaning));

  m.def(
      "model_parameters",
      [](const py::dict& config) { return model_parameters(config_of(config)); },
      py::arg("config"), R"doc(
The named parameters of the model a config describes (C++ model_parameters,
io/parameter_view.hpp): `config` is a dict of config keys (those of `selfalign simulate`'s
config files, e.g. {"units": "si", "mu": 0.2, "a2": 3.0}; arrays as lists), unset keys at their
defaults. Returns a list of ModelParameter in view order: law (mu, mu_static, mu_backward,
stribeck_velocity, stribeck_exponent, viscous), g in SI runs, the friction table's (x_mu, width,
c_mu for two-region), the profile's (arrays by element, "accelerations[0]") with the factors
amplitude_scale and time_scale (y(t) -> a y(t / p)), and t0, x0, v0. Raises InvalidParameter
for a config that does not resolve.)doc");
  m.def(
      "planar_model_parameters",
      [](const py::object& path, const std::vector<std::string>& set) {
        if (!py::isinstance<py::str>(path) && !py::hasattr(path, "__fspath__"))
          throw py::type_error("config: expected a str or os.PathLike, got " +
                               python_type_name(path));
        return planar_model_parameters(py::str(py::module_::import("os").attr("fspath")(path)),
                                       set);
      },
      py::arg("config"), py::arg("set") = std::vector<std::string>{}, R"doc(
The named parameters of the planar model a config file describes (C++
planar_model_parameters, io/planar_config.hpp; `selfalign planar parameters`): every number the
model depends on (scales, table motion, part, friction, field, initial pose and twist), in the
order the model reads them, with its value as the file gives it (its default where unset) and
unit; arrays by element ("field.levels[2]", "run.pose[0]"). Settings (the unit length, the
reported mass, discretisation, solver and analysis keys) are not parameters. `set` holds
"SECTION.KEY=VALUE" or "SECTION.KEY[i]=VALUE" changes applied first, checked as the file's
values are (the same names). Raises InvalidParameter naming the key.)doc");
  m.def(
      "with_parameters",
      [](const py::dict& config, const py::dict& values) {
        ParameterValues v;
        for (const auto& [k, x] : values) {
          const std::string name = py::str(k);
          v.emplace_back(name, number_of(name.empty() ? "values" : name, x));
        }
        return dict_of(with_parameters(config_of(config), v));
      },
      py::arg("config"), py::arg("values"), R"doc(
The config with some parameters changed (C++ with_parameters(config, values)): `values` maps parameter
names (those model_parameters lists) to numbers, applied in order; a factor (amplitude_scale,
time_scale) rescales the profile's keys as they stand. Returns the resolved config as a dict
(every key set). Raises InvalidParameter naming a name that is not a parameter of this model
(with the model's kinds), a setting (step, method, ...), an index out of range or a value that
is not finite; values out of range are refused when the model is built.)doc");
}

}  // namespace selfalign::python
