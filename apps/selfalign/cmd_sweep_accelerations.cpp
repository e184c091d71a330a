// `selfalign sweep accelerations`: f (eq. 11), v̄ (eq. 10) and the motion case (a priori and
// from the steady period) over a (y2'', y3'') grid of the three-phase profile at the config's
// Δt and Δy (Figs. 10, 11; --log for the Fig. 11 style plane).

#include <algorithm>
#include <memory>
#include <mutex>
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
// (run units), row-major with a2 outer, as the library orders the cells. The status is "ok" or
// "failed" (6 bytes in a .npy file).
enum Column : std::size_t { a2_col, a3_col, prior_col, case_col, v_bar_col, f_col, x0_col,
                            converged_col, status_col };

std::vector<NpyField> cell_fields() {
  using K = NpyKind;
  return {{"a2", K::float64},    {"a3", K::float64}, {"case_a_priori", K::int64},
          {"case", K::int64},    {"v_bar", K::float64}, {"f", K::float64},
          {"x_dot_0s", K::float64}, {"converged", K::int64}, {"status", K::bytes, 6}};
}

// Cell k's row of the table, written by the worker that computed it.
void set_row(NpyRecords& t, std::size_t k, const AccelerationCell& c, double a2, double a3,
             const OutputUnits& u) {
  t.set(k, a2_col, a2);
  t.set(k, a3_col, a3);
  t.set(k, prior_col, std::int64_t{static_cast<int>(c.predicted)});
  t.set(k, case_col, std::int64_t{static_cast<int>(c.observed)});
  t.set(k, v_bar_col, u.velocity(c.v_bar));
  t.set(k, f_col, c.f);
  t.set(k, x0_col, u.velocity(c.x_dot_0s));
  t.set(k, converged_col, std::int64_t{c.converged ? 1 : 0});
  t.set(k, status_col, std::string_view(cell_status(c.failure)));
}

json cells_summary(const SimulateConfig& config, const ProfileModel& model,
                   const AccelerationFlags& f, const GridRange& r2, const GridRange& r3,
                   const NpyRecords& table, const std::vector<AccelerationCell>& failed,
                   bool closed_form) {
  const SimulateConfig given = resolve_simulate_config(config);  // Δt, Δy as given (run units)
  std::vector<StickSlipCase> observed, predicted;
  int disagreements = 0, not_converged = 0;
  for (std::size_t k = 0; k < table.rows(); ++k) {
    const auto o = static_cast<StickSlipCase>(table.integer(k, case_col));
    const auto p = static_cast<StickSlipCase>(table.integer(k, prior_col));
    observed.push_back(o);
    predicted.push_back(p);
    if (o != p) ++disagreements;
    if (p != StickSlipCase::non_physical && table.integer(k, converged_col) == 0) ++not_converged;
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
  j["cells"] = table.rows();
  j["cases"] = case_counts(observed);
  j["cases_a_priori"] = case_counts(predicted);
  j["a_priori_disagreements"] = disagreements;
  j["not_converged"] = not_converged;
  // Each cell a formula (docs/three-phase-steady-state.md), or the fixed-point search.
  if (closed_form) j["method"] = "closed form";
  j["failures"] = failures_json(failed, [&](const AccelerationCell& c) {
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
  const OutputUnits units = model.output_units();
  // The workers write each cell's row into the table in place (one buffer for CSV and .npy).
  NpyRecords table(cell_fields(), g.a2.size() * g.a3.size());
  std::vector<std::pair<std::size_t, AccelerationCell>> failed;  // rare: under a mutex
  std::mutex failed_mutex;
  bool closed_form = false;  // whether the cells were the closed form
  {
    const std::unique_ptr<ProgressBar> bar = sweep_progress_bar(*f.common);
    SweepOptions options = sweep_options(*f.common, *bar, model);
    options.closed_form = !f.search;
    closed_form = closed_form_cells(options);
    sweep_accelerations(p.period, p.stroke, g.a2_model, g.a3_model, options,
                        [&](std::size_t k, const AccelerationCell& c) {
                          set_row(table, k, c, g.a2[k / g.a3.size()], g.a3[k % g.a3.size()],
                                  units);
                          if (c.failure.empty()) return;
                          std::lock_guard lock(failed_mutex);
                          failed.emplace_back(k, c);
                        });
  }
  std::sort(failed.begin(), failed.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });  // cell order
  std::vector<AccelerationCell> failed_cells;
  for (auto& [k, c] : failed) failed_cells.push_back(std::move(c));
  write_sweep_outputs(paths, table,
                      cells_summary(config, model, f, g.r2, g.r3, table, failed_cells,
                                    closed_form),
                      model);
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
