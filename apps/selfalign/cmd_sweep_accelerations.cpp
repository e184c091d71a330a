// `selfalign sweep accelerations`: f (eq. 11), v̄ (eq. 10) and the motion case (a priori and
// from the steady period) over a (y2'', y3'') grid of the three-phase profile at the config's
// Δt and Δy (Figs. 10, 11; --log for the Fig. 11 style plane).

#include <memory>
#include <string>
#include <vector>

#include "report.hpp"
#include "sweep_common.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;

struct AccelerationFlags {
  std::shared_ptr<SweepFlags> common;
  std::string a2_range, a3_range;
  bool search = false;  // --search: the fixed-point search on every cell
};

// Columns "a2,a3,case_a_priori,case,v_bar,f,x_dot_0s,converged,status"; a2, a3 as on the grid
// (run units), row-major with a2 outer, as the library orders the cells.
CellTable cells_table(const std::vector<AccelerationCell>& cells, const std::vector<double>& a2,
                      const std::vector<double>& a3, const OutputUnits& u) {
  const std::size_t n = cells.size();
  std::vector<double> ga2(n), ga3(n), v_bar(n), f(n), x0(n);
  std::vector<std::int64_t> prior(n), observed(n), converged(n);
  std::vector<std::string> status(n);
  for (std::size_t k = 0; k < n; ++k) {
    const AccelerationCell& c = cells[k];
    ga2[k] = a2[k / a3.size()], ga3[k] = a3[k % a3.size()];
    prior[k] = static_cast<int>(c.predicted), observed[k] = static_cast<int>(c.observed);
    v_bar[k] = u.velocity(c.v_bar), f[k] = c.f, x0[k] = u.velocity(c.x_dot_0s);
    converged[k] = c.converged ? 1 : 0;
    status[k] = cell_status(c.failure);
  }
  CellTable t;
  t.numbers("a2", std::move(ga2));
  t.numbers("a3", std::move(ga3));
  t.integers("case_a_priori", std::move(prior));
  t.integers("case", std::move(observed));
  t.numbers("v_bar", std::move(v_bar));
  t.numbers("f", std::move(f));
  t.numbers("x_dot_0s", std::move(x0));
  t.integers("converged", std::move(converged));
  t.words("status", std::move(status));
  return t;
}

json cells_summary(const SimulateConfig& config, const ProfileModel& model,
                   const AccelerationFlags& f, const GridRange& r2, const GridRange& r3,
                   const std::vector<AccelerationCell>& cells, bool closed_form) {
  const SimulateConfig given = resolve_simulate_config(config);  // Δt, Δy as given (run units)
  std::vector<StickSlipCase> observed, predicted;
  int disagreements = 0, not_converged = 0;
  for (const AccelerationCell& c : cells) {
    observed.push_back(c.observed);
    predicted.push_back(c.predicted);
    if (c.observed != c.predicted) ++disagreements;
    if (c.predicted != StickSlipCase::non_physical && !c.converged) ++not_converged;
  }
  json j;
  j["sweep"] = "accelerations";
  j["units"] = to_string(model.units);
  j["family"] = "three-phase";
  j["period"] = *given.period;
  j["stroke"] = *given.stroke;
  j["grid"] = {{"a2", grid_json(r2)},
               {"a3", grid_json(r3)},
               {"spacing", f.common->log ? "log" : "linear"},
               {"order", "row-major, a2 outer"}};
  j["cells"] = cells.size();
  j["cases"] = case_counts(observed);
  j["cases_a_priori"] = case_counts(predicted);
  j["a_priori_disagreements"] = disagreements;
  j["not_converged"] = not_converged;
  // Each cell a formula (docs/three-phase-steady-state.md), or the fixed-point search.
  if (closed_form) j["method"] = "closed form";
  j["failures"] = failures_json(cells, [&](const AccelerationCell& c) {
    return json{{"a2", model.from_model_units(Dimension::acceleration, c.a2)},
                {"a3", model.from_model_units(Dimension::acceleration, c.a3)}};
  });
  return j;
}

void run_sweep_accelerations(const AccelerationFlags& f) {
  const SimulateConfig config = read_config(*f.common->config);
  const SweepPaths paths = resolve_sweep_paths(config);
  const ProfileModel model = sweep_model(config);
  const AccelerationGrid g = acceleration_grid(model, f.a2_range, f.a3_range, f.common->log);

  const ThreePhaseParameters& p = *model.three_phase;
  std::vector<AccelerationCell> cells;
  SweepOptions options;
  {
    const std::unique_ptr<ProgressBar> bar = sweep_progress_bar(*f.common);
    options = sweep_options(*f.common, *bar, model);
    options.closed_form = !f.search;
    cells = sweep_accelerations(p.period, p.stroke, g.a2_model, g.a3_model, options);
  }
  const bool closed_form = closed_form_cells(options);
  write_sweep_outputs(paths, cells_table(cells, g.a2, g.a3, model.output_units()),
                      cells_summary(config, model, f, g.r2, g.r3, cells, closed_form), model);
}

}  // namespace

void add_sweep_accelerations_command(CLI::App& sweep) {
  CLI::App* sub = sweep.add_subcommand(
      "accelerations",
      "f, v_bar and the motion case (a priori and of the steady period) over a grid of the three-phase "
      "profile's (y2'', y3'') at the config's period and stroke (Figs. 10, 11). CSV "
      "a2,a3,case_a_priori,case,v_bar,f,x_dot_0s,converged,status; rows a2-major; a cell "
      "that cannot be computed has status failed (reason in the summary). Each cell is the "
      "closed-form steady state (jump accelerations, Coulomb law; summary method \"closed "
      "form\"), else the fixed-point search. --out FILE.npy "
      "writes the same columns as a NumPy structured array (numpy.load).");
  auto f = std::make_shared<AccelerationFlags>();
  f->common = add_sweep_flags(*sub, {"a2", "a3"});
  add_acceleration_range_flags(*sub, f->a2_range, f->a3_range);
  sub->add_flag("--search", f->search,
                "compute every cell by the fixed-point search of the exact solver instead of "
                "the closed-form steady state (docs/three-phase-steady-state.md; used with jump "
                "accelerations under a Coulomb law), e.g. to check it")
      ->group("Sweep");
  sub->callback([f] { run_sweep_accelerations(*f); });
}

}  // namespace selfalign::cli
