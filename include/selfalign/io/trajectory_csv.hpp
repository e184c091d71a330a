#pragma once
/// \file trajectory_csv.hpp
/// A Trajectory as CSV: header "t,x,x_dot,y,y_dot,y_ddot,stick", one row per sample, numbers
/// in shortest round-trip form (strtod gives back the same double), stick as 0/1.
/// Units: [-] for dimensionless runs; [s], [m], [m/s], [m], [m/s], [m/s^2] in SI.

#include <ostream>
#include <string>

#include "selfalign/io/unit_system.hpp"
#include "selfalign/simulate/object_state.hpp"

namespace selfalign {

/// The CSV header line, without newline.
inline constexpr const char* kTrajectoryCsvHeader = "t,x,x_dot,y,y_dot,y_ddot,stick";

/// Writes the header and every sample, converted with `units`.
void write_trajectory_csv(std::ostream& out, const Trajectory& trajectory,
                          const OutputUnits& units = {});
/// The same CSV as one string.
std::string format_trajectory_csv(const Trajectory& trajectory, const OutputUnits& units = {});

}  // namespace selfalign
