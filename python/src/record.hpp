#pragma once
// Value semantics of the bound value types (settings, options, profiles, friction laws and maps,
// results), declared once per class as a list of named fields:
//   pickling   __getstate__/__setstate__: the state is the tuple of the fields' C++ values
//              (vectors of numbers as NumPy arrays, nested value types as their Python
//              objects, which pickle themselves), so a round trip restores the same object
//              under every protocol (0 and 1 too: classes.cpp), copy/deepcopy too;
//   __eq__     field-wise on those values: floats bit-equal except that NaN equals NaN,
//   __ne__     arrays element-wise the same way, nested value types by their own __eq__;
//              NotImplemented for another type (defining __eq__ makes the class unhashable);
//   to_dict()  {field: value} with each value as its attribute returns it (NaN where a result
//              has none, enum members, NumPy arrays), nested value types as dicts, lists of
//              them as lists of dicts.
// A field's name is its Python attribute's; where the class has no such property (a field that
// is only a constructor argument, e.g. FrictionField's position), to_dict gives the state's
// value. The class attribute _record_fields lists the names.
//
//   def_record(cls, field("t", &ObjectState::t), field("x", &ObjectState::x), ...);
// unpickles by default construction and assignment: data members restore themselves; a field
// read by a getter (member function or lambda) names a setter, field(name, get, set), set a
// data member or a callable (T&, value). Classes with invariants instead name a factory,
// called with the fields' values in order (their types decoded from its parameters):
//   def_record(cls, [](double x_mu, double w, double c) { return TwoRegionTable(x_mu, w, c); },
//              field("x_mu", &TwoRegionTable::x_mu), field("width", &TwoRegionTable::width),
//              field("c_mu", &TwoRegionTable::c_mu));

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "arguments.hpp"
#include "arrays.hpp"

