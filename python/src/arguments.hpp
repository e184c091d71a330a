#pragma once
// Arguments a binding takes as py::object (None allowed, several forms accepted) converted to
// a C++ type with a TypeError that names the parameter and the expected type, never pybind11's
// bare "Unable to cast Python instance to C++ type".

#include <pybind11/pybind11.h>

#include <string>
#include <utility>

namespace selfalign::python {

namespace py = pybind11;

/// The name of value's type as Python shows it, e.g. 'str'.
inline std::string python_type_name(const py::handle& value) {
  return py::type::of(value).attr("__name__").cast<std::string>();
}

/// value as a T, as pybind11 converts an argument of type T (ints to float, ...); TypeError
/// "<name>: expected <expected>, got <type>" when it cannot.
template <class T>
T argument(const py::handle& value, const std::string& name, const std::string& expected) {
  py::detail::make_caster<T> caster;
  if (!caster.load(value, true))
    throw py::type_error(name + ": expected " + expected + ", got " + python_type_name(value));
  return py::detail::cast_op<T>(std::move(caster));
}

}  // namespace selfalign::python
