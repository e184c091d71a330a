#pragma once
// The flags `selfalign feeder` and `selfalign regimes` share: the track's incline and the
// friction coefficients, and the runs' solver. Their checks by flag name are the library's
// (io/regime_chart_report.hpp).

#include <string>

#include <CLI/CLI.hpp>

#include "selfalign/analysis/feeder.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/regime_chart_report.hpp"  // require_feeder_flags, feeder_method, require_restitution
#include "selfalign/simulate/method.hpp"

namespace selfalign::cli {

/// Adds the --mu-static and --mu-kinetic flags (group "Friction"), required unless the
/// command reads them from a config file too (`required` false: it checks them itself).
inline void add_friction_flags(CLI::App& sub, double& mu_static, double& mu_kinetic,
                               bool required = true) {
  sub.add_option("--mu-static", mu_static, "static friction coefficient, > 0")
      ->required(required)
      ->group("Friction");
  sub.add_option("--mu-kinetic", mu_kinetic, "kinetic friction coefficient, in (0, mu-static]")
      ->required(required)
      ->group("Friction");
}

/// Adds --method (default exact) and --restitution (default 0), group "Solver".
inline void add_feeder_solver_flags(CLI::App& sub, std::string& method, double& restitution) {
  sub.add_option("--method", method,
                 "exact (event-driven: closed-form arcs, certified events; the default) or "
                 "time-stepping (the contact core: Moreau, Moreau-Jean flight)")
      ->group("Solver");
  sub.add_option("--restitution", restitution,
                 "Newton's restitution e at a landing, in [0, 1] (0: plastic). Default: 0")
      ->group("Solver");
}

}  // namespace selfalign::cli
