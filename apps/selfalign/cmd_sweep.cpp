// `selfalign sweep`: parameter studies of the steady state on the uniform table (Sects. 4.4.1,
// 5.2), one subcommand per kind: `accelerations` (f and the motion case over a (y2'', y3'')
// grid, Figs. 10, 11), `period` (f against Δt, Fig. 4) and `stroke` (f against Δy, Fig. 5).

#include "commands.hpp"
#include "sweep_common.hpp"

namespace selfalign::cli {

void add_sweep_command(CLI::App& app) {
  CLI::App* sweep = app.add_subcommand(
      "sweep",
      "Parameter studies of the steady state on the uniform table, computed in parallel; the "
      "CSV (and its JSON summary) is the same for any number of threads.");
  sweep->require_subcommand(1);
  add_sweep_accelerations_command(*sweep);
  add_sweep_family_command(*sweep, SweptParameter::period);
  add_sweep_family_command(*sweep, SweptParameter::stroke);
}

}  // namespace selfalign::cli
