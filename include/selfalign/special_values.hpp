#pragma once
/// \file special_values.hpp
/// The two special doubles selfalign's results use, named once (STYLE: absent values are NaN,
/// never 0).

#include <limits>

namespace selfalign {

/// +inf: a bound that does not bind, an event that never happens, a run that accumulates.
inline constexpr double kInf = std::numeric_limits<double>::infinity();
/// NaN: a value that is absent (not computed, not defined for this case).
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace selfalign
