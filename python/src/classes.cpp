// Rules for every class of the module, applied once after all bind_* functions (so a class
// added later is covered without a line of its own):
//
//  * An object made by cls.__new__(cls) without __init__ (what pickle and copy do before
//    __setstate__, and careless subclasses) has no C++ value yet. pybind11 would allocate raw,
//    unconstructed memory for it the first time a method, property or function reads it
//    ("lazy allocation", type_info::operator_new) and hand that garbage to the library: a
//    segfault, or a vector of garbage size. Here that allocation raises TypeError "this X has
//    no value: its __init__ was not called ..." instead, wherever the object is used: as self,
//    as an argument, inside a cast. __init__ and __setstate__ build the value themselves and never
//    take this path.
//  * Pickling: a class with __setstate__ (pybind11's py::pickle, record.hpp's value types,
//    enums) pickles through protocol 2's reduction (copyreg.__newobj__ + __getstate__) under
//    every protocol; any other class refuses every protocol with TypeError. Protocols 0 and 1
//    would otherwise build the object through copyreg._reconstructor, which calls pybind11's
//    base type directly and aborts the interpreter ("instance allocation failed").
#include <pybind11/pybind11.h>

#include <array>
#include <cstddef>
#include <string>
#include <utility>

#include "bindings.hpp"

namespace selfalign::python {

namespace {

// One refusing allocator per class, so that the message names it (type_info::operator_new
// gets the size only). More classes than this is a developer's error at import.
constexpr std::size_t kMaxClasses = 256;
std::array<std::string, kMaxClasses> g_class_names;

template <std::size_t I>
void* refuse_uninitialised(std::size_t) {
  const std::string& name = g_class_names[I];
  throw py::type_error("this " + name + " has no value: its __init__ was not called (an object "
                       "made by cls.__new__(cls) alone); create it by calling its class");
}

template <std::size_t... I>
constexpr auto refusers(std::index_sequence<I...>) {
  return std::array<void* (*)(std::size_t), sizeof...(I)>{&refuse_uninitialised<I>...};
}
constexpr auto kRefusers = refusers(std::make_index_sequence<kMaxClasses>{});

// Its own __reduce_ex__, unless it defines one itself (in its own __dict__: a base's rule does
// not fit a subclass that pickles).
void def_pickling_rule(const py::object& cls) {
  const py::object own = cls.attr("__dict__");
  if (own.contains("__reduce_ex__")) return;
  const std::string name = cls.attr("__name__").cast<std::string>();
  const bool picklable = own.contains("__setstate__");
  py::setattr(
      cls, "__reduce_ex__",
      py::cpp_function(
          [picklable, name](const py::object& self, int) -> py::tuple {
            if (!picklable)
              throw py::type_error("cannot pickle '" + name + "' object: it is not a value type "
                                   "(pickle what it was made from)");
            return py::make_tuple(py::module_::import("copyreg").attr("__newobj__"),
                                  py::make_tuple(py::type::of(self)),
                                  self.attr("__getstate__")());
          },
          py::name("__reduce_ex__"), py::is_method(cls), py::arg("protocol")));
}

}  // namespace

void finish_classes(py::module_& m) {
  const py::object module_name = m.attr("__name__");
  std::size_t count = 0;
  for (const auto& [cpp_type, info] : py::detail::get_internals().registered_types_cpp) {
    const auto cls = py::reinterpret_borrow<py::object>(reinterpret_cast<PyObject*>(info->type));
    if (!py::getattr(cls, "__module__", py::none()).equal(module_name)) continue;
    if (count == kMaxClasses)
      py::pybind11_fail("selfalign: more than kMaxClasses bound classes (python/src/classes.cpp)");
    g_class_names[count] = cls.attr("__qualname__").cast<std::string>();
    info->operator_new = kRefusers[count++];
    def_pickling_rule(cls);
  }
}

}  // namespace selfalign::python
