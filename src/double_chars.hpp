#pragma once
// Internal: std::to_chars / std::from_chars for double, or, where the standard library lacks
// them for floating point (libc++ before LLVM 17: emscripten's, for the WebAssembly build,
// wasm/CMakeLists.txt), printf/strtod equivalents with the same contract:
//   double_to_chars: the shortest text that reads back as the same double (%g form: it may
//                    print 0.0001 where std::to_chars prints 1e-04; the value is the same);
//   double_from_chars: the whole of a C-locale number, no leading blank or '+', no hex;
//                    result_out_of_range beyond the range of a double.

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <system_error>

namespace selfalign::detail {

#if defined(__cpp_lib_to_chars) || !defined(_LIBCPP_VERSION)
inline std::to_chars_result double_to_chars(char* first, char* last, double value) {
  return std::to_chars(first, last, value);
}
inline std::from_chars_result double_from_chars(const char* first, const char* last,
                                                double& value) {
  return std::from_chars(first, last, value);
}
#else
inline std::to_chars_result double_to_chars(char* first, char* last, double value) {
  char buffer[40];
  int n = 0;
  for (int precision = 1; precision <= 17; ++precision) {
    n = std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  if (n <= 0 || n > last - first) return {last, std::errc::value_too_large};
  for (int i = 0; i < n; ++i) first[i] = buffer[i];
  return {first + n, std::errc{}};
}
inline std::from_chars_result double_from_chars(const char* first, const char* last,
                                                double& value) {
  const std::string text(first, last);
  if (text.empty() || text[0] == ' ' || text[0] == '\t' || text[0] == '+' ||
      text.find_first_of("xX") != std::string::npos)
    return {first, std::errc::invalid_argument};
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str()) return {first, std::errc::invalid_argument};
  const char* stop = first + (end - text.c_str());
  if (errno == ERANGE && (v == HUGE_VAL || v == -HUGE_VAL)) return {stop, std::errc::result_out_of_range};
  value = v;
  return {stop, std::errc{}};
}
#endif

}  // namespace selfalign::detail
