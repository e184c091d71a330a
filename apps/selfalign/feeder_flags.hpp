#pragma once
// The flags `selfalign feeder` and `selfalign regimes` share: the track's incline and the
// friction coefficients, and the runs' length and step, checked by their flag names.

#include <string>

#include <CLI/CLI.hpp>

#include "selfalign/analysis/feeder.hpp"
#include "selfalign/error.hpp"
#include "selfalign/simulate/method.hpp"

namespace selfalign::cli {

/// --incline in (-pi/2, pi/2), --mu-static > 0, --mu-kinetic in (0, mu-static], --periods in
/// [1, max_periods], --steps-per-period in [2, max_steps]. InvalidParameter naming the flag.
inline void require_feeder_flags(double incline, double mu_static, double mu_kinetic,
                                 long long periods, long long max_periods,
                                 long long steps_per_period, long long max_steps) {
  require_feeder_angle("incline", incline);
  require_positive_moderate("mu-static", mu_static);
  require_positive_moderate("mu-kinetic", mu_kinetic);
  if (mu_kinetic > mu_static)
    throw InvalidParameter("mu-kinetic", mu_kinetic,
                           "must be <= mu-static (" + format_number(mu_static) + ")");
  if (!(periods >= 1 && periods <= max_periods))
    throw InvalidParameter("periods", static_cast<double>(periods),
                           "must be in [1, " + format_number(static_cast<double>(max_periods)) + "]");
  if (!(steps_per_period >= 2 && steps_per_period <= max_steps))
    throw InvalidParameter("steps-per-period", static_cast<double>(steps_per_period),
                           "must be in [2, " + format_number(static_cast<double>(max_steps)) + "]");
}

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

/// The feeder runs' method: "exact" (the exact feeder solver, feeder_run_exact) or
/// "time-stepping" (the contact core, Moreau-Jean). InvalidParameter naming "method" otherwise.
inline Method feeder_method(const std::string& text) {
  if (text == "exact") return Method::exact;
  if (text == "time-stepping") return Method::time_stepping;
  throw InvalidParameter("method", text, "must be exact or time-stepping");
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

/// --restitution in [0, 1]. InvalidParameter naming it otherwise.
inline void require_restitution(double e) {
  if (!(e >= 0 && e <= 1)) throw InvalidParameter("restitution", e, "must be in [0, 1]");
}

}  // namespace selfalign::cli
