// `selfalign sweep`: parameter studies of the steady state on the uniform table (Sects. 4.4.1,
// 5.2, 7.2), one subcommand per kind: `accelerations` (f and the motion case over a (y2'', y3'')
// grid, Figs. 10, 11), `period` (f against Δt, Fig. 4), `stroke` (f against Δy, Fig. 5) and
// `positioning` (f, case, accumulation and Δx_d over a (y2'', y3'') grid, Fig. 17).

#include "commands.hpp"
#include "sweep_common.hpp"

namespace selfalign::cli {

void add_sweep_command(CLI::App& app) {
  CLI::App* sweep = app.add_subcommand(
      "sweep",
      "Parameter studies of the steady state on the uniform table (and, for positioning, of "
      "stopping on the two-region table), computed in parallel; the CSV (and its JSON summary) "
      "is the same for any number of threads.");
  sweep->require_subcommand(1);
  add_sweep_accelerations_command(*sweep);
  add_sweep_family_command(*sweep, SweptParameter::period);
  add_sweep_family_command(*sweep, SweptParameter::stroke);
  add_sweep_positioning_command(*sweep);
}

}  // namespace selfalign::cli
