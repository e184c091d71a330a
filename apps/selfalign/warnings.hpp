#pragma once
// Warning lines: a run that goes ahead (exit 0) with something its user should know, printed as
// one line "selfalign: warning: <message>" on stderr after the run succeeded, never instead of
// a result. A run that fails prints only its one error line (main.cpp), no warning.

#include <optional>
#include <string>

#include "selfalign/io/simulate_config.hpp"

namespace selfalign::cli {

/// Keeps "selfalign: warning: <message>" for print_warnings.
void warn(const std::string& message);
/// Prints the warnings kept, each once, in order (main.cpp, after a successful run).
void print_warnings();

/// The friction coefficients are absolute and their ratios are taken to mu, the kinetic one
/// (docs/config.md, "Friction law"): warns when mu_static or mu_backward is given while mu is
/// not, so the ratio silently uses the default mu.
void warn_default_mu(bool mu_given, double mu, const std::optional<double>& mu_static,
                     const std::optional<double>& mu_backward);

/// Values that look like millimetres or grams where metres or kilograms are expected: a
/// length `metres` >= `from` m (an object 3 m wide), a mass >= 10 kg. `name` is the flag or
/// key as the user gave it.
void warn_if_millimetres(const std::string& name, double metres, double from);
void warn_if_grams(const std::string& name, double kilograms);

/// Both warnings for a simulate config (SI lengths only in SI runs; the mass is in kg in every
/// run) as given, before defaults.
void warn_about_config(const SimulateConfig& given);

}  // namespace selfalign::cli
