// `selfalign accumulation`: the stick-position map of eq. (59) for the three-phase profile on
// the two-region table (Sect. 7.3, Fig. 18): its fixed point (eq. 60) against x_stick,min
// (eq. 41), its slope there, the contraction of the stick positions, the basin of monotone
// accumulation, the Sect. 7.3 condition x_{n+1}(x_mu) < x_stick,min for accumulation from every
// entry (null, with the reason, where its derivation does not hold), and the map iterated
// from x1. On any other piecewise-affine level (a field) the same map by the exact solver
// (PeriodStickPositionMap): its accumulation point, the general eq. (41), and what a closed form
// alone gives (eq. 59's slope, the basin, Sect. 7.3's condition) null.

#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "report.hpp"
#include "selfalign/analysis/stick_position.hpp"
#include "selfalign/analysis/sweep.hpp"
#include "selfalign/error.hpp"
#include "selfalign/special_values.hpp"
#include "stopping_common.hpp"

namespace selfalign::cli {
namespace {

using nlohmann::json;
using D = Dimension;

constexpr int kMaxIterations = 50;  // map applications listed under "iterates"

struct AccumulationFlags {
  bool as_json = false;
  double x1 = 0, from = 0, to = 0;  // run units
  int n = 400;
  CLI::Option* x1_option = nullptr;
  CLI::Option* from_option = nullptr;
  CLI::Option* to_option = nullptr;
};

const ThreePhaseProfile& three_phase_profile(const SimulateModel& model) {
  const ThreePhaseProfile* p = model.profile->three_phase();
  if (!p)
    throw InvalidParameter("profile", model.profile->kind(),
                           "the stick-position map (eq. 59) needs the three-phase profile");
  return *p;
}

// A length given in the run's units, in [-].
double model_length(const SimulateModel& model, double x) {
  return model.units == UnitSystem::si ? to_dimensionless(D::length, x, model.scales) : x;
}

// x1, x2 = map(x1), ... [-] while below the fixed point and still moving (in floating point),
// at most kMaxIterations applications; and for each p, the applications until
// x >= x_mu + p (x_stick,min - x_mu) (null: not within them).
// `map` is eq. (59) or the exact solver's map, `fixed_point` its accumulation point; a map
// value that is not a number (the object moving at the look) ends the list.
json iterates_json(const std::function<double(double)>& map, double fixed_point, double x_mu,
                   double x_stick_min, double x1, const OutputUnits& u) {
  std::vector<double> x{x1};
  while (static_cast<int>(x.size()) <= kMaxIterations && x.back() < fixed_point) {
    const double next = map(x.back());
    if (next == x.back() || std::isnan(next)) break;  // a fixed point in floating point
    x.push_back(next);
  }
  json j;
  j["x1"] = u.length(x1);
  j["positions"] = json::array();
  for (double v : x) j["positions"].push_back(u.length(v));
  j["iterations"] = x.size() - 1;
  j["passed_fixed_point"] = x.back() > fixed_point;
  j["fractions"] = json::array();
  for (double p : StoppingOptions{}.fractions) {  // 0.99, 0.999
    const double target = x_mu + p * (x_stick_min - x_mu);
    json iterations = nullptr;
    for (std::size_t k = 0; k < x.size() && iterations.is_null(); ++k)
      if (x[k] >= target) iterations = k;
    j["fractions"].push_back(
        {{"p", p}, {"position", length_or_null(u, target)}, {"iterations", iterations}});
  }
  return j;
}

json accumulation_json(const SimulateModel& model, const TwoRegionTable& f,
                       const StickPositionMap& map, double x1) {
  const OutputUnits u = model.output_units();
  const double x_stick_min = stick_position_min(f, model.profile->peak_acceleration());
  json j = stopping_context_json(model, true);
  // A field that is the paper's table (one step from 1 to c_mu under a uniform footprint): its
  // table's parameters, as for the two-region flags.
  j["x_mu"] = u.length(f.x_mu());
  j["width"] = u.length(f.width());
  j["c_mu"] = f.c_mu();
  j["map"] = "eq. 59";
  j["fixed_point"] = u.length(map.fixed_point());           // eq. (60)
  j["x_stick_min"] = length_or_null(u, x_stick_min);       // eq. (41)
  j["fixed_point_minus_x_stick_min"] = length_or_null(u, map.fixed_point() - x_stick_min);
  j["slope_at_fixed_point"] = map.slope_at_fixed_point();  // cos θ [-]
  // of the stick positions (eq. 59, plus the slide back on the diagonal) [-]
  j["contraction_at_fixed_point"] = number_or_null(map.contraction_at_fixed_point());
  j["basin_lower_bound"] = u.length(map.basin_lower_bound());
  j["map_at_x_mu"] = u.length(map(f.x_mu()));              // eq. (59) at x_n = x_mu
  // Sect. 7.3, where its derivation holds (docs/accumulation.md); else null and the reason.
  const EveryEntryAccumulation every = map.every_entry_accumulation();
  j["accumulates_for_every_entry"] = every.applies ? json(every.accumulates) : json(nullptr);
  j["accumulation_condition_applies"] = every.applies;
  j["accumulation_condition_reason"] = every.applies ? json(nullptr) : json(every.reason);
  j["iterates"] = iterates_json([&map](double x) { return map(x); }, map.fixed_point(),
                                f.x_mu(), x_stick_min, x1, u);
  return j;
}

// Any other piecewise-affine level: the stick-position map by the exact solver. Its
// accumulation point is the lowest of its fixed points, the general eq. (41) (x_stick_min, from
// the level's rise x_mu); the contraction there is the map's one-sided slope from below (a
// difference over kSlopeStep of the span x_stick,min - x_mu: far above rounding, far below the
// map's curvature).
json field_accumulation_json(const SimulateModel& model, const PeriodStickPositionMap& map,
                             double x_mu, double x_stick_min, double x1) {
  constexpr double kSlopeStep = 1e-6;
  const OutputUnits u = model.output_units();
  json j = stopping_context_json(model, true);
  j["map"] = "exact solver";
  j["fixed_point"] = length_or_null(u, x_stick_min);
  j["x_stick_min"] = length_or_null(u, x_stick_min);
  j["fixed_point_minus_x_stick_min"] = nullptr;  // one position by definition here
  j["slope_at_fixed_point"] = nullptr;           // eq. (59)'s cos θ: the two-region table's
  double contraction = kNaN;
  if (std::isfinite(x_stick_min) && x_stick_min > x_mu) {
    const double d = kSlopeStep * (x_stick_min - x_mu);
    contraction = (map(x_stick_min) - map(x_stick_min - d)) / d;
  }
  j["contraction_at_fixed_point"] = number_or_null(contraction);
  j["basin_lower_bound"] = nullptr;
  j["map_at_x_mu"] = length_or_null(u, map(x_mu));
  j["accumulates_for_every_entry"] = nullptr;
  j["accumulation_condition_applies"] = false;
  j["accumulation_condition_reason"] =
      "Sect. 7.3's condition is derived for the two-region table and this level is not it: the "
      "map is the exact solver's (map_at_x_mu, iterates)";
  j["iterates"] = iterates_json([&map](double x) { return map(x); }, x_stick_min, x_mu,
                                x_stick_min, x1, u);
  return j;
}

// Header "x_n,x_next,diagonal" (Fig. 18): x_n on the grid as given (run units), x_{n+1} of
// eq. (59), and the diagonal x_{n+1} = x_n whose crossing is the fixed point.
std::string map_csv(const SimulateModel& model, const std::function<double(double)>& map,
                    const std::vector<double>& grid) {
  const OutputUnits u = model.output_units();
  std::string csv = "x_n,x_next,diagonal\n";
  for (double x : grid)
    csv += csv_number(x) + ',' + csv_number(u.length(map(model_length(model, x)))) + ',' +
           csv_number(x) + '\n';
  return csv;
}

std::string accumulation_table(const json& j, UnitSystem units) {
  auto with_unit = [&](const json& v) {
    return v.is_null() ? std::string("-") : table_text(v) + " " + unit_label(units, D::length);
  };
  const json& it = j["iterates"];
  TextTable t;
  t.row("fixed_point (eq. 60)", with_unit(j["fixed_point"]));
  t.row("x_stick_min (eq. 41)", with_unit(j["x_stick_min"]));
  t.row("difference", with_unit(j["fixed_point_minus_x_stick_min"]));
  t.row("map", table_text(j["map"]));
  t.row("slope_at_fixed_point", j["slope_at_fixed_point"].is_null()
                                    ? std::string("-")
                                    : table_text(j["slope_at_fixed_point"]));
  t.row("contraction_at_fixed_point", j["contraction_at_fixed_point"].is_null()
                                          ? std::string("-")
                                          : table_text(j["contraction_at_fixed_point"]));
  t.row("basin_lower_bound", with_unit(j["basin_lower_bound"]));
  t.row("map_at_x_mu", with_unit(j["map_at_x_mu"]));
  const json& every = j["accumulates_for_every_entry"];
  t.row("accumulates_for_every_entry",
        every.is_null() ? "not applicable: " + j["accumulation_condition_reason"].get<std::string>()
                        : (every.get<bool>() ? "yes" : "no"));
  t.row("iterates", table_text(it["iterations"]) + " from x1 = " + with_unit(it["x1"]) +
                        " to " + with_unit(it["positions"].back()) +
                        (it["passed_fixed_point"].get<bool>() ? " (past the fixed point)" : ""));
  for (const json& p : it["fractions"])
    t.row("p = " + table_text(p["p"]), table_text(p["iterations"]) + " iterations to x = " +
                                           with_unit(p["position"]));
  t.row("x_mu", with_unit(j["x_mu"]));
  t.row("units", table_text(j["units"]));
  return t.str();
}

void run_accumulation(const ConfigFlags& flags, const AccumulationFlags& f) {
  constexpr int kMaxGridPoints = 1'000'000;  // a map CSV of ~60 MB
  if (f.n < 1 || f.n > kMaxGridPoints) throw InvalidParameter("n", f.n, "must be in [1, 1e6]");
  const SimulateConfig config = read_config(flags);
  const ReportPaths paths = resolve_report_paths(config, f.as_json);
  const SimulateModel model = stopping_model(config, "accumulation");
  // Eq. (59) is derived for the paper's law; a law from a config file is refused, not ignored
  // (D28: the report was byte-identical whatever the law keys said).
  if (!model.law.is_unit())
    throw InvalidParameter("law", model.law.describe(),
                           "accumulation's stick-position map (eq. 59) holds for the paper's law "
                           "only (static = kinetic, no Stribeck or viscous term): leave out "
                           "mu_static, mu_backward, stribeck_velocity, viscous; stop and accuracy "
                           "take any law");
  // Eq. (59) is the two-region table's: the named table, or a field that is it (one step from
  // 1 to c_mu under a uniform footprint). Any other level: the map by the exact solver.
  const ThreePhaseProfile& profile = three_phase_profile(model);
  const std::optional<TwoRegionTable> table = as_two_region_table(*model.friction);
  const OutputUnits u = model.output_units();
  if (!table) {
    const PeriodStickPositionMap map(profile, *model.friction);
    const double x_mu = friction_rise(*model.friction);
    const double x_stick_min = stick_position_min(*model.friction->piecewise_affine(),
                                                  FrictionLaw{}, profile.peak_acceleration());
    const double x1 = f.x1_option->count() > 0
                          ? model_length(model, require_moderate("x1", f.x1))
                          : x_mu;
    const json report = field_accumulation_json(model, map, x_mu, x_stick_min, x1);
    std::string csv;
    if (paths.csv) {  // default grid: from the rise to a quarter past x_stick,min
      const double span = std::isfinite(x_stick_min) ? x_stick_min - x_mu : 0.0;
      if (f.to_option->count() == 0 && !(span > 0))
        throw InvalidParameter("to", "unset",
                               "give --to: the level has no x_stick,min above its rise to end "
                               "the map's grid at");
      const double from = f.from_option->count() > 0 ? require_moderate("from", f.from)
                                                     : u.length(x_mu);
      const double to = f.to_option->count() > 0 ? require_moderate("to", f.to)
                                                 : u.length(x_mu + 1.25 * span);
      csv = map_csv(model, [&map](double x) { return map(x); }, linear_grid(from, to, f.n));
    }
    deliver_csv_and_report(paths, csv, report, accumulation_table(report, model.units));
    return;
  }
  const TwoRegionTable& friction = *table;
  const StickPositionMap map(profile, friction);
  const double x_mu = friction.x_mu();
  const double x1 = f.x1_option->count() > 0 ? model_length(model, require_moderate("x1", f.x1))
                                             : x_mu;
  // The CSV grid in the run's units, as given.
  const double from = f.from_option->count() > 0 ? require_moderate("from", f.from)
                                                 : u.length(x_mu);
  const double to = f.to_option->count() > 0 ? require_moderate("to", f.to)
                                             : u.length(x_mu + friction.width());
  const std::vector<double> grid = linear_grid(from, to, f.n);
  const json report = accumulation_json(model, friction, map, x1);
  deliver_csv_and_report(paths,
                         paths.csv ? map_csv(model, [&map](double x) { return map(x); }, grid)
                                   : "",
                         report, accumulation_table(report, model.units));
}

}  // namespace

void add_accumulation_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "accumulation",
      "The stick-position map x_n -> x_{n+1} of eq. (59) in the friction transition region "
      "(Sect. 7.3, Fig. 18) for the three-phase profile: fixed point (eq. 60) = x_stick,min "
      "(eq. 41), slope there, contraction of the stick positions, basin, the condition "
      "x_{n+1}(x_mu) < x_stick,min for accumulation from every entry (null with a reason where "
      "its derivation does not hold), and the map iterated from --x1. On any other "
      "piecewise-affine level (a field) the same map by the exact solver, its accumulation point "
      "the general eq. (41) (\"map\": \"exact solver\"; eq. 59's slope, the basin and Sect. "
      "7.3's condition null). --out: the map on a grid, CSV x_n,x_next,diagonal.");
  // No law flags (eq. 59 is the paper's law's; a config file's law keys are refused) and no
  // integrator tolerances (nothing is integrated).
  auto flags = add_stopping_config_flags(
      *sub,
      {{"x0", ""}, {"v0", ""}, {"t0", ""}, {"output_step", ""}, {"mu_static", ""},
       {"mu_backward", ""}, {"stribeck_velocity", ""}, {"stribeck_exponent", ""},
       {"viscous", ""}, {"relative_tolerance", ""}, {"absolute_tolerance", ""},
       {"out", "CSV x_n,x_next,diagonal of the map on the grid --from, --to, --n (Fig. 18; "
               "default: none)"},
       {"summary", "report JSON file, - for stdout (default: <out without extension>"
                   ".summary.json when out is given, else the report is printed)"}});
  auto f = std::make_shared<AccumulationFlags>();
  sub->add_flag("--json", f->as_json, "print the report as JSON (default: a table; with --out: "
                                      "instead of writing <stem>.summary.json)")
      ->group("Output");
  const std::string unit = ". Unit: [-], SI [m]";
  f->x1_option = sub->add_option("--x1", f->x1,
                                 "first stick position x1 the map is iterated from" + unit +
                                     ". Default: x_mu")
                     ->type_name("NUMBER")
                     ->group("Stick-position map");
  f->from_option = sub->add_option("--from", f->from,
                                   "first x_n of the CSV grid" + unit + ". Default: x_mu")
                       ->type_name("NUMBER")
                       ->group("Stick-position map");
  f->to_option = sub->add_option("--to", f->to,
                                 "last x_n of the CSV grid" + unit +
                                     ". Default: x_mu + width (a field: x_mu + 1.25 (x_stick,min "
                                     "- x_mu))")
                     ->type_name("NUMBER")
                     ->group("Stick-position map");
  sub->add_option("--n", f->n, "number of grid points, in [1, 1e6]. Default: " + std::to_string(f->n))
      ->type_name("N")
      ->group("Stick-position map");
  sub->callback([flags, f] { run_accumulation(*flags, *f); });
}

}  // namespace selfalign::cli
