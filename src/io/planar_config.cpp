#include "selfalign/io/planar_config.hpp"

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <set>

#include <nlohmann/json.hpp>

#include "selfalign/error.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/io/document.hpp"
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

// One table of the file with its allowed keys: every read is checked, every key must be known.
class Section {
 public:
  Section(const json& node, std::string name, std::set<std::string> allowed)
      : node_(node), name_(std::move(name)) {
    if (!node_.is_object()) throw InvalidParameter(name_, document_value_text(node_), "must be a table");
    for (const auto& [k, v] : node_.items())
      if (!allowed.count(k)) {
        const std::string best =
            closest_name(k, std::vector<std::string>(allowed.begin(), allowed.end()));
        throw InvalidParameter(key(k), "unknown key",
                               "is not a key of [" + name_ + "]" +
                                   (best.empty() ? "" : " (did you mean " + best + "?)"));
      }
  }
  std::string key(const std::string& k) const { return name_.empty() ? k : name_ + "." + k; }
  bool has(const std::string& k) const { return node_.contains(k); }
  double number(const std::string& k, double fallback) const {
    if (!has(k)) return fallback;
    return as_number(node_.at(k), k);
  }
  double required(const std::string& k) const {
    if (!has(k)) throw InvalidParameter(key(k), "missing", "is required");
    return as_number(node_.at(k), k);
  }
  int integer(const std::string& k, int fallback, int lo, int hi) const {
    const double v = number(k, fallback);
    if (!(v >= lo && v <= hi) || v != std::floor(v))
      throw InvalidParameter(key(k), v,
                             "must be a whole number in [" + std::to_string(lo) + ", " +
                                 std::to_string(hi) + "]");
    return static_cast<int>(v);
  }
  std::string text(const std::string& k, const std::string& fallback) const {
    if (!has(k)) return fallback;
    if (!node_.at(k).is_string()) throw InvalidParameter(key(k), document_value_text(node_.at(k)), "must be a string");
    return node_.at(k).get<std::string>();
  }
  std::vector<double> list(const std::string& k, std::vector<double> fallback = {}) const {
    if (!has(k)) return fallback;
    const json& a = node_.at(k);
    if (!a.is_array()) throw InvalidParameter(key(k), document_value_text(a), "must be an array of numbers");
    std::vector<double> out;
    for (const auto& v : a) out.push_back(as_number(v, k));
    return out;
  }
  const json& raw(const std::string& k) const { return node_.at(k); }

 private:
  double as_number(const json& v, const std::string& k) const {
    if (v.is_number()) return v.get<double>();  // TOML nan and inf included
    throw InvalidParameter(key(k), document_value_text(v), "must be a number");
  }
  const json& node_;
  std::string name_;
};

// Sections ([table.x], [part], ...) hold numbers, strings and arrays; [stop] entries are an
// array of [x, y, angle] arrays: 4 levels.
const DocumentKind kPlanarDocument{"config", "--config", 4};

using D = Dimension;

std::unique_ptr<TableProfile> make_profile(const Section& p, const InputUnits& u, bool angular) {
  const std::string kind = p.text("profile", "three-phase");
  if (kind == "three-phase") {
    if (angular)
      throw InvalidParameter(p.key("profile"), kind, "a rotation needs profile = \"fourier\"");
    const double period = u(D::time, p.required("period")), stroke = u(D::length, p.required("stroke"));
    const double a2 = u(D::acceleration, p.required("a2")), a3 = u(D::acceleration, p.required("a3"));
    return make_three_phase_profile({period, stroke, a2, a3},
                                    p.has("jerk") ? u(D::jerk, p.required("jerk")) : kInf);
  }
  if (kind == "fourier") {
    std::vector<double> c = p.list("cos"), s = p.list("sin");
    for (auto* v : {&c, &s})
      for (double& x : *v) x = angular ? x : u(D::length, x);  // rad stay rad
    return std::make_unique<FourierProfile>(u(D::time, p.required("period")), c, s);
  }
  throw InvalidParameter(p.key("profile"), kind, "must be \"three-phase\" or \"fourier\"");
}

void xy(const Section& s, const std::string& k, const InputUnits& u, double& x, double& y) {
  const std::vector<double> v = s.list(k, {0.0, 0.0});
  if (v.size() != 2) throw InvalidParameter(s.key(k), std::to_string(v.size()) + " values", "must be [x, y]");
  x = u(D::length, v[0]), y = u(D::length, v[1]);
}

