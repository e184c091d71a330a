// The key table of the planar config: every section and key of docs/planar.md, with its type,
// dimension (how an SI value converts to the dimensionless model) and meaning.

#include <algorithm>
#include <array>
#include <iterator>
#include <string>
#include <vector>

#include "selfalign/io/planar_config.hpp"

namespace selfalign {
namespace {

using D = Dimension;
using V = ValueType;

constexpr std::array<Dimension, 2> kPoint{D::length, D::length};
constexpr std::array<Dimension, 3> kPose{D::length, D::length, D::none};
constexpr std::array<Dimension, 3> kTwist{D::velocity, D::velocity, D::rate};

// The profile keys of one axis of [table]; the rotation's Fourier coefficients are angles.
void add_axis(std::vector<KeySpec>& keys, std::string_view section, bool angular) {
  const std::string_view amplitude_unit = angular ? "[rad]" : "[m]";
  const Dimension amplitude = angular ? D::none : D::length;
  keys.insert(keys.end(), {
      {section, "profile", V::text, D::none, {}, {}, "",
       "three-phase (period, stroke, a2, a3, optional jerk) or fourier (period, cos, sin); "
       "default three-phase (a rotation: fourier only)"},
      {section, "period", V::number, D::time, {}, {}, "[s]", "period of the motion, > 0"},
      {section, "stroke", V::number, D::length, {}, {}, "[m]", "three-phase stroke, > 0"},
      {section, "a2", V::number, D::acceleration, {}, {}, "[m/s^2]",
       "three-phase y2'' (Sect. 4.4.3), > 0"},
      {section, "a3", V::number, D::acceleration, {}, {}, "[m/s^2]",
       "three-phase y3'' (Sect. 4.4.3), > 0"},
      {section, "jerk", V::number, D::jerk, {}, {}, "[m/s^3]",
       "three-phase jerk limit, > 0 (default: none, jump accelerations)"},
      {section, "cos", V::numbers, amplitude, {}, {}, amplitude_unit,
       "fourier cosine coefficients A_1..A_N"},
      {section, "sin", V::numbers, amplitude, {}, {}, amplitude_unit,
       "fourier sine coefficients B_1..B_N"},
  });
}

std::vector<KeySpec> make_keys() {
  std::vector<KeySpec> keys{
      {"", "units", V::text, D::none, {}, {}, "", "si (default) or dimensionless"},
      {"scales", "length", V::number, D::none, {}, {}, "[m]",
       "length scale L of the dimensionless model (default 0.01)"},
      {"scales", "mu", V::number, D::none, {}, {}, "[-]",
       "mu_1, the kinetic friction coefficient and the model's unit (default 0.2)"},
      {"scales", "g", V::number, D::none, {}, {}, "[m/s^2]",
       "gravitational acceleration (default 9.81)"},
  };
  add_axis(keys, "table.x", false);
  add_axis(keys, "table.y", false);
  add_axis(keys, "table.rotation", true);
  keys.insert(keys.end(), {
      {"part", "mass", V::number, D::none, {}, {}, "[kg]", "mass (default 1; reported only)"},
      {"part", "inertia", V::number, D::none, {}, {}, "[kg m^2]",
       "moment of inertia about the centre of mass, > 0 (required); the model's I/(m L^2)"},
      {"part", "shape", V::text, D::none, {}, {}, "",
       "contact patch: point (default), disc, rectangle, polygon or points"},
      {"part", "radius", V::number, D::length, {}, {}, "[m]", "disc radius, > 0"},
      {"part", "rings", V::number, D::none, {}, {}, "", "disc rings (default 4)"},
      {"part", "sectors", V::number, D::none, {}, {}, "", "disc sectors of the first ring (default 8)"},
      {"part", "length", V::number, D::length, {}, {}, "[m]", "rectangle length along x, > 0"},
      {"part", "width", V::number, D::length, {}, {}, "[m]", "rectangle width along y, > 0"},
      {"part", "nx", V::number, D::none, {}, {}, "", "rectangle cells along x (default 4)"},
      {"part", "ny", V::number, D::none, {}, {}, "", "rectangle cells along y (default 4)"},
      {"part", "xs", V::numbers, D::length, {}, {}, "[m]",
       "polygon vertices or points: x in the body frame"},
      {"part", "ys", V::numbers, D::length, {}, {}, "[m]",
       "polygon vertices or points: y in the body frame"},
      {"part", "subdivisions", V::number, D::none, {}, {}, "",
       "polygon: subdivisions of each triangle (default 2)"},
      {"part", "loads", V::numbers, D::none, {}, {}, "[-]",
       "points: load fractions, >= 0, summing to 1, centred on the centre of mass"},
      {"friction", "mu_static", V::number, D::none, {}, {}, "[-]",
       "absolute static coefficient, >= [scales] mu (default: equal to it)"},
      {"friction", "static", V::number, D::none, {}, {}, "",
       "refused: the relative convention before issue 21 (give mu_static)"},
      {"friction", "kinetic", V::number, D::none, {}, {}, "",
       "refused: the relative convention before issue 21 (the kinetic coefficient is [scales] mu)"},
      {"field", "type", V::text, D::none, {}, {}, "",
       "uniform (default), half-plane, strip, rectangle, circle, grid or axis (the 1-D field along "
       "a direction)"},
      {"field", "level", V::number, D::none, {}, {}, "[-]", "uniform: mu/mu_1 (default 1)"},
      {"field", "origin", V::numbers, D::none, kPoint, "[x, y]", "[m]",
       "half-plane, strip, grid, axis: origin (default [0, 0])"},
      {"field", "centre", V::numbers, D::none, kPoint, "[x, y]", "[m]",
       "rectangle, circle: centre (default [0, 0])"},
      {"field", "angle", V::number, D::none, {}, {}, "[rad]", "orientation (default 0)"},
      {"field", "width", V::number, D::length, {}, {}, "[m]",
       "rough regions: width of the transition band (default 0.1 L)"},
      {"field", "half_width", V::number, D::length, {}, {}, "[m]", "strip, rectangle: half width"},
      {"field", "half_length", V::number, D::length, {}, {}, "[m]", "rectangle: half length"},
      {"field", "radius", V::number, D::length, {}, {}, "[m]", "circle: radius"},
      {"field", "c_mu", V::number, D::none, {}, {}, "[-]",
       "rough regions: mu_2/mu_1 (default 2.5)"},
      {"field", "dx", V::number, D::length, {}, {}, "[m]", "grid: spacing along x"},
      {"field", "dy", V::number, D::length, {}, {}, "[m]", "grid: spacing along y"},
      {"field", "nx", V::number, D::none, {}, {}, "", "grid: nodes along x (default 2)"},
      {"field", "ny", V::number, D::none, {}, {}, "", "grid: nodes along y (default 2)"},
      {"field", "levels", V::numbers, D::none, {}, {}, "[-]",
       "grid: mu/mu_1 at the nodes, row by row; axis: mu/mu_1 at each of positions"},
      {"field", "positions", V::numbers, D::length, {}, {}, "[m]",
       "axis: the samples' positions along the axis, strictly increasing (or file)"},
      {"field", "interpolation", V::text, D::none, {}, {}, "",
       "axis: steps (default: each level holds to the next position) or linear"},
      {"field", "file", V::text, D::none, {}, {}, "",
       "axis: a CSV of 'position,level' rows (positions in [m]), instead of positions/levels"},
      {"run", "step", V::number, D::time, {}, {}, "[s]",
       "Moreau step h, > 0, dividing the periods (required)"},
      {"run", "theta", V::number, D::none, {}, {}, "[-]", "Moreau theta (default 0.5)"},
      {"run", "periods", V::number, D::none, {}, {}, "", "simulate: periods (default 10)"},
      {"run", "pose", V::numbers, D::none, kPose, "[x, y, angle]", "[m, m, rad]",
       "initial pose on the table (default [0, 0, 0])"},
      {"run", "twist", V::numbers, D::none, kTwist, "[ux, uy, omega]", "[m/s, m/s, rad/s]",
       "initial twist relative to the table (default [0, 0, 0])"},
      {"run", "every", V::number, D::none, {}, {}, "", "simulate: a row every N steps (default 1)"},
      {"run", "method", V::text, D::none, {}, {}, "",
       "simulate: time-stepping (default), exact (the exact point solver: a point part at its "
       "centre on a uniform field, a translating table with piecewise-constant accelerations) "
       "or integrator (the patch integrator: any part, a translating table with "
       "piecewise-constant accelerations)"},
      {"run", "relative_tolerance", V::number, D::none, {}, {}, "[-]",
       "simulate, method integrator: relative tolerance in (0, 1) (default 1e-10)"},
      {"run", "absolute_tolerance", V::number, D::none, {}, {}, "[-]",
       "simulate, method integrator: absolute tolerance in (0, 1) (default 1e-12)"},
      {"run", "transient", V::number, D::none, {}, {}, "",
       "steady: periods before the fixed-point search (default 0)"},
      {"run", "window", V::number, D::none, {}, {}, "", "not used (the window average before issue 21)"},
      {"run", "steady_periods", V::number, D::none, {}, {}, "",
       "steady: periods of the search at most (default 2000)"},
      {"run", "tolerance", V::number, D::none, {}, {}, "[-]",
       "steady: the fixed point's tolerance, in [0, 1) (0: the default)"},
      {"field_map", "x", V::numbers, D::length, {}, {}, "[m]", "drift field: x of the grid"},
      {"field_map", "y", V::numbers, D::length, {}, {}, "[m]", "drift field: y of the grid"},
      {"field_map", "angles", V::numbers, D::none, {}, {}, "[rad]", "drift field: angles"},
      {"field_map", "periods", V::number, D::none, {}, {}, "", "drift field: periods from rest (default 1)"},
      {"stop", "entries", V::rows, D::none, kPose, "[x, y, angle]", "[m, m, rad]",
       "entry poses (default: [run] pose)"},
      {"stop", "max_periods", V::number, D::none, {}, {}, "",
       "periods before a part counts as never stopping (default 2000)"},
  });
  // Settings: the unit L, the reported-only mass, the patch's and the grid's discretisation,
  // the solver's and the analyses' own keys. Every other number is a model parameter (the
  // parameter view, planar_model_parameters).
  constexpr std::string_view kSettings[] = {
      "scales.length", "part.mass", "part.rings", "part.sectors", "part.nx", "part.ny",
      "part.subdivisions", "field.nx", "field.ny", "run.step", "run.theta", "run.periods",
      "run.every", "run.transient", "run.window", "run.steady_periods", "run.tolerance",
      "run.relative_tolerance", "run.absolute_tolerance"};
  for (KeySpec& k : keys) {
    const std::string name = qualified_key(k.section, k.name);
    if (k.section == "field_map" || k.section == "stop" ||
        std::find(std::begin(kSettings), std::end(kSettings), name) != std::end(kSettings))
      k.role = KeyRole::setting;
  }
  return keys;
}

}  // namespace

const KeyTable& planar_config_keys() {
  static const std::vector<KeySpec> keys = make_keys();
  static const KeyTable table{keys, "docs/planar.md"};
  return table;
}

}  // namespace selfalign
