#include "arrays.hpp"

#include <string>

#include "arguments.hpp"
#include "selfalign/error.hpp"

namespace selfalign::python {

DoubleArray float_array(const py::handle& values, const char* name) {
  DoubleArray a;
  if (!values.is_none()) a = DoubleArray::ensure(values);  // None would become NaN
  if (values.is_none() || !a)
    throw py::type_error(std::string(name) + ": expected a float or an array-like of floats, got " +
                         python_type_name(values));
  return a;
}

std::vector<double> to_vector(const py::handle& values, const char* name) {
  const DoubleArray a = float_array(values, name);
  if (a.ndim() != 1)
    throw InvalidParameter(name, "an array with " + std::to_string(a.ndim()) + " dimensions",
                           "must be one-dimensional");
  return {a.data(), a.data() + a.size()};
}

double scalar_value(const py::handle& x, const char* name) {
  const double v = PyFloat_AsDouble(x.ptr());
  if (v == -1.0 && PyErr_Occurred()) {  // e.g. 2**2000: OverflowError in Python's conversion
    PyErr_Clear();
    throw InvalidParameter(name, py::str(x).cast<std::string>(),
                           "must be a number a float can hold (|x| <= 1.8e308)");
  }
  return v;
}

py::array make_readonly(py::array a) {
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

py::array readonly_bool_view(const std::vector<unsigned char>& values, py::handle owner) {
  static_assert(sizeof(bool) == sizeof(unsigned char));
  return make_readonly(py::array(py::dtype::of<bool>(), {static_cast<py::ssize_t>(values.size())},
                                 {}, values.data(), owner));
}

}  // namespace selfalign::python
