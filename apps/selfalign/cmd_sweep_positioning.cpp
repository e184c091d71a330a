// `selfalign sweep positioning`: the Fig. 17 surfaces over a (y2'', y3'') grid of the
// three-phase profile at the config's Δt, Δy, w and c_mu: f (A, eq. 11), the motion case (B),
// accumulation (C) and the positioning error Δx_d (D, eq. 39), with the periods from entry to
// p = 0.99 and 0.999 of the way to x_stick,min (Sect. 7.3).

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "report.hpp"
#include "selfalign/analysis/positioning.hpp"
#include "selfalign/error.hpp"
#include "stopping_common.hpp"
#include "sweep_common.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;
using D = Dimension;

constexpr int kDefaultMaxPeriods = 300;  // a stop takes a few periods (Sect. 7.3: at most 8)

struct PositioningFlags {
  std::shared_ptr<SweepFlags> common;
  std::string a2_range, a3_range;
  int entries = PositioningOptions{}.entries;
  int max_periods = kDefaultMaxPeriods;
};

// Header "a2,a3,case,f,accumulates,dx_d,accumulating_entries,max_periods_p99,max_periods_p999,
// status"; a2, a3 as on the grid, row-major with a2 outer; dx_d in the run's units (nan where
// the object does not arrive or an entry does not stop); periods -1 where no entry accumulates;
// status ok or failed (a cell that could not be computed; why: the summary's failures).
CellTable cells_table(const std::vector<PositioningCell>& cells, const std::vector<double>& a2,
                      const std::vector<double>& a3, const OutputUnits& u) {
  const std::size_t n = cells.size();
  std::vector<double> ga2(n), ga3(n), f(n), dx_d(n);
  std::vector<std::int64_t> motion_case(n), accumulates(n), entries(n), p99(n), p999(n);
  std::vector<std::string> status(n);
  for (std::size_t k = 0; k < n; ++k) {
    const PositioningCell& c = cells[k];
    ga2[k] = a2[k / a3.size()], ga3[k] = a3[k % a3.size()];
    motion_case[k] = static_cast<int>(c.motion_case), f[k] = c.f;
    accumulates[k] = c.accumulates ? 1 : 0, dx_d[k] = u.length(c.dx_d);
    entries[k] = c.accumulating_entries, p99[k] = c.max_periods_p99, p999[k] = c.max_periods_p999;
    status[k] = cell_status(c.failure);
  }
  CellTable t;
  t.numbers("a2", std::move(ga2));
  t.numbers("a3", std::move(ga3));
  t.integers("case", std::move(motion_case));
  t.numbers("f", std::move(f));
  t.integers("accumulates", std::move(accumulates));
  t.numbers("dx_d", std::move(dx_d));
  t.integers("accumulating_entries", std::move(entries));
  t.integers("max_periods_p99", std::move(p99));
  t.integers("max_periods_p999", std::move(p999));
  t.words("status", std::move(status));
  return t;
}

json cells_summary(const SimulateConfig& config, const ProfileModel& model,
                   const PositioningFlags& f, const GridRange& r2, const GridRange& r3,
                   const std::vector<PositioningCell>& cells, const FrictionMap* field) {
  const SimulateConfig given = resolve_simulate_config(config);  // run units
  std::vector<StickSlipCase> cases;
  int accumulating = 0, with_accumulating_entries = 0, p99 = -1, p999 = -1;
  for (const PositioningCell& c : cells) {
    cases.push_back(c.motion_case);
    accumulating += c.accumulates;
    with_accumulating_entries += c.accumulating_entries > 0;
    p99 = std::max(p99, c.max_periods_p99);
    p999 = std::max(p999, c.max_periods_p999);
  }
  json j;
  j["sweep"] = "positioning";
  j["units"] = to_string(model.units);
  j["family"] = "three-phase";
  j["period"] = *given.period;
  j["stroke"] = *given.stroke;
  if (field) {  // the field where it stands
    add_field_json(j, *field, model.output_units());
  } else {
    j["width"] = *given.width;
    j["c_mu"] = *given.c_mu;
  }
  j["entries"] = f.entries;
  j["max_periods"] = f.max_periods;
  j["grid"] = {{"a2", grid_json(r2)},
               {"a3", grid_json(r3)},
               {"spacing", f.common->log ? "log" : "linear"},
               {"order", "row-major, a2 outer"}};
  j["cells"] = cells.size();
  j["cases"] = case_counts(cases);
  j["accumulating_cells"] = accumulating;
  j["cells_with_accumulating_entries"] = with_accumulating_entries;
  j["max_periods_p99"] = p99;
  j["max_periods_p999"] = p999;
  j["failures"] = failures_json(cells, [&](const PositioningCell& c) {
    return json{{"a2", model.from_model_units(D::acceleration, c.a2)},
                {"a3", model.from_model_units(D::acceleration, c.a3)}};
  });
  return j;
}

