// `selfalign floquet`: local stability of the steady state on the uniform table (Sect. 6.1):
// the monodromy matrix and Floquet multipliers three ways (analytic eqs. 25-33 for three-phase
// profiles, saltation matrices, finite differences of the period map).

#include <cmath>
#include <complex>
#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"
#include "config_flags.hpp"
#include "report.hpp"
#include "selfalign/io/atomic_file.hpp"
#include "selfalign/analysis/floquet.hpp"
#include "selfalign/error.hpp"
#include "selfalign/io/simulate_model.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;

struct FloquetFlags {
  bool as_json = false;
  double fd_step = FloquetOptions{}.fd_step;
};

// Φ acts on (Δx, Δx'): in SI, Φ12 [s] = Φ12 [-] T and Φ21 [1/s] = Φ21 [-] / T; Φ11, Φ22 and
// the multipliers are the same in both systems.
json monodromy_json(const Monodromy& m, const OutputUnits& u) {
  json j;
  j["available"] = m.available;
  j["matrix"] = nullptr;
  j["multipliers"] = nullptr;
  if (!m.available) return j;
  const double T = u.time(1.0);
  j["matrix"] = {{m.matrix(0, 0), m.matrix(0, 1) * T}, {m.matrix(1, 0) / T, m.matrix(1, 1)}};
  j["multipliers"] = json::array();
  for (const std::complex<double>& z : m.multipliers)
    j["multipliers"].push_back({{"re", z.real()}, {"im", z.imag()}});
  return j;
}

json floquet_json(const ProfileModel& model, const FloquetAnalysis& a, double fd_step) {
  const OutputUnits u = model.output_units();
  json j;
  j["units"] = to_string(model.units);
  j["profile"] = model.profile->kind();
  j["case"] = static_cast<int>(a.steady.motion_case);
  j["case_name"] = describe(a.steady.motion_case);
  j["x_dot_0s"] = u.velocity(a.steady.x_dot_0s);
  j["converged"] = a.steady.converged;
  j["analytic"] = monodromy_json(a.analytic, u);
  j["saltation"] = monodromy_json(a.saltation, u);
  j["finite_difference"] = monodromy_json(a.finite_difference, u);
  j["spread"] = number_or_null(a.spread);
  j["fd_step"] = fd_step;  // [-] in both systems: it perturbs x0 and x'_0s alike
  j["slip_slip_lambda2_formula"] =
      model.three_phase && !model.jerk && model.law.is_unit()
          ? number_or_null(slip_slip_multiplier(model.three_phase->a2, model.three_phase->a3))
          : json(nullptr);
  j["law"] = law_json(model.law, model.output_units(), model.scales.mu());
  j["pattern"] = a.steady.pattern;
  j["method"] = to_string(a.steady.method);
  j["integrator"] = integrator_json(a.steady.method, model.integrator, a.steady.integrator);
  return j;
}

std::string multiplier_text(const json& z) {
  const double im = z["im"];
  if (im == 0) return table_text(z["re"]);
  return table_text(z["re"]) + (im < 0 ? " - " : " + ") + table_text(json(std::abs(im))) + "i";
}

std::string floquet_table(const json& j, UnitSystem units) {
  TextTable t;
  t.row("case", table_text(j["case"]) + " (" + table_text(j["case_name"]) + ")");
  t.row("x_dot_0s", table_text(j["x_dot_0s"]) + " " + unit_label(units, Dimension::velocity));
  for (const char* method : {"analytic", "saltation", "finite_difference"}) {
    const json& m = j[method];
    if (!m["available"].get<bool>()) {
      t.row(method, "not available");
      continue;
    }
    const json& p = m["matrix"];
    t.row(method, "multipliers " + multiplier_text(m["multipliers"][0]) + ", " +
                      multiplier_text(m["multipliers"][1]) + "; matrix [[" +
                      table_text(p[0][0]) + ", " + table_text(p[0][1]) + "], [" +
                      table_text(p[1][0]) + ", " + table_text(p[1][1]) + "]]");
  }
  t.row("spread", table_text(j["spread"]));
  t.row("lambda2, eq. (33)", table_text(j["slip_slip_lambda2_formula"]));
  t.row("fd_step", table_text(j["fd_step"]) + " [-]");
  t.row("units", table_text(j["units"]));
  return t.str();
}

void run_floquet(const ConfigFlags& flags, const FloquetFlags& f) {
  const SimulateConfig config = read_config(flags);
  if (config.out) require_output_path("out", *config.out);
  const ProfileModel model = build_profile_model(config);  // case 0: InvalidParameter
  FloquetOptions options;
  options.fd_step = require_in_half_open("fd-step", f.fd_step, 0.0, 0.1);
  options.steady.integrator = model.integrator;  // Stribeck or viscous laws
  const ThreePhaseProfile* three_phase = model.profile->three_phase();
  // The analytic matrix (eqs. 25-33) is the paper's law's; any other law: saltation and FD.
  const FloquetAnalysis analysis = three_phase && model.law.is_unit()
                                       ? floquet_multipliers(*three_phase, options)
                                       : floquet_multipliers(*model.profile, model.law, options);
  const json report = floquet_json(model, analysis, options.fd_step);
  deliver_report(report, floquet_table(report, model.units), f.as_json, config.out);
}

}  // namespace

void add_floquet_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "floquet",
      "Floquet multipliers of the steady state on the uniform table (Sect. 6.1): monodromy "
      "matrix by the analytic linearisation (eqs. 25-33, three-phase profiles), by saltation "
      "matrices and by finite differences. Needs a piecewise-constant table acceleration "
      "(three-phase, quadratic-sequence, samples with constant interpolation).");
  auto flags = add_config_flags(
      *sub, without_uniform_table_keys(
                {{"out", "write the JSON report to this file instead of printing (nothing printed)"},
                 {"summary", ""}}));
  auto f = std::make_shared<FloquetFlags>();
  sub->add_flag("--json", f->as_json, "print the report as JSON (default: a table)")
      ->group("Output");
  sub->add_option("--fd-step", f->fd_step,
                  "finite-difference perturbation h of x0 and x'_0s, > 0. Unit: [-] in both "
                  "unit systems. Default: " + format_number(f->fd_step))
      ->type_name("NUMBER")
      ->group("Solver");
  sub->callback([flags, f] { run_floquet(*flags, *f); });
}

}  // namespace selfalign::cli
