#include "selfalign/io/planar_config.hpp"

#include <cmath>
#include <algorithm>
#include <initializer_list>
#include <optional>

#include <nlohmann/json.hpp>

#include "selfalign/error.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/io/config_reader.hpp"
#include "selfalign/io/document.hpp"
#include "selfalign/io/run_files.hpp"
#include "selfalign/io/unit_system.hpp"
#include "selfalign/io/spelling.hpp"
#include "selfalign/profiles/fourier.hpp"
#include "selfalign/profiles/jerk_limited_three_phase.hpp"
#include "selfalign/profiles/make_three_phase_profile.hpp"
#include "selfalign/profiles/three_phase.hpp"
#include "selfalign/special_values.hpp"

namespace selfalign {
namespace {

using nlohmann::json;

using Section = ConfigSection;

// Sections ([table.x], [part], ...) hold numbers, strings and arrays; [stop] entries are an
// array of [x, y, angle] arrays: 4 levels.
const DocumentKind kPlanarDocument{"config", "--config", 4};

// One axis of [table], in model units (the rotation's coefficients are angles: the key table
// gives them no dimension).
std::unique_ptr<TableProfile> make_profile(const Section& p, bool angular) {
  const std::string kind = p.text("profile", "three-phase");
  if (kind == "three-phase") {
    if (angular)
      throw InvalidParameter(p.key("profile"), kind, "a rotation needs profile = \"fourier\"");
    return make_three_phase_profile(
        {p.required("period"), p.required("stroke"), p.required("a2"), p.required("a3")},
        p.has("jerk") ? p.required("jerk") : kInf);
  }
  if (kind == "fourier")
    return std::make_unique<FourierProfile>(p.required("period"), p.list("cos"), p.list("sin"));
  throw InvalidParameter(p.key("profile"), kind, "must be \"three-phase\" or \"fourier\"");
}

// A point [x, y] (the key table checks its length and converts it).
void xy(const Section& s, std::string_view k, double& x, double& y) {
  const std::vector<double> v = s.list(k, {0.0, 0.0});
  x = v[0], y = v[1];
}

// The 1-D field of an axis field: the rows of `file` (positions in the config's length unit) or
// `positions` and `levels`, read by the 1-D field's own readers (friction_field.hpp).
FrictionField axis_profile(const Section& f, const InputUnits& u) {
  const FieldInterpolation interpolation = [&] {
    try {
      return parse_field_interpolation(f.text("interpolation", "steps"));
    } catch (const InvalidParameter& e) {
      throw InvalidParameter(f.key("interpolation"), e.value(), e.allowed());
    }
  }();
  if (f.has("file")) {
    if (f.has("positions") || f.has("levels"))
      throw InvalidParameter(f.key("file"), f.text("file", ""),
                             "give either file or positions and levels, not both");
    const FrictionField read = [&] {
      try {
        return FrictionField::from_csv(f.text("file", ""), interpolation);
      } catch (const InvalidParameter& e) {  // "friction field <path>:<line> ...": the key's file
        constexpr std::string_view kReader = "friction field";
        std::string where = e.name();
        if (!where.starts_with(kReader)) throw;
        where.erase(0, kReader.size());
        throw InvalidParameter(f.key("file") + where, e.value(), e.allowed());
      }
    }();
    return u.si() ? read.in_units_of(u.scales().length()) : read;
  }
  if (!f.has("positions") || !f.has("levels"))
    throw InvalidParameter(f.key(f.has("positions") ? "levels" : "positions"), "missing",
                           "is required for an axis field (or give file)");
  const std::vector<double> positions = f.list("positions"), levels = f.list("levels");
  try {
    return FrictionField::samples(positions, levels, interpolation);
  } catch (const InvalidParameter& e) {
    const bool position = e.name().find("position") != std::string::npos;
    throw InvalidParameter(f.key(position ? "positions" : "levels"), e.value(), e.allowed());
  }
}

PlanarField make_field(const Section& f, const InputUnits& u) {
  const std::string type = f.text("type", "uniform");
  // The rough regions' band, read by the types that have one (so that the parameter view lists
  // them only there); braced initialisers evaluate left to right.
  const auto width = [&] { return f.number("width", u.si() ? 0.1 * u.scales().length() : 0.1); };
  const auto c_mu = [&] { return f.number("c_mu", 2.5); };
  if (type == "uniform") return UniformPlanarField{f.number("level", 1.0)};
  if (type == "half-plane") {
    HalfPlaneStepField h{0, 0, f.number("angle", 0), width(), c_mu()};
    xy(f, "origin", h.origin_x, h.origin_y);
    return h;
  }
  if (type == "strip") {
    StripField h{0, 0, f.number("angle", 0), f.required("half_width"), width(), c_mu()};
    xy(f, "origin", h.origin_x, h.origin_y);
    return h;
  }
  if (type == "rectangle") {
    RectangularPocketField h{0, 0, f.number("angle", 0), f.required("half_length"),
                             f.required("half_width"), width(), c_mu()};
    xy(f, "centre", h.centre_x, h.centre_y);
    return h;
  }
  if (type == "circle") {
    CircularPocketField h{0, 0, f.required("radius"), width(), c_mu()};
    xy(f, "centre", h.centre_x, h.centre_y);
    return h;
  }
  if (type == "grid") {
    GridField g;
    xy(f, "origin", g.origin_x, g.origin_y);
    g.angle = f.number("angle", 0);
    g.dx = f.required("dx"), g.dy = f.required("dy");
    g.nx = f.integer("nx", 2, 2, 100000), g.ny = f.integer("ny", 2, 2, 100000);
    g.levels = f.list("levels");
    return g;
  }
  if (type == "axis") {
    AxisField a{axis_profile(f, u)};
    xy(f, "origin", a.origin_x, a.origin_y);
    a.angle = f.number("angle", 0);
    return a;
  }
  throw InvalidParameter(f.key("type"), type,
                         "must be uniform, half-plane, strip, rectangle, circle, grid or axis");
}

ContactPatch make_patch(const Section& p) {
  const std::string shape = p.text("shape", "point");
  if (shape == "point") return point_patch();
  if (shape == "disc")
    return disc_patch(p.required("radius"), p.integer("rings", 4, 1, 10000),
                      p.integer("sectors", 8, 1, 10000));
  if (shape == "rectangle")
    return rectangle_patch(p.required("length"), p.required("width"), p.integer("nx", 4, 1, 10000),
                           p.integer("ny", 4, 1, 10000));
  if (shape == "polygon")
    return polygon_patch(p.list("xs"), p.list("ys"), p.integer("subdivisions", 2, 1, 100));
  if (shape == "points") return weighted_points_patch(p.list("xs"), p.list("ys"), p.list("loads"));
  throw InvalidParameter(p.key("shape"), shape, "must be point, disc, rectangle, polygon or points");
}

// A pose [x, y, angle] (the key table checks its length and converts it).
PlanarPose pose_from(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

// The library's names of what a section builds, as the section's keys (messages name the key
// the user wrote, with its section: "table.x.cos", "part.loads").
struct SectionNames {
  std::vector<std::string> users;
  std::vector<UserName> names;
  SectionNames(std::initializer_list<std::pair<std::string_view, std::string>> pairs) {
    users.reserve(pairs.size());
    for (const auto& [library, user] : pairs) users.push_back(user);
    std::size_t i = 0;
    for (const auto& [library, user] : pairs) names.push_back({library, users[i++]});
  }
  SectionNames(const SectionNames&) = delete;  // `names` views `users`
};

SectionNames axis_names(const std::string& k) {  // k = "table.x."
  return {{"fourier coefficients", k + "cos, " + k + "sin"},
          {"fourier order", k + "cos, " + k + "sin"},
          {"fourier_cos", k + "cos"},
          {"fourier_sin", k + "sin"}};
}
const SectionNames kPartNames{{"load_fractions", "part.loads"},
                              {"points", "part.xs, part.ys, part.loads"},
                              {"point x", "part.xs"},
                              {"point y", "part.ys"},
                              {"polygon vertex x", "part.xs"},
                              {"polygon vertex y", "part.ys"},
                              {"polygon", "part.xs, part.ys"}};
const SectionNames kFrictionNames{{"mu_static", "friction.mu_static"}, {"mu", "scales.mu"}};
const SectionNames kScalesNames{{"length_scale", "scales.length"}};
const SectionNames kFieldNames{{"centre_x", "field.centre"}, {"centre_y", "field.centre"},
                               {"origin_x", "field.origin"}, {"origin_y", "field.origin"}};
const SectionNames kRunNames{{"step", "run.step"}, {"theta", "run.theta"},
                             {"inertia", "part.inertia"}};

// One --set "section.key=value": the value parsed by the key's type (parse_config_value) and
// written into the document before it is read, so that it is checked as the file's values are.
void apply_setting(json& doc, const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InvalidParameter("--set", assignment, "must be SECTION.KEY=VALUE, e.g. run.step=4e-5");
  std::string name = assignment.substr(0, eq);
  // "section.key[i]": element i of an array the config gives (the parameter view's names).
  std::optional<std::size_t> element;
  if (const std::size_t open = name.find('['); open != std::string::npos) {
    const std::string index = name.substr(open + 1, name.size() - open - 2);
    if (name.back() != ']' || index.empty() ||
        index.find_first_not_of("0123456789") != std::string::npos || index.size() > 9)
      throw InvalidParameter("--set", name, "must be SECTION.KEY or SECTION.KEY[i], i a whole number");
    element = static_cast<std::size_t>(std::stoul(index));
    name.erase(open);
  }
  const std::size_t dot = name.rfind('.');
  const std::string section = dot == std::string::npos ? "" : name.substr(0, dot);
  const std::string key = dot == std::string::npos ? name : name.substr(dot + 1);
  const KeyTable& table = planar_config_keys();
  if (table.has_section(name))
    throw InvalidParameter("--set", name, "is a table: set one of its keys, " + name + ".KEY=VALUE");
  if (!table.has_section(section))
    throw InvalidParameter("--set", name, "[" + section + "] is not a table of the config; " +
                                              unknown_key_message(table, "", name));
  const KeySpec* spec = table.find(section, key);
  if (!spec) throw InvalidParameter("--set", name, unknown_key_message(table, section, key));
  json* node = &doc;
  for (std::size_t begin = 0; begin < section.size();) {
    const std::size_t end = std::min(section.find('.', begin), section.size());
    json& child = (*node)[section.substr(begin, end - begin)];
    if (child.is_null()) child = json::object();
    if (!child.is_object())
      throw InvalidParameter(section.substr(0, end), document_value_text(child), "must be a table");
    node = &child;
    begin = end + 1;
  }
  const std::string text = assignment.substr(eq + 1);
  if (!element) {
    (*node)[key] = to_json(parse_config_value(*spec, text));
    return;
  }
  json& array = (*node)[key];
  if (spec->type != ValueType::numbers)
    throw InvalidParameter("--set", name + "[" + std::to_string(*element) + "]",
                           "only an array key has elements");
  if (!array.is_array() || *element >= array.size())
    throw InvalidParameter("--set", name + "[" + std::to_string(*element) + "]",
                           array.is_array() ? "is beyond the " + std::to_string(array.size()) +
                                                  " values the config gives"
                                            : "the config does not give " + name +
                                                  ": set the whole array, " + name + "=...");
  KeySpec one = *spec;  // one element: a number of the key's (component's) dimension
  one.type = ValueType::number;
  one.components = {};
  try {
    array[*element] = to_json(parse_config_value(one, text));
  } catch (const InvalidParameter& e) {  // name the element as given
    throw InvalidParameter(e.name() + "[" + std::to_string(*element) + "]", e.value(), e.allowed());
  }
}

}  // namespace

PlanarSetup load_planar_config(const std::string& path, const std::vector<std::string>& set,
                               std::vector<ConfigSection::Read>* caller_reads) {
  std::vector<ConfigSection::Read> log;  // every key read: the caller's view, and unused keys
  json doc = read_document(path, kPlanarDocument);
  if (!doc.is_object()) throw InvalidParameter("config", path, "must be a table of sections");
  for (const std::string& assignment : set) apply_setting(doc, assignment);
  const ConfigValues values = read_config_values(doc, planar_config_keys(), path);
  PlanarSetup st;
  st.path = path;
  Section top(values, "", InputUnits());
  top.record_reads(&log);
  const std::string units = top.text("units", "si");
  if (units != "si" && units != "dimensionless")
    throw InvalidParameter("units", units, "must be \"si\" or \"dimensionless\"");
  st.si = units == "si";
  Section sc(values, "scales", InputUnits());  // the scales are the unit system itself
  sc.record_reads(&log);
  st.scales = with_user_names(
      kScalesNames.names,
      [&] { return Scales(sc.number("length", 0.01), sc.number("mu", 0.2), sc.number("g", 9.81)); },
      "scales.");
  const InputUnits u = st.si ? InputUnits(st.scales) : InputUnits();
  const auto section = [&](std::string name) {
    Section s(values, std::move(name), u);
    s.record_reads(&log);
    return s;
  };
  PlanarTableMotion& m = st.problem.motion;
  for (const char* axis : {"x", "y", "rotation"}) {
    const Section p = section(std::string("table.") + axis);
    if (!values.has_section(p.name())) continue;
    const SectionNames names = axis_names(p.key(""));
    st.profiles.push_back(with_user_names(
        names.names, [&] { return make_profile(p, std::string(axis) == "rotation"); },
        p.key("")));
    const TableProfile* ptr = st.profiles.back().get();
    (std::string(axis) == "x" ? m.first : std::string(axis) == "y" ? m.second : m.rotation) = ptr;
  }
  if (st.profiles.empty())
    throw InvalidParameter("table", "no motion", "needs [table.x], [table.y] or [table.rotation]");
  const Section part = section("part");
  st.mass = part.number("mass", 1.0);
  require_positive_moderate("part.mass", st.mass);
  const double inertia = part.required("inertia");
  // I [kg m^2] to the model's j = I/(m L^2) (docs/planar.md): by hand, it needs the mass.
  st.problem.part.inertia = st.si ? inertia / (st.mass * st.scales.length() * st.scales.length()) : inertia;
  if (!(inertia > 0) || !std::isfinite(inertia))
    throw InvalidParameter("part.inertia", inertia, "must be finite and > 0");
  st.problem.part.patch =
      with_user_names(kPartNames.names, [&] { return make_patch(part); }, "part.");
  // One convention for coefficients everywhere (issue 21; docs/config.md "Friction law"):
  // absolute coefficients, the kinetic one being the model's unit [scales] mu, as --mu in the
  // 1-D subcommands. The keys of the relative convention before it are refused by name, never
  // read as absolute values (a static = 1.2 would silently become mu_static = 1.2).
  const Section fr = section("friction");
  for (const char* old : {"static", "kinetic"})
    if (fr.has(old))
      throw InvalidParameter(fr.key(old), format_number(fr.number(old, 0.0)),
                             "[friction] takes absolute coefficients: give mu_static (static "
                             "times [scales] mu); the kinetic coefficient is [scales] mu");
  const std::optional<double> mu_static =
      fr.has("mu_static") ? std::optional<double>(fr.number("mu_static", 0.0)) : std::nullopt;
  st.problem.law = with_user_names(
      kFrictionNames.names,
      [&] { return law_of_coefficients(st.scales.mu(), mu_static, std::nullopt); }, "");
  const Section field = section("field");
  // An axis field's file is an input of the run (io/run_files.hpp), registered under its key
  // before it is read: an output naming it is refused naming the output and field.file.
  if (field.has("file")) register_input_file(field.text("file", ""), "field.file");
  st.problem.field = with_user_names(
      kFieldNames.names,
      [&] {
        PlanarField f = make_field(field, u);
        validate(f);
        return f;
      },
      "field.");
  const Section run = section("run");
  st.problem.options.step = run.required("step");
  st.problem.options.theta = run.number("theta", 0.5);
  st.periods = run.integer("periods", 10, 1, 1000000);
  st.transient = run.integer("transient", 0, 0, 100000);
  // Before issue 21 `planar steady` averaged over two windows of `window` periods; it now
  // finds the fixed point of the period map. The key is still read (and checked) so that
  // older configs run; the CLI says it is not used.
  st.window_given = run.has("window");
  st.window = run.integer("window", 10, 1, 100000);
  st.steady_periods = run.integer("steady_periods", 2000, 1, 1000000);
  st.tolerance = run.number("tolerance", 0.0);
  if (!(st.tolerance >= 0 && st.tolerance < 1))
    throw InvalidParameter(run.key("tolerance"), st.tolerance, "must be in [0, 1) (0: the default)");
  st.every = run.integer("every", 1, 1, 1000000000);
  {
    const std::string method = run.text("method", "time-stepping");
    if (method == "time-stepping") st.method = Method::time_stepping;
    else if (method == "exact") st.method = Method::exact;
    else if (method == "integrator") st.method = Method::integrator;
    else
      throw InvalidParameter(run.key("method"), method,
                             "must be time-stepping, exact or integrator");
  }
  // The patch integrator's tolerances (Method::integrator).
  st.problem.integrator.relative_tolerance = run.number("relative_tolerance", 1e-10);
  st.problem.integrator.absolute_tolerance = run.number("absolute_tolerance", 1e-12);
  for (const char* key : {"relative_tolerance", "absolute_tolerance"}) {
    const double v = std::string(key) == "relative_tolerance"
                         ? st.problem.integrator.relative_tolerance
                         : st.problem.integrator.absolute_tolerance;
    if (!(v > 0 && v < 1)) throw InvalidParameter(run.key(key), v, "must be in (0, 1)");
  }
  st.pose = pose_from(run.list("pose", {0, 0, 0}));
  const std::vector<double> tw = run.list("twist", {0, 0, 0});
  st.twist = {tw[0], tw[1], tw[2]};
  const Section fm = section("field_map");
  st.grid_x = fm.list("x", {0.0}), st.grid_y = fm.list("y", {0.0});
  st.grid_angles = fm.list("angles", {0.0});
  st.field_periods = fm.integer("periods", 1, 1, 100000);
  const Section stop = section("stop");
  st.max_periods = stop.integer("max_periods", 2000, 1, 1000000);
  if (stop.has("entries")) {
    for (const std::vector<double>& row : stop.rows("entries")) st.entries.push_back(pose_from(row));
  } else {
    st.entries.push_back(st.pose);
  }
  with_user_names(kRunNames.names, [&] { validate(st.problem); });
  for (const ConfigValues::Entry& e : values.entries())
    if (std::none_of(log.begin(), log.end(),
                     [&](const ConfigSection::Read& r) { return r.key == e.key; }))
      st.unused_keys.push_back(qualified_key(e.key->section, e.key->name));
  if (caller_reads) *caller_reads = std::move(log);
  return st;
}

}  // namespace selfalign