PlanarField make_field(const Section& f, const InputUnits& u) {
  const std::string type = f.text("type", "uniform");
  const double c_mu = f.number("c_mu", 2.5);
  const double width = u(D::length, f.number("width", u.si() ? 0.1 * u.scales().length() : 0.1));
  if (type == "uniform") return UniformPlanarField{f.number("level", 1.0)};
  if (type == "half-plane") {
    HalfPlaneStepField h{0, 0, f.number("angle", 0), width, c_mu};
    xy(f, "origin", u, h.origin_x, h.origin_y);
    return h;
  }
  if (type == "strip") {
    StripField h{0, 0, f.number("angle", 0), u(D::length, f.required("half_width")), width, c_mu};
    xy(f, "origin", u, h.origin_x, h.origin_y);
    return h;
  }
  if (type == "rectangle") {
    RectangularPocketField h{0, 0, f.number("angle", 0), u(D::length, f.required("half_length")),
                             u(D::length, f.required("half_width")), width, c_mu};
    xy(f, "centre", u, h.centre_x, h.centre_y);
    return h;
  }
  if (type == "circle") {
    CircularPocketField h{0, 0, u(D::length, f.required("radius")), width, c_mu};
    xy(f, "centre", u, h.centre_x, h.centre_y);
    return h;
  }
  if (type == "grid") {
    GridField g;
    xy(f, "origin", u, g.origin_x, g.origin_y);
    g.angle = f.number("angle", 0);
    g.dx = u(D::length, f.required("dx")), g.dy = u(D::length, f.required("dy"));
    g.nx = f.integer("nx", 2, 2, 100000), g.ny = f.integer("ny", 2, 2, 100000);
    g.levels = f.list("levels");
    return g;
  }
  throw InvalidParameter(f.key("type"), type,
                         "must be uniform, half-plane, strip, rectangle, circle or grid");
}

ContactPatch make_patch(const Section& p, const InputUnits& u) {
  const std::string shape = p.text("shape", "point");
  const auto lengths = [&](const std::string& k) {
    std::vector<double> v = p.list(k);
    for (double& x : v) x = u(D::length, x);
    return v;
  };
  if (shape == "point") return point_patch();
  if (shape == "disc")
    return disc_patch(u(D::length, p.required("radius")), p.integer("rings", 4, 1, 10000),
                      p.integer("sectors", 8, 1, 10000));
  if (shape == "rectangle")
    return rectangle_patch(u(D::length, p.required("length")), u(D::length, p.required("width")),
                           p.integer("nx", 4, 1, 10000), p.integer("ny", 4, 1, 10000));
  if (shape == "polygon")
    return polygon_patch(lengths("xs"), lengths("ys"), p.integer("subdivisions", 2, 1, 100));
  if (shape == "points") return weighted_points_patch(lengths("xs"), lengths("ys"), p.list("loads"));
  throw InvalidParameter(p.key("shape"), shape, "must be point, disc, rectangle, polygon or points");
}

PlanarPose pose_from(const std::vector<double>& v, const std::string& key, const InputUnits& u) {
  if (v.size() != 3) throw InvalidParameter(key, std::to_string(v.size()) + " values", "must be [x, y, angle]");
  return {u(D::length, v[0]), u(D::length, v[1]), v[2]};
}

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

}  // namespace

