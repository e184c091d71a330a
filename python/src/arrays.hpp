#pragma once
// NumPy conversions shared by the bindings: array-likes in, owning arrays or read-only views
// out, and elementwise evaluation of scalar library functions.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "selfalign/error.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace selfalign::python {

namespace py = pybind11;

/// A C-contiguous float64 array converted from any array-like (copies only when needed).
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// values as a C-contiguous float64 array (copied only when needed); TypeError naming `name`
/// and the type it got unless values is a number or an array-like of numbers.
DoubleArray float_array(const py::handle& values, const char* name);

/// Copies a 1-D array-like of floats. Throws InvalidParameter(name) unless it is 1-D.
std::vector<double> to_vector(const py::handle& values, const char* name);

/// Moves a vector into a 1-D NumPy array that owns it (no copy).
template <class T>
py::array_t<T> to_array(std::vector<T>&& values) {
  auto* heap = new std::vector<T>(std::move(values));
  const py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(static_cast<py::ssize_t>(heap->size()), heap->data(), owner);
}

/// Marks an array read-only (views of library results must not write into them).
py::array make_readonly(py::array a);

/// A read-only 1-D view of `values`, which `owner` (the Python object holding them) keeps alive.
template <class T>
py::array readonly_view(const std::vector<T>& values, py::handle owner) {
  return make_readonly(
      py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data(), owner));
}
/// The same for 0/1 flags stored as unsigned char, viewed as a NumPy bool array.
py::array readonly_bool_view(const std::vector<unsigned char>& values, py::handle owner);

/// Binds the std::vector member `member` of Class as a read-only NumPy view property.
template <class PyClass, class Class, class T>
void def_array(PyClass& cls, const char* name, std::vector<T> Class::*member, const char* doc) {
  cls.def_property_readonly(
      name,
      [member](py::object self) { return readonly_view(self.cast<const Class&>().*member, self); },
      doc);
}

/// The failure array of a study whose cells report failures sparsely: '' everywhere (an object
/// array of `shape`) but at the flat indices listed, which hold their messages.
inline py::array sparse_failure_array(const std::vector<std::pair<std::size_t, std::string>>& failures,
                                      const std::vector<py::ssize_t>& shape) {
  py::object numpy = py::module_::import("numpy");
  py::tuple dims(shape.size());
  for (std::size_t i = 0; i < shape.size(); ++i) dims[i] = shape[i];
  py::array a = numpy.attr("full")(dims, py::str(""), py::arg("dtype") = "object");
  py::object flat = a.attr("reshape")(-1);  // a view
  for (const auto& [k, message] : failures) flat[py::int_(k)] = py::str(message);
  return a;
}

/// The cells' `failure` messages as a NumPy array of str (dtype object) of the given shape:
/// '' where the cell was computed, else why it could not be (its numbers are NaN).
template <class Cell>
py::array failure_array(const std::vector<Cell>& cells, const std::vector<py::ssize_t>& shape) {
  std::vector<std::pair<std::size_t, std::string>> failures;
  for (std::size_t k = 0; k < cells.size(); ++k)
    if (!cells[k].failure.empty()) failures.emplace_back(k, cells[k].failure);
  return sparse_failure_array(failures, shape);
}

/// Is x a Python int or float (or a subclass, e.g. numpy.float64)?
inline bool is_scalar(const py::handle& x) {
  return py::isinstance<py::float_>(x) || py::isinstance<py::int_>(x);
}

/// A Python int/float as a double; InvalidParameter(name) for an int too large for a float.
double scalar_value(const py::handle& x, const char* name);

/// What map_elementwise does with NaN and inf: refuse them (most inputs: NaN in, NaN out
/// would hide a mistake upstream), or pass them to f (unit conversions of values where NaN
/// means absent and inf unbounded).
enum class NonFinite { refuse, pass };

/// f(x) elementwise: a Python scalar for a Python int/float, else an ndarray of x's shape
/// with element type R. With NonFinite::refuse, NaN or inf raises InvalidParameter naming
/// `name`.
template <class R, class F>
py::object map_elementwise(const py::handle& x, const F& f, const char* name = "x",
                           NonFinite non_finite = NonFinite::refuse) {
  auto checked = [&](double v) {
    if (non_finite == NonFinite::refuse && !std::isfinite(v))
      throw InvalidParameter(name, v, "must be a finite number");
    return static_cast<R>(f(v));
  };
  if (is_scalar(x)) return py::cast(checked(scalar_value(x, name)));
  const DoubleArray in = float_array(x, name);
  py::array_t<R> out(std::vector<py::ssize_t>(in.shape(), in.shape() + in.ndim()));
  const double* src = in.data();
  R* dst = out.mutable_data();
  for (py::ssize_t i = 0; i < in.size(); ++i) dst[i] = checked(src[i]);
  return out;
}

}  // namespace selfalign::python
