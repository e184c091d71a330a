#pragma once
// Expects a call to throw InvalidParameter naming a parameter: the library's one error for
// bad input (error.hpp).

#include <gtest/gtest.h>

#include <string>

#include "selfalign/error.hpp"

namespace selfalign::testing {

/// Expects `f` to throw InvalidParameter naming `name`; returns its message ("" if none).
template <class F>
std::string expect_invalid(F&& f, const std::string& name) {
  try {
    f();
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(e.name(), name) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no InvalidParameter thrown, expected one naming " << name;
  return "";
}

}  // namespace selfalign::testing
