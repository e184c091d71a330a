#include "selfalign/io/trajectory_csv.hpp"

#include "../double_chars.hpp"

#include <charconv>
#include <sstream>

namespace selfalign {
namespace {

// Shortest text that reads back as the same double (std::to_chars round-trip guarantee).
void append_number(std::string& line, double value) {
  char buffer[32];
  const auto [end, ec] = detail::double_to_chars(buffer, buffer + sizeof buffer, value);
  line.append(buffer, ec == std::errc{} ? end : buffer);
}

}  // namespace

void write_trajectory_csv(std::ostream& out, const Trajectory& tr, const OutputUnits& u) {
  out << kTrajectoryCsvHeader << '\n';
  std::string line;
  for (std::size_t i = 0; i < tr.size(); ++i) {
    line.clear();
    append_number(line, u.time(tr.t[i]));          // t      [-] | [s]
    line += ',';
    append_number(line, u.length(tr.x[i]));        // x      [-] | [m]
    line += ',';
    append_number(line, u.velocity(tr.xd[i]));     // x_dot  [-] | [m/s]
    line += ',';
    append_number(line, u.length(tr.y[i]));        // y      [-] | [m]
    line += ',';
    append_number(line, u.velocity(tr.yd[i]));     // y_dot  [-] | [m/s]
    line += ',';
    append_number(line, u.acceleration(tr.ydd[i]));  // y_ddot [-] | [m/s^2]
    line += tr.stick[i] ? ",1\n" : ",0\n";
    out << line;
  }
}

std::string format_trajectory_csv(const Trajectory& trajectory, const OutputUnits& units) {
  std::ostringstream out;
  write_trajectory_csv(out, trajectory, units);
  return std::move(out).str();
}

}  // namespace selfalign
