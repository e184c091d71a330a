#pragma once
// __repr__ text of the bound value types: Name(field=value, ...), numbers printed the way the
// library's messages print them (shortest round-trip).

#include <pybind11/pybind11.h>

#include <cmath>
#include <string>

#include "selfalign/error.hpp"

namespace selfalign::python {

/// "Type.member" of a value of a bound enum (needs the GIL).
template <class Enum>
std::string enum_name(Enum value) {
  const pybind11::object member = pybind11::cast(value);
  return pybind11::type::of(member).attr("__name__").template cast<std::string>() + "." +
         member.attr("name").template cast<std::string>();
}

/// A number as Python source that evaluates back: float('inf'), float('-inf'), float('nan')
/// for the non-finite ones (a bare inf or nan would not).
inline std::string number_source(double value) {
  if (std::isnan(value)) return "float('nan')";
  if (std::isinf(value)) return value > 0 ? "float('inf')" : "float('-inf')";
  return format_number(value);
}

class Repr {
 public:
  explicit Repr(const std::string& type) : text_(type + "(") {}

  Repr& operator()(const char* field, double value) { return raw(field, format_number(value)); }
  Repr& operator()(const char* field, int value) { return raw(field, std::to_string(value)); }
  Repr& operator()(const char* field, long long value) { return raw(field, std::to_string(value)); }
  Repr& operator()(const char* field, bool value) { return raw(field, value ? "True" : "False"); }
  /// A value already formatted as Python source (an enum member, a quoted string, ...).
  Repr& raw(const char* field, const std::string& value) {
    text_ += (first_ ? "" : ", ") + std::string(field) + "=" + value;
    first_ = false;
    return *this;
  }
  std::string str() const { return text_ + ")"; }

 private:
  std::string text_;
  bool first_ = true;
};

}  // namespace selfalign::python
