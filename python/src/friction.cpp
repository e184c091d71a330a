// Friction laws and maps m(x) = mu_bar(x)/mu_1 (eqs. 7-9): uniform, two-region, and a
// friction field averaged over a footprint (docs/friction-field.md).
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "record.hpp"
#include "repr.hpp"
#include "selfalign/friction/friction_law.hpp"
#include "selfalign/friction/friction_field.hpp"
#include "selfalign/friction/friction_map.hpp"

namespace selfalign::python {

namespace {

// The affine pieces as a dict of 1-D arrays, or None.
py::object pieces(const FrictionMap& f) {
  const PiecewiseAffineFriction* affine = f.piecewise_affine();
  if (!affine) return py::none();
  std::vector<double> begin, end, bound, slope;
  for (const AffinePiece& p : affine->pieces()) {
    begin.push_back(p.begin);
    end.push_back(p.end);
    bound.push_back(p.bound_at_begin);
    slope.push_back(p.slope);
  }
  py::dict d;
  d["begin"] = to_array(std::move(begin));
  d["end"] = to_array(std::move(end));
  d["bound_at_begin"] = to_array(std::move(bound));
  d["slope"] = to_array(std::move(slope));
  return d;
}


// A footprint given as a PointFootprint, a UniformFootprint, or a float width (uniform).
Footprint footprint_from(const py::handle& obj) {
  if (py::isinstance<PointFootprint>(obj)) return obj.cast<PointFootprint>();
  if (py::isinstance<UniformFootprint>(obj)) return obj.cast<UniformFootprint>();
  if (is_scalar(obj)) return UniformFootprint{scalar_value(obj, "footprint width")};
  throw py::type_error(
      "footprint: expected a PointFootprint, a UniformFootprint or a float width");
}

py::object footprint_object(const Footprint& f) {
  return std::visit([](const auto& shape) { return py::cast(shape); }, f);
}

std::string footprint_repr(const Footprint& f) {
  if (const auto* u = std::get_if<UniformFootprint>(&f))
    return Repr("UniformFootprint")("width", u->width).str();
  return "PointFootprint()";
}

// The general FrictionField from node columns of equal length.
FrictionField field_from_columns(const std::vector<double>& p, const std::vector<double>& l,
                                 const std::vector<double>& r) {
  if (l.size() != p.size() || r.size() != p.size())
    throw InvalidParameter("friction field nodes",
                           std::to_string(p.size()) + ", " + std::to_string(l.size()) + ", " +
                               std::to_string(r.size()),
                           "position, left and right must have the same length");
  std::vector<FieldNode> nodes;
  for (std::size_t i = 0; i < p.size(); ++i) nodes.push_back({p[i], l[i], r[i]});
  return FrictionField(std::move(nodes));
}

// One column of a field's nodes (a record field of FrictionField).
auto node_column(double FieldNode::*column) {
  return [column](const FrictionField& f) {
    std::vector<double> out;
    for (const FieldNode& n : f.nodes()) out.push_back(n.*column);
    return out;
  };
}

py::dict field_nodes(const FrictionField& field) {
  py::dict d;
  d["position"] = to_array(node_column(&FieldNode::position)(field));
  d["left"] = to_array(node_column(&FieldNode::left)(field));
  d["right"] = to_array(node_column(&FieldNode::right)(field));
  return d;
}

void bind_friction_field(py::module_& m) {
  py::class_<FrictionField> field_cls(m, "FrictionField", R"doc(
The table's relative friction mu(xi)/mu_1 [-] over table position xi [-], piecewise linear
with jumps (docs/friction-field.md). Its nodes (position, left, right): at `position` the
field jumps from `left` (limit from the left) to `right` (value at and after the node: the
field is right-continuous); between nodes it goes straight from one node's right to the next
node's left; before the first node it is the first left, after the last the last right.
Valid fields: >= 1 node; positions finite, |position| <= 1e50, strictly increasing; levels
finite, in [0, 1e50], > 0 somewhere. Every constructor raises InvalidParameter otherwise.
FieldFriction averages a field over the object's footprint (eq. 7).)doc");
  field_cls
      .def(py::init([](const py::object& position, const py::object& left,
                       const py::object& right) {
             return field_from_columns(to_vector(position, "position"), to_vector(left, "left"),
                                       to_vector(right, "right"));
           }),
           py::arg("position"), py::arg("left"), py::arg("right"),
           "The general form from 1-D arrays of equal length: node positions [-] and the "
           "field's left limits and right values there [-].")
      .def_static(
          "steps",
          [](const py::object& positions, const py::object& levels) {
            return FrictionField::steps(to_vector(positions, "positions"),
                                        to_vector(levels, "levels"));
          },
          py::arg("positions"), py::arg("levels"), R"doc(
Piecewise constant: levels[0] for xi < positions[0], levels[i] on [positions[i-1],
positions[i]), levels[-1] from positions[-1] on. Needs len(levels) = len(positions) + 1 (no
positions: a uniform field); positions strictly increasing. Raises InvalidParameter naming
the offending entry, e.g. 'friction field positions[1]'.)doc")
      .def_static(
          "ramps",
          [](const py::object& positions, const py::object& levels) {
            return FrictionField::ramps(to_vector(positions, "positions"),
                                        to_vector(levels, "levels"));
          },
          py::arg("positions"), py::arg("levels"), R"doc(
Piecewise linear through (positions[i], levels[i]) [-], constant outside; len(levels) =
len(positions) >= 1, positions strictly increasing. Raises InvalidParameter otherwise.)doc")
      .def_static(
          "from_csv",
          [](const py::object& path, const std::string& interpolation) {
            return FrictionField::from_csv(
                py::str(py::module_::import("os").attr("fspath")(path)), interpolation);
          },
          py::arg("path"), py::arg("interpolation") = "steps", R"doc(
Reads a CSV of rows 'position,level' [-] (one leading header line, blank lines and '#'
comments allowed; positions strictly increasing; levels finite, in [0, 1e50], > 0 somewhere).
interpolation 'steps': each level holds from its position to the next (the first also before
it); 'linear': ramps through the samples. Raises InvalidParameter naming '<path>:<line>' on
bad input, and naming 'interpolation' for another word.)doc")
      .def("nodes", &field_nodes,
           "The nodes as a dict of 1-D float64 arrays 'position', 'left', 'right' [-] (copies).")
      .def(
          "__call__",
          [](const FrictionField& f, const py::object& xi) {
            return map_elementwise<double>(xi, [&](double v) { return f(v); }, "xi");
          },
          py::arg("xi"),
          "mu(xi)/mu_1 [-] at table position(s) xi [-] (float or ndarray; right-continuous at "
          "jumps). Raises InvalidParameter for a non-finite xi.")
      .def(
          "integral",
          [](const FrictionField& f, double a, double b) {
            return f.integral(require_finite("a", a), require_finite("b", b));
          },
          py::arg("a"), py::arg("b"),
          "The integral of the field over [a, b] [-] (0 for a >= b). Raises InvalidParameter "
          "for a non-finite bound.")
      .def_property_readonly("piecewise_constant", &FrictionField::piecewise_constant,
                             "True when the field is a step function (no ramps)")
      .def_property_readonly("min_level", &FrictionField::min_level, "smallest level [-]")
      .def_property_readonly("max_level", &FrictionField::max_level, "largest level [-]")
      .def("__repr__", [](const FrictionField& f) {
        return "<FrictionField nodes=" + std::to_string(f.nodes().size()) +
               " min_level=" + format_number(f.min_level()) +
               " max_level=" + format_number(f.max_level()) + ">";
      });
  def_record(field_cls, &field_from_columns, field("position", node_column(&FieldNode::position)),
             field("left", node_column(&FieldNode::left)),
             field("right", node_column(&FieldNode::right)));

  py::class_<PointFootprint> point(m, "PointFootprint",
                                   "A point contact: the friction level is the field itself, "
                                   "m(x) = field(x).");
  point
      .def(py::init<>())
      .def("__repr__", [](const PointFootprint&) { return std::string("PointFootprint()"); });
  def_record(point);

  py::class_<UniformFootprint> uniform(m, "UniformFootprint", R"doc(
Uniform contact pressure over [x - width, x], x the object's leading edge: the friction level
is the field's average over that window (eq. 7). Validated by FieldFriction.)doc");
  uniform
      .def(py::init([](double width) { return UniformFootprint{width}; }), py::arg("width"),
           "width: the object's width w [-], in [1e-50, 1e50].")
      .def_readonly("width", &UniformFootprint::width, "w [-]")
      .def("__repr__",
           [](const UniformFootprint& u) { return Repr("UniformFootprint")("width", u.width).str(); });
  def_record(uniform, field("width", &UniformFootprint::width));

  py::class_<TwoRegionTable> table(m, "TwoRegionTable", R"doc(
The parameters of the paper's two-region table (Sect. 3.3, eq. 9): x_mu, width w, c_mu, and
b1, b2 of eq. (42). A value; the friction map is two_region_friction(x_mu, width, c_mu) (or
FieldFriction(table)). StickPositionMap and stick_position_min take it.)doc");
  table
      .def(py::init<double, double, double>(), py::arg("x_mu"), py::arg("width"), py::arg("c_mu"),
           R"doc(
x_mu:  start of the high-friction region [-], finite
width: object width w [-], > 0, with x_mu + w finite and w >= 1e-9 |x_mu|
c_mu:  friction ratio mu_2/mu_1 [-], > 1, with (c_mu - 1)/w <= 1e12
Raises InvalidParameter naming the offending argument.)doc")
      .def_property_readonly("x_mu", &TwoRegionTable::x_mu, "start of the transition [-]")
      .def_property_readonly("width", &TwoRegionTable::width, "object width w [-]")
      .def_property_readonly("c_mu", &TwoRegionTable::c_mu, "mu_2/mu_1 [-]")
      .def_property_readonly("b1", &TwoRegionTable::b1,
                             "b_1 = (c_mu - 1)/w, the stiffness of the transition (eq. 42) [-]")
      .def_property_readonly("b2", &TwoRegionTable::b2,
                             "b_2 = (c_mu - 1) x_mu / w - 1 (eq. 42) [-]")
      .def("__repr__", [](const TwoRegionTable& t) {
        return Repr("TwoRegionTable")("x_mu", t.x_mu())("width", t.width())("c_mu", t.c_mu())
            .str();
      });
  def_record(
      table,
      [](double x_mu, double width, double c_mu) { return TwoRegionTable(x_mu, width, c_mu); },
      field("x_mu", &TwoRegionTable::x_mu), field("width", &TwoRegionTable::width),
      field("c_mu", &TwoRegionTable::c_mu));

  py::class_<FieldFriction, FrictionMap> field_friction(m, "FieldFriction", R"doc(
The friction level m(x) = the table's field averaged over the object's footprint (eq. 7):
a point footprint gives m = field; a uniform footprint of width w the window average over
[x - w, x], which for FrictionField.steps([x_mu], [1, c_mu]) is the paper's two-region table
(eq. 9; its named constructor two_region_friction(x_mu, w, c_mu) also carries the table's
parameters, .two_region). Piecewise affine (so the exact solver applies) for a point footprint, or a uniform one
on a step field; a uniform footprint on a field with ramps gives a piecewise-quadratic level
(pieces() is None: time-stepping only).)doc");
  const auto make_field_friction = [](const FrictionField& field, const py::object& footprint) {
    return FieldFriction(field, footprint_from(footprint));
  };
  // Pickle state: the field, the footprint and the table it was named as (None for data).
  const auto restore_field_friction = [make_field_friction](const FrictionField& field,
                                                             const py::object& footprint,
                                                             const py::object& table) {
    if (!table.is_none()) return FieldFriction(table.cast<TwoRegionTable>());
    return make_field_friction(field, footprint);
  };
  const auto two_region = [](const FieldFriction& f) -> py::object {
    return f.two_region() ? py::cast(*f.two_region()) : py::none();
  };
  const auto footprint = [](const FieldFriction& f) { return footprint_object(f.footprint()); };
  field_friction
      .def(py::init(make_field_friction),
           py::arg("field"), py::arg("footprint"), R"doc(
field: a FrictionField; footprint: PointFootprint(), UniformFootprint(width) or a float width
(uniform). Raises InvalidParameter for a width outside [1e-50, 1e50] or below 1e-9 max
|position|, or a level that cannot be resolved (slopes above 1e12, ramps narrower than 1e-9
|position| under a point footprint); TypeError for another footprint type.)doc")
      .def(py::init<const TwoRegionTable&>(), py::arg("table"),
           "The paper's table as the field it is (two_region_friction builds the same).")
      .def_property_readonly("field", &FieldFriction::field, "the table's FrictionField")
      .def_property_readonly("footprint", footprint,
                             "the object's footprint (PointFootprint or UniformFootprint)")
      .def_property_readonly("two_region", two_region,
                             "the TwoRegionTable it was built as (two_region_friction), else None")
      .def("__repr__", [](const FieldFriction& f) {
        if (const TwoRegionTable* t = f.two_region())
          return Repr("two_region_friction")("x_mu", t->x_mu())("width", t->width())(
                     "c_mu", t->c_mu())
              .str();
        return "<FieldFriction nodes=" + std::to_string(f.field().nodes().size()) +
               " footprint=" + footprint_repr(f.footprint()) + ">";
      });
  def_record(field_friction, restore_field_friction, field("field", &FieldFriction::field),
             field("footprint", footprint), field("two_region", two_region));

  m.def("two_region_friction", &two_region_friction, py::arg("x_mu"), py::arg("width"),
        py::arg("c_mu"), R"doc(
The paper's two-region table (Sect. 3.3) as a FieldFriction: mu_1 for x < x_mu,
mu_2 = c_mu mu_1 beyond x_mu + w, in between the width-averaged transition of eqs. (7)-(9):
  m(x) = 1 + (c_mu - 1)/w * z,   z = min(max(x - x_mu, 0), w)
x the object's leading edge [-], w its dimensionless width. Its .two_region is the
TwoRegionTable(x_mu, width, c_mu). Raises InvalidParameter as TwoRegionTable does.)doc");
  m.def(
      "as_two_region_table",
      [](const FrictionMap& friction) -> py::object {
        const std::optional<TwoRegionTable> t = as_two_region_table(friction);
        return t ? py::cast(*t) : py::none();
      },
      py::arg("friction"), R"doc(
The paper's table that `friction` is (a TwoRegionTable), where it is one: a map built by
two_region_friction, or a field of one step from level 1 to c_mu > 1 under a uniform footprint
(e.g. read from a file: eq. 7 of it is eq. 9); None otherwise.)doc");
}

}  // namespace

void bind_friction(py::module_& m) {
  auto law = py::class_<FrictionLaw>(m, "FrictionLaw", R"doc(
The contact's friction law: Coulomb friction with a static coefficient at least the kinetic
one, optionally with direction-dependent kinetic coefficients (sawtooth or textured surfaces),
and optionally speed-dependent: a Stribeck decay from static to kinetic,
mu(v) = k + (s - k) exp(-(|v|/v_s)^delta), and a viscous force -c x' (with_stribeck,
with_viscous). A speed-dependent law has no closed form: steady_state, simulate, floquet and
the sweeps then use the slip integrator (Method.integrator: exact sticks, Dormand-Prince slips
with event location).
Dimensionless: every coefficient is relative to mu_1, the forward kinetic coefficient of the
low-friction region, so FrictionLaw() = (1, 1, 1) is the paper's law. While stuck the
object is held as long as |y''| <= static m(x); while slipping in direction sigma the force is
-kinetic_sigma m(x) sigma.)doc")
      .def(py::init<>())
      .def(py::init<double, double>(), py::arg("static"), py::arg("kinetic"),
           "Symmetric law: 0 < kinetic <= static. Raises InvalidParameter naming both otherwise.")
      .def(py::init<double, double, double>(), py::arg("static"), py::arg("kinetic_forward"),
           py::arg("kinetic_backward"),
           "Direction-dependent kinetic coefficients: 0 < kinetic_forward, kinetic_backward <= "
           "static.")
      .def_property_readonly("static", &FrictionLaw::static_coefficient, "s [-]")
      .def_property_readonly("kinetic_forward", &FrictionLaw::kinetic_forward, "k_+ [-]")
      .def_property_readonly("kinetic_backward", &FrictionLaw::kinetic_backward, "k_- [-]")
      .def("with_stribeck", &FrictionLaw::with_stribeck, py::arg("stribeck_velocity"),
           py::arg("exponent") = 1.0,
           "This law with a Stribeck decay: stribeck_velocity v_s [-] > 0, exponent delta in "
           "(0, 100]. Raises InvalidParameter naming the parameter otherwise.")
      .def("with_viscous", &FrictionLaw::with_viscous, py::arg("viscous"),
           "This law with a viscous force -c x': viscous c [-] >= 0. Raises InvalidParameter "
           "naming 'viscous' otherwise.")
      .def_property_readonly("stribeck_velocity", &FrictionLaw::stribeck_velocity,
                             "v_s [-]; 0 when the law has no Stribeck decay")
      .def_property_readonly("stribeck_exponent", &FrictionLaw::stribeck_exponent, "delta [-]")
      .def_property_readonly("viscous", &FrictionLaw::viscous, "c [-]; 0 when none")
      .def_property_readonly("velocity_dependent", &FrictionLaw::velocity_dependent,
                             "True when a Stribeck decay or viscous term was given")
      .def(
          "kinetic",
          [](const FrictionLaw& f, int direction, double speed) {
            return f.kinetic(direction, speed);
          },
          py::arg("direction"), py::arg("speed"),
          "mu_sigma(speed) [-] for slip direction sigma (> 0 forward, < 0 backward)")
      .def("__repr__", [](const FrictionLaw& f) {
        Repr r("FrictionLaw");
        r("static", f.static_coefficient())("kinetic_forward", f.kinetic_forward())(
            "kinetic_backward", f.kinetic_backward());
        if (f.stribeck_velocity() > 0)
          r("stribeck_velocity", f.stribeck_velocity())("stribeck_exponent",
                                                        f.stribeck_exponent());
        if (f.viscous() > 0) r("viscous", f.viscous());
        return r.str();
      });
  def_record(
      law,
      [](double s, double forward, double backward, double stribeck, double exponent,
         double viscous) {
        FrictionLaw f(s, forward, backward);
        if (stribeck > 0) f = f.with_stribeck(stribeck, exponent);
        return viscous > 0 ? f.with_viscous(viscous) : f;
      },
      field("static", &FrictionLaw::static_coefficient),
      field("kinetic_forward", &FrictionLaw::kinetic_forward),
      field("kinetic_backward", &FrictionLaw::kinetic_backward),
      field("stribeck_velocity", &FrictionLaw::stribeck_velocity),
      field("stribeck_exponent", &FrictionLaw::stribeck_exponent),
      field("viscous", &FrictionLaw::viscous));

  py::class_<FrictionMap>(m, "FrictionMap", R"doc(
A friction law m(x) = mu_bar(x)/mu_1 >= 0 [-] (eqs. 7-9): in the dimensionless model
(Sect. 3.2) the friction force lies in -m(x) Sign(x'); m = 1 on the low-friction table.
Abstract: use UniformFriction or FieldFriction (the paper's table: two_region_friction).)doc")
      .def(
          "bound",
          [](const FrictionMap& f, const py::object& x) {
            return map_elementwise<double>(x, [&](double v) { return f.bound(v); }, "x");
          },
          py::arg("x"),
          "Friction bound m(x) [-] at dimensionless position(s) x [-] (float or ndarray).")
      .def("pieces", &pieces, R"doc(
The map as affine pieces m(x) = bound_at_begin + slope (x - begin) on [begin, end), sorted,
covering the real line (the form the exact solver integrates), as a dict of 1-D float64
arrays 'begin', 'end', 'bound_at_begin', 'slope'; None when the map is not piecewise affine.)doc");

  py::class_<UniformFriction, FrictionMap> uniform(m, "UniformFriction",
                                                  "Uniform Coulomb friction: m(x) = level (1 on "
                                                  "the paper's low-friction table).");
  uniform
      .def(py::init<double>(), py::arg("level") = 1.0,
           "level: m = mu/mu_1 [-], finite and > 0. Raises InvalidParameter otherwise.")
      .def_property_readonly("level", &UniformFriction::level, "m [-]")
      .def("__repr__", [](const UniformFriction& f) {
        return Repr("UniformFriction")("level", f.level()).str();
      });
  def_record(uniform, [](double level) { return UniformFriction(level); },
             field("level", &UniformFriction::level));

  bind_friction_field(m);
}

}  // namespace selfalign::python
