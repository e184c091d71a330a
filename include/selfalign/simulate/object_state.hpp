#pragma once
/// \file object_state.hpp
/// The state of the object on the table and a recorded trajectory, shared by both solvers.

#include <cstddef>
#include <vector>

namespace selfalign {

/// State of the object at one time [-]: x is its position relative to the table (its leading
/// edge, for the friction map), xd = x' its velocity relative to the table.
struct ObjectState {
  double t = 0;   ///< time [-]
  double x = 0;   ///< position relative to the table [-]
  double xd = 0;  ///< relative velocity x' [-]
};

/// The start state every solver takes: throws InvalidParameter naming t0 (not finite), x0 or
/// v0 (not finite, or beyond 1e50 in magnitude).
void validate(const ObjectState& start);

/// A sampled trajectory (columns of equal length) [-].
struct Trajectory {
  std::vector<double> t, x, xd, y, yd, ydd;  ///< time, object x, x', table y, y', y''
  std::vector<unsigned char> stick;           ///< 1 where the object sticks (x' = 0, no slip)

  std::size_t size() const noexcept { return t.size(); }
  void reserve(std::size_t n);
  void push(double t, double x, double xd, double y, double yd, double ydd, bool stick);
};

}  // namespace selfalign
