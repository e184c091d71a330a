#pragma once
// 2x2 matrices (monodromy matrices) to NumPy, shared by floquet.cpp and solvers.cpp.

#include <pybind11/numpy.h>

#include <Eigen/Core>

namespace selfalign::python {

/// A 2x2 float64 ndarray copy of a.
inline pybind11::array_t<double> matrix_array(const Eigen::Matrix2d& a) {
  pybind11::array_t<double> out({2, 2});
  auto r = out.mutable_unchecked<2>();
  for (pybind11::ssize_t i = 0; i < 2; ++i)
    for (pybind11::ssize_t j = 0; j < 2; ++j) r(i, j) = a(i, j);
  return out;
}

}  // namespace selfalign::python