void run_sweep_positioning(const PositioningFlags& f) {
  const SimulateConfig config = read_config(*f.common->config);
  const SweepPaths paths = resolve_sweep_paths(config);
  const ProfileModel model = sweep_model(config);
  const SimulateConfig given = resolve_simulate_config(config);
  if (*given.friction == "uniform")
    throw InvalidParameter("friction", "uniform",
                           "sweep positioning needs a rise of friction: two-region or field");
  // A field stands where its file puts it (x_mu: its rise); the two-region table is placed at
  // x_mu = dx in every cell (Sect. 7.1).
  const std::unique_ptr<FrictionMap> field =
      *given.friction == "field" ? build_friction_map(config) : nullptr;
  const double width = model.to_model_units(D::length, *given.width);
  const double c_mu = *given.c_mu;
  if (f.entries < 1) throw InvalidParameter("entries", f.entries, "must be >= 1");
  if (f.max_periods < 1) throw InvalidParameter("max-periods", f.max_periods, "must be >= 1");
  const AccelerationGrid g = acceleration_grid(model, f.a2_range, f.a3_range, f.common->log);

  PositioningOptions options;
  options.entries = f.entries;
  options.stopping.max_periods = f.max_periods;
  // Stribeck or viscous laws: the steady state, Δx and the stopping runs all integrate.
  options.steady.integrator = options.stopping.integrator = model.integrator;
  const ThreePhaseParameters& p = *model.three_phase;
  std::vector<PositioningCell> cells;
  {
    const std::unique_ptr<ProgressBar> bar = sweep_progress_bar(*f.common);
    const SweepOptions sweep = sweep_options(*f.common, *bar, model);
    cells = field ? positioning_surfaces(p.period, p.stroke, *field, g.a2_model, g.a3_model,
                                         options, sweep)
                  : positioning_surfaces(p.period, p.stroke, width, c_mu, g.a2_model, g.a3_model,
                                         options, sweep);
  }
  write_sweep_outputs(paths, cells_table(cells, g.a2, g.a3, model.output_units()).records(),
                      cells_summary(config, model, f, g.r2, g.r3, cells, field.get()), model);
}

}  // namespace

void add_sweep_positioning_command(CLI::App& sweep) {
  CLI::App* sub = sweep.add_subcommand(
      "positioning",
      "Fig. 17 over a grid of the three-phase profile's (y2'', y3'') at the config's period, "
      "stroke, width and c_mu: f, motion case, accumulation and the positioning error dx_d "
      "(eq. 39) from N steady-state entries per cell; or on a friction field where it stands "
      "(--field-file; level 1 before its rise), as `accuracy`. CSV a2,a3,case,f,accumulates,"
      "dx_d,accumulating_entries,max_periods_p99,max_periods_p999,status; rows a2-major.");
  auto f = std::make_shared<PositioningFlags>();
  f->common = add_sweep_flags(*sub, {"a2", "a3"},
                               {"width", "c_mu", "friction", "field_file", "field_positions",
                                "field_levels", "field_interpolation",
                                "footprint"});
  add_acceleration_range_flags(*sub, f->a2_range, f->a3_range);
  sub->add_option("--entries", f->entries,
                  "steady-state entries x_0s per cell, in [1, 1e5]. Default: " +
                      std::to_string(f->entries))
      ->type_name("N")
      ->group("Sweep");
  sub->add_option("--max-periods", f->max_periods,
                  "give up an entry's stopping run after N table periods, >= 1. Default: " +
                      std::to_string(f->max_periods))
      ->type_name("N")
      ->group("Sweep");
  sub->callback([f] { run_sweep_positioning(*f); });
}

}  // namespace selfalign::cli
