#pragma once
// Library enums whose values the Python API also hands out as plain ints (case numbers in
// sweep arrays, arc kinds in exact_arcs, case-0 reasons) are bound as real Python enum.IntEnum classes: they
// compare equal to ints, hash like ints, pickle, and convert from ints. A type caster maps the
// C++ enum to and from the IntEnum class created by bind_int_enum. Every translation unit of
// the module sees these casters through bindings.hpp (one definition of each caster).

#include <pybind11/pybind11.h>

#include <initializer_list>
#include <string>
#include <utility>

#include "selfalign/analysis/feeder.hpp"
#include "selfalign/analysis/motion_case.hpp"
#include "selfalign/error.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/simulate/arc.hpp"

namespace selfalign::python {

/// The Python IntEnum class of Enum (set once by bind_int_enum, kept for the process).
template <class Enum>
struct IntEnumClass {
  static inline PyObject* type = nullptr;
};

/// Creates enum.IntEnum `name` (module 'selfalign') with these members and adds it to m.
template <class Enum>
void bind_int_enum(pybind11::module_& m, const char* name, const char* doc,
                   std::initializer_list<std::pair<const char*, Enum>> members) {
  namespace py = pybind11;
  py::list items;
  for (const auto& [member, value] : members)
    items.append(py::make_tuple(member, static_cast<int>(value)));
  py::object cls =
      py::module_::import("enum").attr("IntEnum")(name, items, py::arg("module") = "selfalign");
  cls.attr("__doc__") = doc;
  m.attr(name) = cls;
  IntEnumClass<Enum>::type = cls.release().ptr();
}

/// Makes Enum(int) of a pybind11 enum_ refuse values that are not members (pybind11 accepts
/// any int and shows it as 'Enum.???'): a checked constructor placed before pybind11's own.
/// The members are 0 .. count - 1.
template <class Enum>
void refuse_unknown_values(pybind11::enum_<Enum>& e, const char* name, int count) {
  namespace py = pybind11;
  e.def(py::init([name, count](int value) {
          if (value < 0 || value >= count)
            throw InvalidParameter(name, static_cast<double>(value),
                                   "must be one of the members 0.." + std::to_string(count - 1));
          return static_cast<Enum>(value);
        }),
        py::arg("value"), py::prepend());
}

}  // namespace selfalign::python

namespace pybind11::detail {

template <class Enum>
struct int_enum_caster {
  PYBIND11_TYPE_CASTER(Enum, const_name("IntEnum"));

  // Accepts a member of the class, or (when converting) anything the class accepts: an int.
  bool load(handle src, bool convert) {
    const handle type(selfalign::python::IntEnumClass<Enum>::type);
    if (!convert && !isinstance(src, type)) return false;
    try {
      value = static_cast<Enum>(reinterpret_borrow<object>(type)(src).template cast<int>());
      return true;
    } catch (const error_already_set&) {
      return false;
    }
  }
  static handle cast(Enum src, return_value_policy, handle) {
    const handle type(selfalign::python::IntEnumClass<Enum>::type);
    return reinterpret_borrow<object>(type)(static_cast<int>(src)).release();
  }
};

template <>
struct type_caster<selfalign::StickSlipCase> : int_enum_caster<selfalign::StickSlipCase> {
  static constexpr auto name = const_name("StickSlipCase");
};
template <>
struct type_caster<selfalign::ArcKind> : int_enum_caster<selfalign::ArcKind> {
  static constexpr auto name = const_name("ArcKind");
};
template <>
struct type_caster<selfalign::ArcEnd> : int_enum_caster<selfalign::ArcEnd> {
  static constexpr auto name = const_name("ArcEnd");
};
template <>
struct type_caster<selfalign::JerkLimitedCase0> : int_enum_caster<selfalign::JerkLimitedCase0> {
  static constexpr auto name = const_name("JerkLimitedCase0");
};
template <>
struct type_caster<selfalign::FeederEvent> : int_enum_caster<selfalign::FeederEvent> {
  static constexpr auto name = const_name("FeederEvent");
};
template <>
struct type_caster<selfalign::FeederRegime> : int_enum_caster<selfalign::FeederRegime> {
  static constexpr auto name = const_name("FeederRegime");
};

}  // namespace pybind11::detail