namespace selfalign::python {

namespace record {

/// How a field's value travels in the pickle state: pybind11's conversion, except vectors
/// (of numbers: a NumPy array copy; of anything else: a list).
template <class V>
struct Codec {
  static py::object dump(const V& v) {
    if constexpr (std::is_base_of_v<py::handle, V>)
      return py::reinterpret_borrow<py::object>(v);
    else
      return py::cast(v);
  }
  static V load(const py::handle& h) { return h.cast<V>(); }
};
template <class T, class A>
struct Codec<std::vector<T, A>> {
  static py::object dump(const std::vector<T, A>& v) {
    if constexpr (std::is_arithmetic_v<T>) {
      return to_array(std::vector<T>(v.begin(), v.end()));
    } else {
      py::list out;
      for (const T& x : v) out.append(Codec<T>::dump(x));
      return out;
    }
  }
  static std::vector<T, A> load(const py::handle& h) {
    if constexpr (std::is_arithmetic_v<T>) {
      const auto a = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(h);
      if (!a || a.ndim() != 1) throw py::type_error("pickle state: expected a 1-D array");
      return {a.data(), a.data() + a.size()};
    } else {
      std::vector<T, A> out;
      for (const py::handle x : h) out.push_back(Codec<T>::load(x));
      return out;
    }
  }
};

/// A field's state value as a V; TypeError naming the field when it has the wrong type (a
/// hand-made or corrupted pickle state).
template <class V>
V load_field(const py::handle& h, const char* name) {
  const auto wrong = [&] {
    return py::type_error(std::string("pickle state: field '") + name + "' has the wrong type (" +
                          python_type_name(h) + ")");
  };
  try {
    return Codec<V>::load(h);
  } catch (const py::cast_error&) {
    throw wrong();
  } catch (const py::type_error&) {
    throw wrong();
  } catch (py::error_already_set& e) {  // e.g. iterating a number
    if (!e.matches(PyExc_TypeError)) throw;
    throw wrong();
  }
}

struct NoSetter {};

template <class Get, class Set>
struct Field {
  const char* name;
  Get get;
  Set set;
};

template <class X>
struct is_field : std::false_type {};
template <class Get, class Set>
struct is_field<Field<Get, Set>> : std::true_type {};

/// The decayed parameter types of a lambda or function pointer, as a std::tuple.
template <class F>
struct parameters : parameters<decltype(&F::operator())> {};
template <class C, class R, class... A>
struct parameters<R (C::*)(A...) const> {
  using type = std::tuple<std::decay_t<A>...>;
};
template <class R, class... A>
struct parameters<R (*)(A...)> {
  using type = std::tuple<std::decay_t<A>...>;
};

template <class C, class M>
M member_type(M C::*);

template <class T, class Get, class Set>
py::object dump(const Field<Get, Set>& f, const T& obj) {
  using V = std::decay_t<std::invoke_result_t<const Get&, const T&>>;
  return Codec<V>::dump(std::invoke(f.get, obj));
}

template <class T, class Member>
void assign(Member member, T& obj, const py::handle& h, const char* name) {
  obj.*member = load_field<decltype(member_type(member))>(h, name);
}

template <class T, class Get, class Set>
void restore(const Field<Get, Set>& f, T& obj, const py::handle& h) {
  if constexpr (std::is_same_v<Set, NoSetter>) {
    static_assert(std::is_member_object_pointer_v<Get>,
                  "a field read by a getter needs a setter, or the class a factory");
    assign(f.get, obj, h, f.name);
  } else if constexpr (std::is_member_object_pointer_v<Set>) {
    assign(f.set, obj, h, f.name);
  } else {
    using V = std::tuple_element_t<1, typename parameters<Set>::type>;
    f.set(obj, load_field<V>(h, f.name));
  }
}

inline bool same_double(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) ||
         std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

inline bool arrays_equal(const py::array& a, const py::array& b) {
  if (a.ndim() != b.ndim() || !std::equal(a.shape(), a.shape() + a.ndim(), b.shape()) ||
      !a.dtype().equal(b.dtype()))
    return false;
  const py::module_ numpy = py::module_::import("numpy");
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'c') return numpy.attr("array_equal")(a, b).cast<bool>();
  // Floats as contiguous float64 (complex: real and imaginary parts in turn).
  const char* wide = kind == 'c' ? "complex128" : "float64";
  const auto doubles = [&](const py::array& x) {
    return DoubleArray::ensure(numpy.attr("ascontiguousarray")(x, wide).attr("view")("float64"));
  };
  const DoubleArray x = doubles(a), y = doubles(b);
  for (py::ssize_t i = 0; i < x.size(); ++i)
    if (!same_double(x.data()[i], y.data()[i])) return false;
  return true;
}

/// Equality of two field values (see the header comment).
inline bool values_equal(const py::handle& a, const py::handle& b) {
  if (PyFloat_Check(a.ptr()) && PyFloat_Check(b.ptr()))
    return same_double(PyFloat_AS_DOUBLE(a.ptr()), PyFloat_AS_DOUBLE(b.ptr()));
  if (PyComplex_Check(a.ptr()) && PyComplex_Check(b.ptr()))
    return same_double(PyComplex_RealAsDouble(a.ptr()), PyComplex_RealAsDouble(b.ptr())) &&
           same_double(PyComplex_ImagAsDouble(a.ptr()), PyComplex_ImagAsDouble(b.ptr()));
  if (py::isinstance<py::array>(a) && py::isinstance<py::array>(b))
    return arrays_equal(py::reinterpret_borrow<py::array>(a),
                        py::reinterpret_borrow<py::array>(b));
  if ((PyList_Check(a.ptr()) && PyList_Check(b.ptr())) ||
      (PyTuple_Check(a.ptr()) && PyTuple_Check(b.ptr()))) {
    const py::sequence x = py::reinterpret_borrow<py::sequence>(a);
    const py::sequence y = py::reinterpret_borrow<py::sequence>(b);
    if (x.size() != y.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (!values_equal(x[i], y[i])) return false;
    return true;
  }
  return a.equal(b);
}

/// A value as to_dict() gives it: value types as their to_dict(), lists of them as lists.
inline py::object plain(const py::handle& value) {
  if (py::hasattr(py::type::of(value), "_record_fields")) return value.attr("to_dict")();
  if (PyList_Check(value.ptr())) {
    py::list out;
    for (const py::handle x : value) out.append(plain(x));
    return out;
  }
  return py::reinterpret_borrow<py::object>(value);
}

template <class T, class... Options, class Restore, class... Fields>
void define(py::class_<T, Options...>& cls, Restore restore_all, const Fields&... fields) {
  constexpr std::size_t n = sizeof...(Fields);
  const std::array<const char*, n> names{fields.name...};
  const auto state = [fields...](const T& obj) { return py::make_tuple(dump(fields, obj)...); };
  cls.def(py::pickle(state, [restore_all](const py::tuple& s) {
    if (s.size() != n)
      throw py::value_error("pickle state: expected " + std::to_string(n) + " fields, got " +
                            std::to_string(s.size()));
    return restore_all(s);
  }));
  const auto equal = [state](const T& self, const py::object& other) -> py::object {
    if (!py::isinstance<T>(other)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
    return py::bool_(values_equal(state(self), state(other.cast<const T&>())));
  };
  cls.def("__eq__", equal, py::arg("other"));
  cls.def(
      "__ne__",
      [equal](const T& self, const py::object& other) -> py::object {
        const py::object eq = equal(self, other);
        return eq.is(py::reinterpret_borrow<py::object>(Py_NotImplemented))
                   ? eq
                   : py::bool_(!eq.cast<bool>());
      },
      py::arg("other"));
  cls.def(
      "to_dict",
      [state, names](const py::object& self) {
        const py::tuple values = state(self.cast<const T&>());
        const py::object type = py::type::of(self);
        py::dict d;
        for (std::size_t i = 0; i < n; ++i) {
          const bool attribute = py::isinstance(
              py::getattr(type, names[i], py::none()),
              py::module_::import("builtins").attr("property"));
          d[names[i]] = plain(attribute ? py::object(self.attr(names[i])) : values[i]);
        }
        return d;
      },
      "The fields as a dict {name: value}, each as its attribute returns it (NaN where a "
      "result has no such value); nested value types as dicts.");
  py::tuple field_names(n);
  for (std::size_t i = 0; i < n; ++i) field_names[i] = py::str(names[i]);
  cls.attr("_record_fields") = field_names;
}

}  // namespace record

/// A field: its name and a data member (read and restored), or a getter (member function,
/// data member or callable (const T&) -> value), optionally with a setter (data member or
/// callable (T&, value)).
template <class Get>
record::Field<Get, record::NoSetter> field(const char* name, Get get) {
  return {name, get, {}};
}
template <class Get, class Set>
record::Field<Get, Set> field(const char* name, Get get, Set set) {
  return {name, get, set};
}

/// Pickling, ==, != and to_dict() for cls from its fields, unpickled by default construction
/// and assignment of every field.
template <class T, class... Options, class... Fields>
  requires(record::is_field<Fields>::value && ...)
void def_record(py::class_<T, Options...>& cls, Fields... fields) {
  record::define(
      cls,
      [fields...](const py::tuple& s) {
        T obj{};
        std::size_t i = 0;
        (record::restore(fields, obj, s[i++]), ...);
        return obj;
      },
      fields...);
}

/// The same for a class rebuilt by factory(field values...) (its public constructor), which
/// keeps the class's invariants.
template <class T, class... Options, class Factory, class... Fields>
  requires(!record::is_field<Factory>::value && (record::is_field<Fields>::value && ...))
void def_record(py::class_<T, Options...>& cls, Factory factory, Fields... fields) {
  using Args = typename record::parameters<Factory>::type;
  static_assert(std::tuple_size_v<Args> == sizeof...(Fields),
                "the factory takes one parameter per field");
  record::define(
      cls,
      [factory, names = std::array<const char*, sizeof...(Fields)>{fields.name...}](
          const py::tuple& s) {
        return [&]<std::size_t... I>(std::index_sequence<I...>) {
          return factory(record::load_field<std::tuple_element_t<I, Args>>(s[I], names[I])...);
        }(std::make_index_sequence<sizeof...(Fields)>{});
      },
      fields...);
}

/// A double that a result does not always have: its value where present(s), else NaN (the
/// library leaves such a value 0, which would read as a real 0.0 in Python).
template <class S, class Present>
auto nan_unless(double S::*member, Present present) {
  return [member, present](const S& s) {
    return present(s) ? s.*member : std::numeric_limits<double>::quiet_NaN();
  };
}

}  // namespace selfalign::python