PlanarSetup load_planar_config(const std::string& path) {
  const json doc = read_document(path, kPlanarDocument);
  if (!doc.is_object()) throw InvalidParameter("config", path, "must be a table of sections");
  const Section top(doc, "", {"units", "scales", "table", "part", "friction", "field", "run",
                              "field_map", "stop"});
  PlanarSetup st;
  st.path = path;
  const std::string units = top.text("units", "si");
  if (units != "si" && units != "dimensionless")
    throw InvalidParameter("units", units, "must be \"si\" or \"dimensionless\"");
  st.si = units == "si";
  const json empty = json::object();
  const auto section = [&](const char* name, std::set<std::string> keys) {
    return Section(doc.contains(name) ? doc.at(name) : empty, name, std::move(keys));
  };
  const Section sc = section("scales", {"length", "mu", "g"});
  st.scales = with_user_names(
      kScalesNames.names,
      [&] { return Scales(sc.number("length", 0.01), sc.number("mu", 0.2), sc.number("g", 9.81)); },
      "scales.");
  const InputUnits u = st.si ? InputUnits(st.scales) : InputUnits();
  const Section table = section("table", {"x", "y", "rotation"});
  const std::set<std::string> profile_keys{"profile", "period", "stroke", "a2", "a3", "jerk", "cos", "sin"};
  PlanarTableMotion& m = st.problem.motion;
  for (const char* axis : {"x", "y", "rotation"}) {
    if (!table.has(axis)) continue;
    const Section p(table.raw(axis), std::string("table.") + axis, profile_keys);
    const SectionNames names = axis_names(p.key(""));
    st.profiles.push_back(with_user_names(
        names.names, [&] { return make_profile(p, u, std::string(axis) == "rotation"); },
        p.key("")));
    const TableProfile* ptr = st.profiles.back().get();
    (std::string(axis) == "x" ? m.first : std::string(axis) == "y" ? m.second : m.rotation) = ptr;
  }
  if (st.profiles.empty())
    throw InvalidParameter("table", "no motion", "needs [table.x], [table.y] or [table.rotation]");
  const Section part = section("part", {"mass", "inertia", "shape", "radius", "rings", "sectors",
                                        "length", "width", "nx", "ny", "xs", "ys", "subdivisions",
                                        "loads"});
  st.mass = part.number("mass", 1.0);
  require_positive_moderate("part.mass", st.mass);
  const double inertia = part.required("inertia");
  st.problem.part.inertia = st.si ? inertia / (st.mass * st.scales.length() * st.scales.length()) : inertia;
  if (!(inertia > 0) || !std::isfinite(inertia))
    throw InvalidParameter("part.inertia", inertia, "must be finite and > 0");
  st.problem.part.patch =
      with_user_names(kPartNames.names, [&] { return make_patch(part, u); }, "part.");
  // One convention for coefficients everywhere (issue 21; docs/config.md "Friction law"):
  // absolute coefficients, the kinetic one being the model's unit [scales] mu, as --mu in the
  // 1-D subcommands. The keys of the relative convention before it are refused by name, never
  // read as absolute values (a static = 1.2 would silently become mu_static = 1.2).
  const Section fr = section("friction", {"mu_static", "static", "kinetic"});
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
  const Section field = section("field", {"type", "level", "origin", "centre", "angle", "width",
                                          "half_width", "half_length", "radius", "c_mu", "dx",
                                          "dy", "nx", "ny", "levels"});
  st.problem.field = with_user_names(
      kFieldNames.names,
      [&] {
        PlanarField f = make_field(field, u);
        validate(f);
        return f;
      },
      "field.");
  const Section run = section("run", {"step", "theta", "periods", "pose", "twist", "every",
                                      "transient", "window", "steady_periods", "tolerance"});
  st.problem.options.step = u(D::time, run.required("step"));
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
  st.pose = pose_from(run.list("pose", {0, 0, 0}), "run.pose", u);
  const std::vector<double> tw = run.list("twist", {0, 0, 0});
  if (tw.size() != 3) throw InvalidParameter("run.twist", std::to_string(tw.size()) + " values", "must be [ux, uy, omega]");
  st.twist = {u(D::velocity, tw[0]), u(D::velocity, tw[1]), u(D::rate, tw[2])};
  const Section fm = section("field_map", {"x", "y", "angles", "periods"});
  st.grid_x = fm.list("x", {0.0}), st.grid_y = fm.list("y", {0.0});
  for (double& v : st.grid_x) v = u(D::length, v);
  for (double& v : st.grid_y) v = u(D::length, v);
  st.grid_angles = fm.list("angles", {0.0});
  st.field_periods = fm.integer("periods", 1, 1, 100000);
  const Section stop = section("stop", {"entries", "max_periods"});
  st.max_periods = stop.integer("max_periods", 2000, 1, 1000000);
  if (stop.has("entries")) {
    const json& e = stop.raw("entries");
    if (!e.is_array()) throw InvalidParameter("stop.entries", document_value_text(e), "must be an array of [x, y, angle]");
    for (const auto& row : e) {
      if (!row.is_array()) throw InvalidParameter("stop.entries", document_value_text(row), "must be [x, y, angle]");
      std::vector<double> v;
      for (const auto& x : row) {
        if (!x.is_number()) throw InvalidParameter("stop.entries", document_value_text(x), "must be numbers");
        v.push_back(x.get<double>());
      }
      st.entries.push_back(pose_from(v, "stop.entries", u));
    }
  } else {
    st.entries.push_back(st.pose);
  }
  with_user_names(kRunNames.names, [&] { validate(st.problem); });
  return st;
}

}  // namespace selfalign
