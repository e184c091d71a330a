// `selfalign sweep period` and `selfalign sweep stroke`: f (eq. 11) and v̄ (eq. 10) of a profile
// family against Δt at the config's Δy (Fig. 4), or against Δy at the config's Δt (Fig. 5).
// Families: three-phase (the config's y2'', y3'') or scaled-shape (ScaledShapeFamily::
// paper_like(), a fixed piecewise-constant shape stretched to Δt and scaled to Δy).

#include <memory>
#include <string>
#include <vector>

#include "report.hpp"
#include "selfalign/error.hpp"
#include "sweep_common.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;
using D = Dimension;

struct FamilyFlags {
  SweptParameter swept;
  std::shared_ptr<SweepFlags> common;
  std::string range;
  std::string family = "three-phase";
};

std::unique_ptr<ProfileFamily> make_family(const std::string& name, const ProfileModel& model) {
  if (name == "three-phase" && model.jerk)
    return std::make_unique<JerkLimitedThreePhaseFamily>(model.three_phase->a2,
                                                         model.three_phase->a3, *model.jerk);
  if (name == "three-phase")
    return std::make_unique<ThreePhaseFamily>(model.three_phase->a2, model.three_phase->a3);
  if (name == "scaled-shape")
    return std::make_unique<ScaledShapeFamily>(ScaledShapeFamily::paper_like());
  throw InvalidParameter("family", name, "must be one of: three-phase, scaled-shape");
}

// Header "period,stroke,physical,case,v_bar,f,status": the swept value as on the grid, the fixed one
// as given (run units).
CellTable points_table(const std::vector<FamilyPoint>& points, const std::vector<double>& values,
                       double fixed, SweptParameter swept, const OutputUnits& u) {
  const std::size_t n = points.size();
  const bool by_period = swept == SweptParameter::period;
  std::vector<double> period(n), stroke(n), v_bar(n), f(n);
  std::vector<std::int64_t> physical(n), observed(n);
  std::vector<std::string> status(n);
  for (std::size_t k = 0; k < n; ++k) {
    const FamilyPoint& pt = points[k];
    period[k] = by_period ? values[k] : fixed, stroke[k] = by_period ? fixed : values[k];
    physical[k] = pt.physical ? 1 : 0, observed[k] = static_cast<int>(pt.observed);
    v_bar[k] = u.velocity(pt.v_bar), f[k] = pt.f;
    status[k] = cell_status(pt.failure);
  }
  CellTable t;
  t.numbers("period", std::move(period));
  t.numbers("stroke", std::move(stroke));
  t.integers("physical", std::move(physical));
  t.integers("case", std::move(observed));
  t.numbers("v_bar", std::move(v_bar));
  t.numbers("f", std::move(f));
  t.words("status", std::move(status));
  return t;
}

void run_sweep_family(const FamilyFlags& f) {
  const SimulateConfig config = read_config(*f.common->config);
  const SweepPaths paths = resolve_sweep_paths(config);
  const ProfileModel model = sweep_model(config);
  const std::unique_ptr<ProfileFamily> family = make_family(f.family, model);
  const bool by_period = f.swept == SweptParameter::period;
  const GridRange range = parse_grid_range("range", f.range);
  const std::vector<double> values =
      positive_grid("range", range, f.common->log, by_period ? "periods" : "strokes");
  std::vector<double> values_model;  // [-]
  for (double v : values)
    values_model.push_back(model.to_model_units(by_period ? D::time : D::length, v));

  const ThreePhaseParameters& p = *model.three_phase;
  std::vector<FamilyPoint> points;
  {
    const std::unique_ptr<ProgressBar> bar = sweep_progress_bar(*f.common);
    const SweepOptions options = sweep_options(*f.common, *bar, model);
    points = by_period ? sweep_period(*family, p.stroke, values_model, options)
                       : sweep_stroke(*family, p.period, values_model, options);
  }

  const SimulateConfig given = resolve_simulate_config(config);  // fixed values as given
  const double fixed = by_period ? *given.stroke : *given.period;
  std::vector<StickSlipCase> cases;
  int non_physical = 0;
  for (const FamilyPoint& pt : points) {
    cases.push_back(pt.observed);
    if (!pt.physical) ++non_physical;
  }
  json j;
  j["sweep"] = by_period ? "period" : "stroke";
  j["units"] = to_string(model.units);
  j["family"] = family->name();
  j[by_period ? "stroke" : "period"] = fixed;
  const bool three_phase = family->name() == "three-phase" ||
                           family->name() == "jerk-limited-three-phase";
  j["a2"] = three_phase ? json(*given.a2) : json(nullptr);
  j["a3"] = three_phase ? json(*given.a3) : json(nullptr);
  j["grid"] = {{by_period ? "period" : "stroke", grid_json(range)},
               {"spacing", f.common->log ? "log" : "linear"}};
  j["cells"] = points.size();
  j["cases"] = case_counts(cases);
  j["non_physical"] = non_physical;
  j["failures"] = failures_json(points, [&](const FamilyPoint& pt) {
    return json{{"period", model.from_model_units(D::time, pt.period)},
                {"stroke", model.from_model_units(D::length, pt.stroke)}};
  });
  write_sweep_outputs(
      paths, points_table(points, values, fixed, f.swept, model.output_units()).records(), j,
      model);
}

}  // namespace

void add_sweep_family_command(CLI::App& sweep, SweptParameter swept) {
  const bool by_period = swept == SweptParameter::period;
  CLI::App* sub = sweep.add_subcommand(
      by_period ? "period" : "stroke",
      by_period ? "f and v_bar of a profile family against the period Δt at the config's "
                  "stroke (Fig. 4). CSV period,stroke,physical,case,v_bar,f,status."
                : "f and v_bar of a profile family against the stroke Δy at the config's "
                  "period (Fig. 5). CSV period,stroke,physical,case,v_bar,f,status.");
  auto f = std::make_shared<FamilyFlags>();
  f->swept = swept;
  f->common = add_sweep_flags(*sub, {by_period ? std::string_view("period") : std::string_view("stroke")});
  sub->add_option("--range", f->range,
                  by_period ? "period grid LO:HI:N (N values, LO, HI > 0). Unit: [-], SI [s]"
                            : "stroke grid LO:HI:N (N values, LO, HI > 0). Unit: [-], SI [m]")
      ->type_name("LO:HI:N")
      ->required()
      ->group("Sweep");
  sub->add_option("--family", f->family,
                  "profile family: three-phase (the config's a2, a3) or scaled-shape (a fixed "
                  "piecewise-constant shape stretched to Δt and scaled to Δy). Default: "
                  "three-phase")
      ->type_name("NAME")
      ->group("Sweep");
  sub->callback([f] { run_sweep_family(*f); });
}

}  // namespace selfalign::cli
