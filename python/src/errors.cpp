// selfalign::InvalidParameter -> selfalign.InvalidParameter, a ValueError carrying the
// parameter's name, its value and the allowed range as attributes. pybind11's cast_error (a
// conversion a binding did not name: arguments.hpp's argument() names the parameter) ->
// TypeError, not pybind11's RuntimeError "Unable to cast Python instance to C++ type".
#include "bindings.hpp"
#include "selfalign/error.hpp"

namespace selfalign::python {

namespace {
PyObject* invalid_parameter_type = nullptr;  // owned by the module for the process's lifetime
}  // namespace

void bind_errors(py::module_& m) {
  auto type = py::exception<InvalidParameter>(m, "InvalidParameter", PyExc_ValueError);
  type.attr("__module__") = "selfalign";
  type.doc() =
      "A parameter outside its allowed range: misuse of the API (a negative width, c_mu <= 1,\n"
      "NaN). Expected outcomes (a non-physical case-0 profile, a run that never stops) are\n"
      "values, not exceptions.\n\n"
      "str(e) is one line, 'invalid <name> = <value>: <allowed>'. Attributes (all str):\n"
      "  name     the parameter, e.g. 'width'\n"
      "  value    its value as given, e.g. '-1' or 'nan'\n"
      "  allowed  the allowed range, e.g. 'must be > 0'";
  invalid_parameter_type = type.release().ptr();

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidParameter& e) {
      py::object error = py::reinterpret_borrow<py::object>(invalid_parameter_type)(e.what());
      error.attr("name") = e.name();
      error.attr("value") = e.value();
      error.attr("allowed") = e.allowed();
      PyErr_SetObject(invalid_parameter_type, error.ptr());
    } catch (const py::cast_error&) {
      PyErr_SetString(PyExc_TypeError, "a value has the wrong type and could not be converted");
    }
  });
}

}  // namespace selfalign::python
