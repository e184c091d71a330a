// Planar motion of a rigid part on a contact patch (issue 13): contact patches, friction-level
// fields over the table plane, the Moreau stepper of planar_rigid.hpp recorded as NumPy columns,
// and the analyses of planar_analysis.hpp (steady drift, drift field, stopping).
//
// The library's PlanarTableMotion borrows raw TableProfile pointers, so it is never bound: each
// function takes the profiles as arguments (the call keeps the Python objects, hence the
// profiles, alive while it runs without the GIL) and builds the motion itself.
#include <pybind11/stl.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "progress.hpp"
#include "selfalign/planar/planar_steady_state.hpp"
#include "record.hpp"
#include "repr.hpp"
#include "selfalign/analysis/sweep.hpp"  // worker_threads
#include "selfalign/error.hpp"
#include "selfalign/planar/planar_analysis.hpp"
#include "selfalign/planar/planar_run.hpp"
#include "selfalign/simulate/simulate.hpp"  // kMaxRecordedSamples, kMaxTimeSteps

namespace selfalign::python {

namespace {

// A list of numbers as Python source: [1, 0.5, ...].
std::string list_source(const std::vector<double>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i)
    out += (i ? ", " : "") + number_source(values[i]);
  return out + "]";
}

// A field struct checked as the library checks it (InvalidParameter naming the parameter).
template <class F>
F checked_field(F f) {
  validate(PlanarField{f});
  return f;
}

// ---- contact patches ---------------------------------------------------------------------

void bind_patches(py::module_& m) {
  py::class_<ContactPoint> point(m, "ContactPoint", R"doc(
One contact point of a part's patch: its position (x, y) in the part's body frame relative to
the centre of mass [-] and its load fraction `load` [-] (its share of the normal load m g).
The points of a patch carry loads summing to 1 with their load centre at the origin.)doc");
  point
      .def(py::init([](double x, double y, double load) { return ContactPoint{x, y, load}; }),
           py::arg("x") = 0.0, py::arg("y") = 0.0, py::arg("load") = 1.0)
      .def_readwrite("x", &ContactPoint::x, "body-frame x relative to the centre of mass [-]")
      .def_readwrite("y", &ContactPoint::y, "body-frame y relative to the centre of mass [-]")
      .def_readwrite("load", &ContactPoint::load, "load fraction w [-] (share of m g), >= 0")
      .def("__repr__", [](const ContactPoint& p) {
        return Repr("ContactPoint")("x", p.x)("y", p.y)("load", p.load).str();
      });
  def_record(point, field("x", &ContactPoint::x), field("y", &ContactPoint::y),
             field("load", &ContactPoint::load));

  m.def("point_patch", &point_patch,
        "A single contact point at the centre of mass with load 1 (a point contact): a list of "
        "one ContactPoint.");
  m.def("disc_patch", &disc_patch, py::arg("radius"), py::arg("rings"), py::arg("sectors"),
        R"doc(
Uniform pressure over a disc of radius `radius` [-] (finite, > 0) as `rings` equal-area annuli
of `sectors` equal sectors each (both in [1, 10000]), one ContactPoint per cell at its centroid
with load 1/(rings sectors). Their polar moment is r^2/2 to O(1/rings^2). Raises
InvalidParameter naming the parameter out of range.)doc");
  m.def("rectangle_patch", &rectangle_patch, py::arg("length"), py::arg("width"), py::arg("nx"),
        py::arg("ny"), R"doc(
Uniform pressure over a length x width rectangle [-] centred on the origin (length along the
body x axis), nx by ny equal cells, one ContactPoint per cell centre with load 1/(nx ny).)doc");
  m.def(
      "polygon_patch",
      [](const py::object& xs, const py::object& ys, int subdivisions) {
        return polygon_patch(to_vector(xs, "xs"), to_vector(ys, "ys"), subdivisions);
      },
      py::arg("xs"), py::arg("ys"), py::arg("subdivisions") = 1, R"doc(
Uniform pressure over a simple polygon with vertices (xs[i], ys[i]) in order (either
orientation): ear-clipping triangulation, each triangle split into subdivisions^2 congruent
sub-triangles (subdivisions in [1, 100]) represented by their centroids, weighted by area, and
shifted so that the area centroid is the origin. Raises InvalidParameter naming "polygon" for
fewer than 3 vertices, a self-intersection (naming the two edges) or zero area.)doc");
  m.def(
      "weighted_points_patch",
      [](const py::object& xs, const py::object& ys, const py::object& loads) {
        return weighted_points_patch(to_vector(xs, "xs"), to_vector(ys, "ys"),
                                     to_vector(loads, "loads"));
      },
      py::arg("xs"), py::arg("ys"), py::arg("loads"), R"doc(
User contact points (xs[i], ys[i]) [-] with load fractions loads[i]: finite positions,
fractions >= 0 summing to 1 (to 1e-9) whose load centre sum w_i p_i is the origin (the centre
of mass; to 1e-9 of the patch size). Points with zero load are dropped. Raises
InvalidParameter naming "load_fractions" or "points" otherwise.)doc");
  m.def(
      "polar_moment",
      [](const ContactPatch& patch) {
        validate(patch);
        return polar_moment(patch);
      },
      py::arg("patch"),
      "sum w_i |p_i|^2 [-]: the patch's polar moment per unit load (r^2/2 for a uniform disc "
      "of radius r). Raises InvalidParameter for an invalid patch.");
  m.def(
      "patch_radius",
      [](const ContactPatch& patch) {
        validate(patch);
        return patch_radius(patch);
      },
      py::arg("patch"),
      "The largest distance |p_i| of a contact point from the centre of mass [-]. Raises "
      "InvalidParameter for an invalid patch.");

  py::class_<RigidPart> part(m, "RigidPart", R"doc(
A rigid part for planar motion: its moment of inertia about the centre of mass per unit mass
j = I/(m L^2) [-] (finite, > 0; r^2/2 for a uniform disc of radius r) and its contact patch
(a list of ContactPoint, loads summing to 1 with their centre at the origin). Checked on
construction (InvalidParameter naming "inertia" or the patch's parameter); immutable.)doc");
  part.def(py::init([](double inertia, std::optional<ContactPatch> patch) {
             RigidPart p{inertia, patch ? std::move(*patch) : point_patch()};
             validate(p);
             return p;
           }),
           py::arg("inertia") = RigidPart{}.inertia, py::arg("patch") = py::none(),
           "patch None: a point contact at the centre of mass (point_patch()).")
      .def_readonly("inertia", &RigidPart::inertia, "j = I/(m L^2) [-], > 0")
      .def_property_readonly(
          "patch", [](const RigidPart& p) { return p.patch; },
          "the contact points (a list of ContactPoint, a copy)")
      .def("__repr__", [](const RigidPart& p) {
        std::string points = "[";
        for (std::size_t i = 0; i < p.patch.size(); ++i)
          points += (i ? ", " : "") + Repr("ContactPoint")("x", p.patch[i].x)("y", p.patch[i].y)(
                                          "load", p.patch[i].load)
                                          .str();
        return Repr("RigidPart")("inertia", p.inertia).raw("patch", points + "]").str();
      });
  def_record(
      part,
      [](double inertia, ContactPatch patch) {
        RigidPart p{inertia, std::move(patch)};
        validate(p);
        return p;
      },
      field("inertia", &RigidPart::inertia), field("patch", &RigidPart::patch));
}

// ---- fields ------------------------------------------------------------------------------

void bind_fields(py::module_& m) {
  py::class_<UniformPlanarField> uniform(m, "UniformPlanarField",
                                         "The friction level m(x, y) = level everywhere [-].");
  uniform
      .def(py::init([](double level) { return checked_field(UniformPlanarField{level}); }),
           py::arg("level") = UniformPlanarField{}.level, "level finite, > 0.")
      .def_readonly("level", &UniformPlanarField::level, "m [-]")
      .def("__repr__", [](const UniformPlanarField& f) {
        return Repr("UniformPlanarField")("level", f.level).str();
      });
  def_record(
      uniform, [](double level) { return checked_field(UniformPlanarField{level}); },
      field("level", &UniformPlanarField::level));

  const HalfPlaneStepField h;
  py::class_<HalfPlaneStepField> half(m, "HalfPlaneStepField", R"doc(
The two-region table along the unit normal n = (cos angle, sin angle): with
d = n . (p - origin), m = 1 for d <= 0, c_mu for d >= width, linear in between (eq. 7 along any
direction).)doc");
  half.def(py::init([](double origin_x, double origin_y, double angle, double width,
                       double c_mu) {
             return checked_field(HalfPlaneStepField{origin_x, origin_y, angle, width, c_mu});
           }),
           py::kw_only(), py::arg("origin_x") = h.origin_x, py::arg("origin_y") = h.origin_y,
           py::arg("angle") = h.angle, py::arg("width") = h.width, py::arg("c_mu") = h.c_mu,
           "Raises InvalidParameter naming the parameter out of range (width > 0, c_mu >= 1).")
      .def_readonly("origin_x", &HalfPlaneStepField::origin_x,
                    "x of a point on the boundary where the rise starts [-]")
      .def_readonly("origin_y", &HalfPlaneStepField::origin_y,
                    "y of a point on the boundary where the rise starts [-]")
      .def_readonly("angle", &HalfPlaneStepField::angle, "direction of the rise [rad]")
      .def_readonly("width", &HalfPlaneStepField::width, "transition band [-], > 0")
      .def_readonly("c_mu", &HalfPlaneStepField::c_mu, "mu_2/mu_1 [-], >= 1")
      .def("__repr__", [](const HalfPlaneStepField& f) {
        return Repr("HalfPlaneStepField")("origin_x", f.origin_x)("origin_y", f.origin_y)(
                   "angle", f.angle)("width", f.width)("c_mu", f.c_mu)
            .str();
      });
  def_record(
      half,
      [](double ox, double oy, double angle, double width, double c_mu) {
        return checked_field(HalfPlaneStepField{ox, oy, angle, width, c_mu});
      },
      field("origin_x", &HalfPlaneStepField::origin_x),
      field("origin_y", &HalfPlaneStepField::origin_y), field("angle", &HalfPlaneStepField::angle),
      field("width", &HalfPlaneStepField::width), field("c_mu", &HalfPlaneStepField::c_mu));

  const StripField s;
  py::class_<StripField> strip(m, "StripField", R"doc(
A rough strip: the points with |n . (p - origin)| <= half_width, n = (cos angle, sin angle)
(the strip runs across n); m rises linearly from 1 at its edge to c_mu at depth `width`
inside it (depth = half_width - |n . (p - origin)|).)doc");
  strip
      .def(py::init([](double origin_x, double origin_y, double angle, double half_width,
                       double width, double c_mu) {
             return checked_field(StripField{origin_x, origin_y, angle, half_width, width, c_mu});
           }),
           py::kw_only(), py::arg("origin_x") = s.origin_x, py::arg("origin_y") = s.origin_y,
           py::arg("angle") = s.angle, py::arg("half_width") = s.half_width,
           py::arg("width") = s.width, py::arg("c_mu") = s.c_mu,
           "Raises InvalidParameter naming the parameter out of range.")
      .def_readonly("origin_x", &StripField::origin_x, "x of a point on the centre line [-]")
      .def_readonly("origin_y", &StripField::origin_y, "y of a point on the centre line [-]")
      .def_readonly("angle", &StripField::angle, "direction across the strip [rad]")
      .def_readonly("half_width", &StripField::half_width, "half the strip's width [-], > 0")
      .def_readonly("width", &StripField::width, "transition band [-], > 0")
      .def_readonly("c_mu", &StripField::c_mu, "mu_2/mu_1 [-], >= 1")
      .def("__repr__", [](const StripField& f) {
        return Repr("StripField")("origin_x", f.origin_x)("origin_y", f.origin_y)(
                   "angle", f.angle)("half_width", f.half_width)("width", f.width)("c_mu",
                                                                                    f.c_mu)
            .str();
      });
  def_record(
      strip,
      [](double ox, double oy, double angle, double half_width, double width, double c_mu) {
        return checked_field(StripField{ox, oy, angle, half_width, width, c_mu});
      },
      field("origin_x", &StripField::origin_x), field("origin_y", &StripField::origin_y),
      field("angle", &StripField::angle), field("half_width", &StripField::half_width),
      field("width", &StripField::width), field("c_mu", &StripField::c_mu));

  const RectangularPocketField r;
  py::class_<RectangularPocketField> rect(m, "RectangularPocketField", R"doc(
A rough rectangular pocket centred at (centre_x, centre_y) with half sides half_length (along
the direction `angle`) and half_width; m rises from 1 at its edge to c_mu at depth `width`
inside (depth = min(a - |xi|, b - |eta|) in the pocket's axes).)doc");
  rect.def(py::init([](double centre_x, double centre_y, double angle, double half_length,
                       double half_width, double width, double c_mu) {
             return checked_field(RectangularPocketField{centre_x, centre_y, angle, half_length,
                                                         half_width, width, c_mu});
           }),
           py::kw_only(), py::arg("centre_x") = r.centre_x, py::arg("centre_y") = r.centre_y,
           py::arg("angle") = r.angle, py::arg("half_length") = r.half_length,
           py::arg("half_width") = r.half_width, py::arg("width") = r.width,
           py::arg("c_mu") = r.c_mu, "Raises InvalidParameter naming the parameter out of range.")
      .def_readonly("centre_x", &RectangularPocketField::centre_x, "x of the centre [-]")
      .def_readonly("centre_y", &RectangularPocketField::centre_y, "y of the centre [-]")
      .def_readonly("angle", &RectangularPocketField::angle,
                    "direction of the pocket's long axis [rad]")
      .def_readonly("half_length", &RectangularPocketField::half_length,
                    "half side a along `angle` [-], > 0")
      .def_readonly("half_width", &RectangularPocketField::half_width,
                    "half side b across `angle` [-], > 0")
      .def_readonly("width", &RectangularPocketField::width, "transition band [-], > 0")
      .def_readonly("c_mu", &RectangularPocketField::c_mu, "mu_2/mu_1 [-], >= 1")
      .def("__repr__", [](const RectangularPocketField& f) {
        return Repr("RectangularPocketField")("centre_x", f.centre_x)("centre_y", f.centre_y)(
                   "angle", f.angle)("half_length", f.half_length)("half_width", f.half_width)(
                   "width", f.width)("c_mu", f.c_mu)
            .str();
      });
  def_record(
      rect,
      [](double cx, double cy, double angle, double a, double b, double width, double c_mu) {
        return checked_field(RectangularPocketField{cx, cy, angle, a, b, width, c_mu});
      },
      field("centre_x", &RectangularPocketField::centre_x),
      field("centre_y", &RectangularPocketField::centre_y),
      field("angle", &RectangularPocketField::angle),
      field("half_length", &RectangularPocketField::half_length),
      field("half_width", &RectangularPocketField::half_width),
      field("width", &RectangularPocketField::width), field("c_mu", &RectangularPocketField::c_mu));

  const CircularPocketField c;
  py::class_<CircularPocketField> circle(m, "CircularPocketField", R"doc(
A rough circular pocket of radius `radius` about (centre_x, centre_y); m rises from 1 at its
edge to c_mu at depth `width` inside (depth = radius - |p - centre|).)doc");
  circle
      .def(py::init([](double centre_x, double centre_y, double radius, double width,
                       double c_mu) {
             return checked_field(CircularPocketField{centre_x, centre_y, radius, width, c_mu});
           }),
           py::kw_only(), py::arg("centre_x") = c.centre_x, py::arg("centre_y") = c.centre_y,
           py::arg("radius") = c.radius, py::arg("width") = c.width, py::arg("c_mu") = c.c_mu,
           "Raises InvalidParameter naming the parameter out of range.")
      .def_readonly("centre_x", &CircularPocketField::centre_x, "x of the centre [-]")
      .def_readonly("centre_y", &CircularPocketField::centre_y, "y of the centre [-]")
      .def_readonly("radius", &CircularPocketField::radius, "[-], > 0")
      .def_readonly("width", &CircularPocketField::width, "transition band [-], > 0")
      .def_readonly("c_mu", &CircularPocketField::c_mu, "mu_2/mu_1 [-], >= 1")
      .def("__repr__", [](const CircularPocketField& f) {
        return Repr("CircularPocketField")("centre_x", f.centre_x)("centre_y", f.centre_y)(
                   "radius", f.radius)("width", f.width)("c_mu", f.c_mu)
            .str();
      });
  def_record(
      circle,
      [](double cx, double cy, double radius, double width, double c_mu) {
        return checked_field(CircularPocketField{cx, cy, radius, width, c_mu});
      },
      field("centre_x", &CircularPocketField::centre_x),
      field("centre_y", &CircularPocketField::centre_y),
      field("radius", &CircularPocketField::radius), field("width", &CircularPocketField::width),
      field("c_mu", &CircularPocketField::c_mu));

  const GridField g;
  const auto make_grid = [](double origin_x, double origin_y, double angle, double dx, double dy,
                            int nx, int ny, std::vector<double> levels) {
    return checked_field(GridField{origin_x, origin_y, angle, dx, dy, nx, ny, std::move(levels)});
  };
  py::class_<GridField> grid(m, "GridField", R"doc(
Friction levels sampled on a regular grid: node (i, j) at origin + i dx e_a + j dy e_b
(e_a = (cos angle, sin angle), e_b its normal) has level levels[j nx + i]; bilinear inside, the
nearest edge value outside. Levels finite and > 0, nx, ny >= 2, nx ny levels.)doc");
  grid.def(py::init([make_grid](double origin_x, double origin_y, double angle, double dx,
                                double dy, int nx, int ny, const py::object& levels) {
             return make_grid(origin_x, origin_y, angle, dx, dy, nx, ny,
                              to_vector(levels, "levels"));
           }),
           py::kw_only(), py::arg("origin_x") = g.origin_x, py::arg("origin_y") = g.origin_y,
           py::arg("angle") = g.angle, py::arg("dx") = g.dx, py::arg("dy") = g.dy,
           py::arg("nx") = g.nx, py::arg("ny") = g.ny,
           py::arg("levels") = to_array(std::vector(g.levels)),
           "levels: a 1-D array-like of nx ny values, row j (y index) after row j - 1. Raises "
           "InvalidParameter naming \"levels\" for a NaN or non-positive level or a count that "
           "does not match nx ny.")
      .def_readonly("origin_x", &GridField::origin_x, "x of node (0, 0) [-]")
      .def_readonly("origin_y", &GridField::origin_y, "y of node (0, 0) [-]")
      .def_readonly("angle", &GridField::angle, "direction of the grid's first axis [rad]")
      .def_readonly("dx", &GridField::dx, "spacing along the first axis [-], > 0")
      .def_readonly("dy", &GridField::dy, "spacing along the second axis [-], > 0")
      .def_readonly("nx", &GridField::nx, "nodes along the first axis, >= 2")
      .def_readonly("ny", &GridField::ny, "nodes along the second axis, >= 2")
      .def_property_readonly(
          "levels", [](const GridField& f) { return to_array(std::vector(f.levels)); },
          "the nx ny levels [-] (a copy, float64, index j nx + i)")
      .def("__repr__", [](const GridField& f) {
        return Repr("GridField")("origin_x", f.origin_x)("origin_y", f.origin_y)(
                   "angle", f.angle)("dx", f.dx)("dy", f.dy)("nx", f.nx)("ny", f.ny)
            .raw("levels", list_source(f.levels))
            .str();
      });
  def_record(grid, make_grid, field("origin_x", &GridField::origin_x),
             field("origin_y", &GridField::origin_y), field("angle", &GridField::angle),
             field("dx", &GridField::dx), field("dy", &GridField::dy), field("nx", &GridField::nx),
             field("ny", &GridField::ny), field("levels", &GridField::levels));

  const AxisField a{FrictionField::steps({}, {1.0})};
  const auto make_axis = [](const FrictionField& field, double origin_x, double origin_y,
                            double angle) {
    return checked_field(AxisField{field, origin_x, origin_y, angle});
  };
  py::class_<AxisField> axis(m, "AxisField", R"doc(
The 1-D table's friction field (a FrictionField: steps, ramps, FrictionField.from_csv) laid
along the direction n = (cos angle, sin angle) from (origin_x, origin_y), constant across it:
m(x, y) = field(n . (p - origin)). The 1-D field is the planar family's one-axis case: a point
contact at angle 0 and origin 0 reads field(x), and a contact patch averages the field over its
points as eq. (7)'s footprint does in 1-D. Levels must be in (0, 1e6] everywhere.)doc");
  axis.def(py::init(make_axis), py::arg("field"), py::kw_only(), py::arg("origin_x") = a.origin_x,
           py::arg("origin_y") = a.origin_y, py::arg("angle") = a.angle,
           "Raises InvalidParameter naming \"levels\" for a level of 0 (or above 1e6) somewhere, "
           "or the origin / angle out of range.")
      .def_readonly("field", &AxisField::field, "the 1-D FrictionField along the axis")
      .def_readonly("origin_x", &AxisField::origin_x, "x where the field's position 0 lies [-]")
      .def_readonly("origin_y", &AxisField::origin_y, "y where the field's position 0 lies [-]")
      .def_readonly("angle", &AxisField::angle, "direction of increasing position [rad]")
      .def("__repr__", [](const AxisField& f) {
        return "<AxisField nodes=" + std::to_string(f.field.nodes().size()) +
               " origin_x=" + format_number(f.origin_x) + " origin_y=" +
               format_number(f.origin_y) + " angle=" + format_number(f.angle) + ">";
      });
  def_record(axis, make_axis, field("field", &AxisField::field),
             field("origin_x", &AxisField::origin_x), field("origin_y", &AxisField::origin_y),
             field("angle", &AxisField::angle));

  m.def(
      "planar_level",
      [](const PlanarField& f, const py::object& x, const py::object& y) -> py::object {
        validate(f);
        if (is_scalar(x) && is_scalar(y)) {
          const double xv = require_finite("x", scalar_value(x, "x"));
          const double yv = require_finite("y", scalar_value(y, "y"));
          return py::float_(planar_level(f, xv, yv));
        }
        const py::module_ numpy = py::module_::import("numpy");
        const py::tuple both =
            numpy.attr("broadcast_arrays")(float_array(x, "x"), float_array(y, "y"));
        const auto xa = DoubleArray::ensure(both[0]), ya = DoubleArray::ensure(both[1]);
        py::array_t<double> out(std::vector<py::ssize_t>(xa.shape(), xa.shape() + xa.ndim()));
        double* dst = out.mutable_data();
        for (py::ssize_t i = 0; i < xa.size(); ++i)
          dst[i] = planar_level(f, require_finite("x", xa.data()[i]),
                                require_finite("y", ya.data()[i]));
        return out;
      },
      py::arg("field"), py::arg("x"), py::arg("y"), R"doc(
The friction level m(x, y) [-] of a planar field at table coordinates (x, y): a float for
floats, else a float64 array of the broadcast shape of x and y. Non-finite coordinates raise
InvalidParameter naming "x" or "y".)doc");
  m.def(
      "rotated_field",
      [](const PlanarField& f, double angle) {
        validate(f);
        return rotated_field(f, require_finite("angle", angle));
      },
      py::arg("field"), py::arg("angle"),
      "The field rotated by `angle` [rad] about the origin (same kind), for frame-invariance "
      "checks: a setup rotated as a whole moves the same way, rotated.");
}

// ---- results ---------------------------------------------------------------------------------

void bind_values(py::module_& m) {
  bind_int_enum<PatchMode>(m, "PatchMode", R"doc(
How one step of the rigid-part stepper ended (an enum.IntEnum; the `mode` column of
simulate_planar):
  stick = 0  zero relative twist (the part moves with the table)
  pivot = 1  zero slip at one contact point, the others slipping (a rotation about it)
  slip  = 2  every contact point slips)doc",
                           {{"stick", PatchMode::stick},
                            {"pivot", PatchMode::pivot},
                            {"slip", PatchMode::slip}});

  py::class_<PlanarPose> pose(m, "PlanarPose", R"doc(
A pose of the part on the table: its centre of mass (x, y) in table coordinates [-] and its
angle relative to the table [rad].)doc");
  pose.def(py::init([](double x, double y, double angle) { return PlanarPose{x, y, angle}; }),
           py::arg("x") = 0.0, py::arg("y") = 0.0, py::arg("angle") = 0.0)
      .def_readwrite("x", &PlanarPose::x, "centre of mass, table x [-]")
      .def_readwrite("y", &PlanarPose::y, "centre of mass, table y [-]")
      .def_readwrite("angle", &PlanarPose::angle, "angle relative to the table [rad]")
      .def("__repr__", [](const PlanarPose& p) {
        return Repr("PlanarPose")("x", p.x)("y", p.y)("angle", p.angle).str();
      });
  def_record(pose, field("x", &PlanarPose::x), field("y", &PlanarPose::y),
             field("angle", &PlanarPose::angle));

  py::class_<PlanarTwist> twist(m, "PlanarTwist", R"doc(
A twist of the part relative to the table, in table axes: the centre of mass's velocity
(ux, uy) [-] and the spin omega [-] (rad per unit time).)doc");
  twist
      .def(py::init([](double ux, double uy, double omega) { return PlanarTwist{ux, uy, omega}; }),
           py::arg("ux") = 0.0, py::arg("uy") = 0.0, py::arg("omega") = 0.0)
      .def_readwrite("ux", &PlanarTwist::ux, "relative velocity along the table's x axis [-]")
      .def_readwrite("uy", &PlanarTwist::uy, "relative velocity along the table's y axis [-]")
      .def_readwrite("omega", &PlanarTwist::omega, "relative spin [-]")
      .def("__repr__", [](const PlanarTwist& t) {
        return Repr("PlanarTwist")("ux", t.ux)("uy", t.uy)("omega", t.omega).str();
      });
  def_record(twist, field("ux", &PlanarTwist::ux), field("uy", &PlanarTwist::uy),
             field("omega", &PlanarTwist::omega));

  py::class_<PlanarCensus> census(m, "PlanarCensus",
                                  "Steps of each kind (PatchMode) over a stretch of a run.");
  census
      .def(py::init([](long long stick, long long pivot, long long slip) {
             return PlanarCensus{stick, pivot, slip};
           }),
           py::arg("stick") = 0, py::arg("pivot") = 0, py::arg("slip") = 0)
      .def_readonly("stick", &PlanarCensus::stick, "steps ending in stick")
      .def_readonly("pivot", &PlanarCensus::pivot, "steps ending in a pivot")
      .def_readonly("slip", &PlanarCensus::slip, "steps ending in slip")
      .def("total", &PlanarCensus::total, "stick + pivot + slip")
      .def("__repr__", [](const PlanarCensus& c) {
        return Repr("PlanarCensus")("stick", c.stick)("pivot", c.pivot)("slip", c.slip).str();
      });
  def_record(census, field("stick", &PlanarCensus::stick), field("pivot", &PlanarCensus::pivot),
             field("slip", &PlanarCensus::slip));

  using SR = PlanarSteadyResult;
  py::class_<SR> steady(m, "PlanarSteadyResult", "The outcome of planar_steady().");
  steady
      .def_readonly("drift_x", &SR::drift_x,
                    "mean velocity of the centre of mass over the last window, table x [-]")
      .def_readonly("drift_y", &SR::drift_y,
                    "mean velocity of the centre of mass over the last window, table y [-]")
      .def_readonly("rotation_rate", &SR::rotation_rate,
                    "mean spin relative to the table over the last window [-]")
      .def_readonly("change", &SR::change,
                    "|drift(last window) - drift(window before)| [-]: what is left of the "
                    "transient")
      .def_readonly("census", &SR::census, "PlanarCensus of the last window")
      .def_readonly("end_pose", &SR::end_pose, "PlanarPose at the end of the run")
      .def("__repr__", [](const SR& r) {
        return Repr("PlanarSteadyResult")("drift_x", r.drift_x)("drift_y", r.drift_y)(
                   "rotation_rate", r.rotation_rate)("change", r.change)
            .str();
      });
  def_record(steady, field("drift_x", &SR::drift_x), field("drift_y", &SR::drift_y),
             field("rotation_rate", &SR::rotation_rate), field("change", &SR::change),
             field("census", &SR::census), field("end_pose", &SR::end_pose));

  using SS = PlanarSteadyState;
  py::class_<SS> fixed(m, "PlanarSteadyState",
                       "The outcome of planar_steady_state(): the fixed point of the planar "
                       "period map (planar/planar_steady_state.hpp).");
  fixed
      .def_readonly("converged", &SS::converged,
                    "False: max_periods reached, or the level under the part changing")
      .def_readonly("level_changed", &SS::level_changed,
                    "the friction level under the part changed during the run (it entered "
                    "another region): a drift found is the steady state where it ended")
      .def_readonly("method", &SS::method, "Method.exact (point solver) or Method.time_stepping")
      .def_readonly("periods", &SS::periods, "periods simulated")
      .def_readonly("drift_x", &SS::drift_x, "Δx/Δt over the steady period, table x [-]; NaN "
                    "unless converged")
      .def_readonly("drift_y", &SS::drift_y, "Δy/Δt [-]; NaN unless converged")
      .def_readonly("rotation_rate", &SS::rotation_rate, "Δangle/Δt [-]; NaN unless converged")
      .def_readonly("twist_0s", &SS::twist_0s, "PlanarTwist at phase 0 of the last period [-]")
      .def_readonly("residual", &SS::residual, "|z_n - z_(n-1)| [-] (inf before two periods)")
      .def_readonly("error", &SS::error, "estimate of |z - z*| [-]; inf without a contraction")
      .def_readonly("census", &SS::census, "PlanarCensus of the last period (Moreau)")
      .def_readonly("end_pose", &SS::end_pose, "PlanarPose at the end of the run")
      .def_readonly("level_min", &SS::level_min, "least level under the part over the run [-]")
      .def_readonly("level_max", &SS::level_max, "largest level under the part over the run [-]")
      .def("__repr__", [](const SS& r) {
        return Repr("PlanarSteadyState")("converged", r.converged)(
                   "level_changed", r.level_changed)("drift_x", r.drift_x)("drift_y", r.drift_y)(
                   "rotation_rate", r.rotation_rate)("periods", r.periods)
            .str();
      });
  def_record(fixed, field("converged", &SS::converged),
             field("level_changed", &SS::level_changed), field("method", &SS::method),
             field("periods", &SS::periods), field("drift_x", &SS::drift_x),
             field("drift_y", &SS::drift_y), field("rotation_rate", &SS::rotation_rate),
             field("twist_0s", &SS::twist_0s), field("residual", &SS::residual),
             field("error", &SS::error), field("census", &SS::census),
             field("end_pose", &SS::end_pose), field("level_min", &SS::level_min),
             field("level_max", &SS::level_max));

  using DS = PlanarDriftSample;
  py::class_<DS> drift(m, "PlanarDriftSample",
                       "One sample of planar_drift_field() (its 'samples' list): from rest at "
                       "(x, y, angle), the mean drift over the sampled periods.");
  drift.def_readonly("x", &DS::x, "start x on the table [-]")
      .def_readonly("y", &DS::y, "start y on the table [-]")
      .def_readonly("angle", &DS::angle, "start angle relative to the table [rad]")
      .def_readonly("drift_x", &DS::drift_x, "mean velocity along table x [-]")
      .def_readonly("drift_y", &DS::drift_y, "mean velocity along table y [-]")
      .def_readonly("rotation_rate", &DS::rotation_rate, "mean spin relative to the table [-]")
      .def_readonly("census", &DS::census, "PlanarCensus over the sampled periods")
      .def_readonly("failure", &DS::failure,
                    "'' when computed; otherwise why the sample could not be (its numbers are "
                    "then NaN; a failed sample never aborts the field)")
      .def("__repr__", [](const DS& d) {
        return Repr("PlanarDriftSample")("x", d.x)("y", d.y)("angle", d.angle)(
                   "drift_x", d.drift_x)("drift_y", d.drift_y)("rotation_rate", d.rotation_rate)
            .raw("failure", py::repr(py::str(d.failure)).cast<std::string>())
            .str();
      });
  def_record(drift, field("x", &DS::x), field("y", &DS::y), field("angle", &DS::angle),
             field("drift_x", &DS::drift_x), field("drift_y", &DS::drift_y),
             field("rotation_rate", &DS::rotation_rate), field("census", &DS::census),
             field("failure", &DS::failure));

  using RUN = PlanarStopRun;
  py::class_<RUN> run(m, "PlanarStopRun", "One run of planar_stop().");
  run.def_readonly("entry", &RUN::entry, "the entry PlanarPose (the part starts at rest)")
      .def_readonly("stopped", &RUN::stopped, "whether it stuck for a whole table period")
      .def_readonly("end", &RUN::end, "the PlanarPose where it stopped; NaN when not stopped")
      .def_readonly("process_time", &RUN::process_time,
                    "T_p: when the final stick began, to the step (the end of the last step "
                    "that did not end in stick; 0 for a part that never moved) [-]; NaN when "
                    "not stopped")
      .def_readonly("periods", &RUN::periods, "table periods simulated")
      .def_readonly("failure", &RUN::failure,
                    "'' when computed; otherwise why the run could not be (stopped is then "
                    "False; a failed run never aborts the study)")
      .def("__repr__", [](const RUN& r) {
        return Repr("PlanarStopRun")
            .raw("entry", py::repr(py::cast(r.entry)))("stopped", r.stopped)
            .raw("end", py::repr(py::cast(r.end)))("process_time", r.process_time)(
                "periods", r.periods)
            .raw("failure", py::repr(py::str(r.failure)).cast<std::string>())
            .str();
      });
  def_record(run, field("entry", &RUN::entry), field("stopped", &RUN::stopped),
             field("end", &RUN::end), field("process_time", &RUN::process_time),
             field("periods", &RUN::periods), field("failure", &RUN::failure));

  using SUM = PlanarStopSummary;
  py::class_<SUM> summary(m, "PlanarStopSummary", R"doc(
The outcome of planar_stop(): every run, and over the stopped ones the positioning error as a
2-D region (bounding box, largest distance from the mean end position) and an orientation error
(range of end angles). NaN where no run stopped.)doc");
  summary.def_readonly("runs", &SUM::runs, "a list of PlanarStopRun, one per entry (a copy)")
      .def_readonly("stopped", &SUM::stopped, "runs that stopped")
      .def_readonly("failed", &SUM::failed,
                    "runs that could not be computed (each run's failure says why)")
      .def_readonly("never_stops", &SUM::never_stops,
                    "proven that no part is ever stuck for a whole period (a table that does "
                    "not turn whose velocity changes in some step by more than h s max m); the "
                    "runs are then not simulated")
      .def_readonly("mean_x", &SUM::mean_x, "mean end x [-]")
      .def_readonly("mean_y", &SUM::mean_y, "mean end y [-]")
      .def_readonly("mean_angle", &SUM::mean_angle, "mean end angle [rad]")
      .def_readonly("min_x", &SUM::min_x, "smallest end x [-]")
      .def_readonly("max_x", &SUM::max_x, "largest end x [-]")
      .def_readonly("min_y", &SUM::min_y, "smallest end y [-]")
      .def_readonly("max_y", &SUM::max_y, "largest end y [-]")
      .def_readonly("radius", &SUM::radius, "max |end - mean| over the stopped runs [-]")
      .def_readonly("angle_range", &SUM::angle_range, "max - min end angle [rad]")
      .def_readonly("max_process_time", &SUM::max_process_time,
                    "largest T_p over the stopped runs [-]")
      .def("__repr__", [](const SUM& s) {
        return Repr("PlanarStopSummary")("runs", static_cast<long long>(s.runs.size()))(
                   "stopped", s.stopped)("mean_x", s.mean_x)("mean_y", s.mean_y)(
                   "radius", s.radius)("angle_range", s.angle_range)("max_process_time",
                                                                     s.max_process_time)
            .str();
      });
  def_record(summary, field("runs", &SUM::runs), field("stopped", &SUM::stopped),
             field("mean_x", &SUM::mean_x), field("mean_y", &SUM::mean_y),
             field("mean_angle", &SUM::mean_angle), field("min_x", &SUM::min_x),
             field("max_x", &SUM::max_x), field("min_y", &SUM::min_y),
             field("max_y", &SUM::max_y), field("radius", &SUM::radius),
             field("angle_range", &SUM::angle_range),
             field("max_process_time", &SUM::max_process_time),
             field("failed", &SUM::failed), field("never_stops", &SUM::never_stops));
}

// ---- runs ------------------------------------------------------------------------------------

// The table's motion, borrowing the profiles (which the caller's arguments keep alive).
PlanarTableMotion motion_of(const TableProfile* x_profile, const TableProfile* y_profile,
                            const TableProfile* rotation, const py::handle& x_direction,
                            const py::handle& y_direction) {
  const auto direction = [](const py::handle& h, const char* name) {
    const std::vector<double> v = to_vector(h, name);
    if (v.size() != 2)
      throw InvalidParameter(name, std::to_string(v.size()) + " values",
                             "must be a unit vector (ex, ey)");
    if (!(std::abs(std::hypot(v[0], v[1]) - 1) <= 1e-12))
      throw InvalidParameter(name, std::hypot(v[0], v[1]), "must be a unit vector (|e| = 1)");
    return v;
  };
  const std::vector<double> e1 = direction(x_direction, "x_direction");
  const std::vector<double> e2 = direction(y_direction, "y_direction");
  PlanarTableMotion motion{x_profile, e1[0], e1[1], y_profile, e2[0], e2[1], rotation};
  validate(motion);
  return motion;
}

// A PlanarPose, or a sequence (x, y, angle).
PlanarPose pose_of(const py::handle& h, const char* name) {
  if (py::isinstance<PlanarPose>(h)) return h.cast<PlanarPose>();
  const std::vector<double> v = to_vector(h, name);
  if (v.size() != 3)
    throw InvalidParameter(name, std::to_string(v.size()) + " values",
                           "must be a PlanarPose or (x, y, angle)");
  return {v[0], v[1], v[2]};
}

// A PlanarTwist, or a sequence (ux, uy, omega).
PlanarTwist twist_of(const py::handle& h, const char* name) {
  if (py::isinstance<PlanarTwist>(h)) return h.cast<PlanarTwist>();
  const std::vector<double> v = to_vector(h, name);
  if (v.size() != 3)
    throw InvalidParameter(name, std::to_string(v.size()) + " values",
                           "must be a PlanarTwist or (ux, uy, omega)");
  return {v[0], v[1], v[2]};
}

PlanarProblem problem_of(const TableProfile* x_profile, const TableProfile* y_profile,
                         const TableProfile* rotation, const py::handle& x_direction,
                         const py::handle& y_direction, const PlanarField& field,
                         const RigidPart& part, const FrictionLaw& law, double step,
                         double theta) {
  PlanarProblem p;
  p.motion = motion_of(x_profile, y_profile, rotation, x_direction, y_direction);
  p.field = field;
  p.law = law;
  p.part = part;
  p.options = TimeSteppingOptions{step, theta};
  return p;
}

// Python's PlanarProblem: C++'s PlanarProblem (planar_analysis.hpp) with the profiles it
// borrows held alive by the Python object.
struct PyPlanarProblem {
  py::object x_profile, y_profile, rotation;  // a TableProfile or None each
  PlanarProblem problem;
};

// None, or a TableProfile (TypeError naming `name` otherwise).
const TableProfile* profile_or_null(const py::object& o, const char* name) {
  if (o.is_none()) return nullptr;
  if (!py::isinstance<TableProfile>(o))
    throw py::type_error(std::string(name) + ": expected a TableProfile or None, got " +
                         py::str(py::type::of(o).attr("__name__")).cast<std::string>());
  return o.cast<const TableProfile*>();
}

// The checked PlanarProblem (the constructor, and unpickling).
PyPlanarProblem make_problem(const py::object& x_profile, const py::object& y_profile,
                             const py::object& rotation, const PlanarField& field,
                             const RigidPart& part, const FrictionLaw& law, double step,
                             double theta, const py::object& x_direction,
                             const py::object& y_direction) {
  PyPlanarProblem pp{x_profile, y_profile, rotation,
                     problem_of(profile_or_null(x_profile, "x_profile"),
                                profile_or_null(y_profile, "y_profile"),
                                profile_or_null(rotation, "rotation"), x_direction, y_direction,
                                field, part, law, step, theta)};
  validate(pp.problem.field);
  validate(pp.problem.part);
  validate(pp.problem.options);
  require_planar_law(pp.problem.law);
  return pp;
}

void bind_problem(py::module_& m) {
  const auto none = py::none();
  py::class_<PyPlanarProblem> cls(m, "PlanarProblem", R"doc(
Everything one planar run needs, as C++'s PlanarProblem: the table's motion
T(t) = x_profile(t) x_direction + y_profile(t) y_direction, turning by rotation(t) [rad] about its
origin (each a TableProfile or None; their periods dividing the longest), the friction `field`
(a planar field, table coordinates), the `part` (RigidPart), the friction `law` (isotropic and
velocity-independent) and Moreau's step `step` [-] and `theta`. Checked on construction
(InvalidParameter naming the first invalid argument); immutable. Every planar analysis takes it
as its first argument: simulate_planar(problem, periods=3), planar_steady_state(problem), ...
(the keyword form with the same ten arguments builds one).)doc");
  cls.def(py::init(&make_problem),
          py::arg("x_profile") = none, py::arg("y_profile") = none, py::arg("rotation") = none,
          py::kw_only(), py::arg("field"), py::arg("part"), py::arg("law") = FrictionLaw{},
          py::arg("step"), py::arg("theta") = 0.5,
          py::arg("x_direction") = py::make_tuple(1.0, 0.0),
          py::arg("y_direction") = py::make_tuple(0.0, 1.0))
      .def_property_readonly(
          "x_profile", [](const PyPlanarProblem& p) { return p.x_profile; },
          "the TableProfile along x_direction, or None")
      .def_property_readonly(
          "y_profile", [](const PyPlanarProblem& p) { return p.y_profile; },
          "the TableProfile along y_direction, or None")
      .def_property_readonly(
          "rotation", [](const PyPlanarProblem& p) { return p.rotation; },
          "the TableProfile of the table's angle [rad], or None")
      .def_property_readonly(
          "x_direction",
          [](const PyPlanarProblem& p) {
            return py::make_tuple(p.problem.motion.e1_x, p.problem.motion.e1_y);
          },
          "unit vector (ex, ey) of x_profile's motion")
      .def_property_readonly(
          "y_direction",
          [](const PyPlanarProblem& p) {
            return py::make_tuple(p.problem.motion.e2_x, p.problem.motion.e2_y);
          },
          "unit vector (ex, ey) of y_profile's motion")
      .def_property_readonly(
          "field", [](const PyPlanarProblem& p) { return p.problem.field; },
          "the planar friction field (a copy)")
      .def_property_readonly(
          "part", [](const PyPlanarProblem& p) { return p.problem.part; }, "the RigidPart")
      .def_property_readonly(
          "law", [](const PyPlanarProblem& p) { return p.problem.law; }, "the FrictionLaw")
      .def_property_readonly(
          "step", [](const PyPlanarProblem& p) { return p.problem.options.step; },
          "Moreau's step h [-]")
      .def_property_readonly(
          "theta", [](const PyPlanarProblem& p) { return p.problem.options.theta; },
          "Moreau's theta, in [0, 1]")
      .def("__repr__", [](const PyPlanarProblem& p) {
        const auto r = [](const py::handle& h) { return py::repr(h).cast<std::string>(); };
        return Repr("PlanarProblem")
            .raw("x_profile", r(p.x_profile))
            .raw("y_profile", r(p.y_profile))
            .raw("rotation", r(p.rotation))
            .raw("field", r(py::cast(p.problem.field)))
            .raw("part", r(py::cast(p.problem.part)))
            .raw("law", r(py::cast(p.problem.law)))("step", p.problem.options.step)(
                "theta", p.problem.options.theta)
            .raw("x_direction", r(py::make_tuple(p.problem.motion.e1_x, p.problem.motion.e1_y)))
            .raw("y_direction", r(py::make_tuple(p.problem.motion.e2_x, p.problem.motion.e2_y)))
            .str();
      });
  using PP = PyPlanarProblem;
  def_record(
      cls,
      [](py::object x_profile, py::object y_profile, py::object rotation, PlanarField field,
         RigidPart part, FrictionLaw law, double step, double theta, py::object x_direction,
         py::object y_direction) {
        return make_problem(x_profile, y_profile, rotation, field, part, law, step, theta,
                            x_direction, y_direction);
      },
      field("x_profile", [](const PP& p) { return p.x_profile; }),
      field("y_profile", [](const PP& p) { return p.y_profile; }),
      field("rotation", [](const PP& p) { return p.rotation; }),
      field("field", [](const PP& p) { return p.problem.field; }),
      field("part", [](const PP& p) { return p.problem.part; }),
      field("law", [](const PP& p) { return p.problem.law; }),
      field("step", [](const PP& p) { return p.problem.options.step; }),
      field("theta", [](const PP& p) { return p.problem.options.theta; }),
      field("x_direction",
            [](const PP& p) {
              return py::object(py::make_tuple(p.problem.motion.e1_x, p.problem.motion.e1_y));
            }),
      field("y_direction", [](const PP& p) {
        return py::object(py::make_tuple(p.problem.motion.e2_x, p.problem.motion.e2_y));
      }));
}

// A recorded run as the dict of NumPy columns simulate_planar returns.
py::dict trajectory_dict(PlanarTrajectory&& r, Method method) {
  py::dict d;
  if (method == Method::integrator) d["integration"] = r.integration;
  std::vector<std::int8_t> mode;
  mode.reserve(r.mode.size());
  for (PatchMode m : r.mode) mode.push_back(static_cast<std::int8_t>(m));
  d["t"] = to_array(std::move(r.t)), d["x"] = to_array(std::move(r.x));
  d["y"] = to_array(std::move(r.y)), d["angle"] = to_array(std::move(r.angle));
  d["ux"] = to_array(std::move(r.ux)), d["uy"] = to_array(std::move(r.uy));
  d["omega"] = to_array(std::move(r.omega)), d["mode"] = to_array(std::move(mode));
  d["pivot"] = to_array(std::move(r.pivot));
  d["table_x"] = to_array(std::move(r.table_x)), d["table_y"] = to_array(std::move(r.table_y));
  d["table_angle"] = to_array(std::move(r.table_angle));
  return d;
}

// The (x, y, angle) rows of an N x 3 array-like, or a list of PlanarPose.
std::vector<PlanarPose> entries_of(const py::handle& h) {
  std::vector<PlanarPose> out;
  if (py::isinstance<py::list>(h) || py::isinstance<py::tuple>(h)) {
    const py::sequence seq = py::reinterpret_borrow<py::sequence>(h);
    if (seq.size() > 0 && py::isinstance<PlanarPose>(seq[0])) {
      for (const py::handle e : seq) out.push_back(pose_of(e, "entries"));
      return out;
    }
  }
  const auto a = DoubleArray::ensure(h);
  if (!a) throw py::type_error("entries: expected an N x 3 array-like of (x, y, angle)");
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw InvalidParameter("entries", "an array of " + std::to_string(a.ndim()) + " dimensions",
                           "must be N x 3: one (x, y, angle) per row");
  for (py::ssize_t i = 0; i < a.shape(0); ++i)
    out.push_back({a.at(i, 0), a.at(i, 1), a.at(i, 2)});
  return out;
}

constexpr const char* kCommonDoc = R"doc(
The table moves by T(t) = x_profile(t) x_direction + y_profile(t) y_direction and turns by
rotation(t) [rad] about its origin (None: no motion of that kind; each profile a TableProfile,
their periods dividing the longest one). The part (RigidPart) lies on the friction level
`field` (UniformPlanarField, HalfPlaneStepField, StripField, RectangularPocketField,
CircularPocketField, GridField or AxisField, in table coordinates) under `law` (FrictionLaw: isotropic,
kinetic_forward = kinetic_backward, and velocity-independent), and is advanced by Moreau's
time-stepping with step `step` [-] and theta `theta` (docs/planar.md). Everything is
dimensionless: mass 1, lengths in L, friction per unit m g mu_1. Raises InvalidParameter
naming the first invalid argument. Runs without the GIL.)doc";

std::string doc(const char* head) { return std::string(head) + kCommonDoc; }

void bind_runs(py::module_& m) {
  bind_problem(m);
  const auto none = py::none();
  const py::tuple zero3 = py::make_tuple(0.0, 0.0, 0.0);
  const py::tuple ex = py::make_tuple(1.0, 0.0), ey = py::make_tuple(0.0, 1.0);
  static const std::string simulate_doc = doc(R"doc(
One run of a rigid part on a table moving in the plane, from `pose` (PlanarPose or (x, y,
angle): centre of mass in table coordinates, angle relative to the table) with `twist`
(PlanarTwist or (ux, uy, omega): relative to the table, in table axes) at t = 0, over `periods`
table periods or a `duration` [-] (exactly one; a table at rest, no profiles, needs duration,
a whole number of steps to 1e-9). Returns a dict of 1-D NumPy arrays sampled at t = 0, every
`every` steps, and at the last step:
  float64  t; x, y, angle (the pose on the table); ux, uy, omega (the relative twist);
           table_x, table_y, table_angle (the table's world pose: the part's world centre is
           (table_x, table_y) + R(table_angle) (x, y), its world angle table_angle + angle)
  int8     mode (PatchMode of the step that ended there: 0 stick, 1 pivot, 2 slip; at t = 0
           stick for a zero twist, else slip)
  int32    pivot (the pivot contact's index in part.patch for mode 1, else -1)
`method`: "time-stepping" (Moreau, the default) or "exact": the exact event-driven point solver
(a point part at its centre of mass on a uniform field, a translating table with
piecewise-constant accelerations; otherwise InvalidParameter naming method), sampled at the same
times (the step then only sets them): exact to rounding, mode 0 where the relative velocity is
0, else 2; the angle turns at the start's constant omega (no torque about a centred point).
Or "integrator": the patch integrator (any part and field on a translating table with
piecewise-constant accelerations; docs/planar-integrator.md): slips integrated by Dormand-Prince
5(4) under `integrator` (IntegratorOptions: relative and absolute tolerance, step budget), stick
and pivot decided exactly at the events; mode and pivot are the current ones at each sample,
and the dict also holds "integration" (IntegratorStatistics: steps, events, sticks, pivots).
)doc");
  // simulate_planar on a PlanarProblem: both overloads below call it.
  const auto simulate_planar_of = [](const PlanarProblem& problem,
                                      std::optional<long long> periods,
                                      std::optional<double> duration, const py::object& pose_in,
                                      const py::object& twist_in, long long every, Method method,
                                      const IntegratorOptions& integrator) {
    PlanarProblem p = problem;
    p.integrator = integrator;
    const PlanarPose pose = pose_of(pose_in, "pose");
    const PlanarTwist twist = twist_of(twist_in, "twist");
    if (every < 1) throw InvalidParameter("every", static_cast<double>(every), "must be >= 1");
    if (periods.has_value() == duration.has_value())
      throw InvalidParameter("periods", periods ? std::to_string(*periods) : "None",
                             "give exactly one of periods and duration");
    const long long steps = periods ? planar_steps_of_periods(p, *periods)
                                    : planar_steps_of_duration(p, *duration);
    const PythonProgress interrupt{py::none()};
    PlanarTrajectory r = interrupt.run([&] {
      return simulate_planar(p, pose, twist, steps, every,
                             [&interrupt](long long, long long) { interrupt.stop_if_cancelled(); },
                             method);
    });
    return trajectory_dict(std::move(r), method);
  };
  m.def(
      "simulate_planar",
      [simulate_planar_of](const PyPlanarProblem& problem,
              std::optional<long long> periods, std::optional<double> duration,
              const py::object& pose_in, const py::object& twist_in, long long every,
              Method method, const IntegratorOptions& integrator) {
        return simulate_planar_of(problem.problem, periods, duration, pose_in, twist_in, every,
                                  method, integrator);
      },
      py::arg("problem"), py::kw_only(),
      py::arg("periods") = none, py::arg("duration") = none, py::arg("pose") = zero3,
      py::arg("twist") = zero3, py::arg("every") = 1, py::arg("method") = Method::time_stepping,
      py::arg("integrator") = IntegratorOptions{}, simulate_doc.c_str());
  m.def(
      "simulate_planar",
      [simulate_planar_of](const TableProfile* x_profile, const TableProfile* y_profile,
         const TableProfile* rotation, const PlanarField& field, const RigidPart& part,
         const FrictionLaw& law, double step, double theta, 
              std::optional<long long> periods, std::optional<double> duration,
              const py::object& pose_in, const py::object& twist_in, long long every,
              const py::object& x_direction, const py::object& y_direction, Method method,
              const IntegratorOptions& integrator) {
        return simulate_planar_of(problem_of(x_profile, y_profile, rotation, x_direction, y_direction, field,
                                part, law, step, theta),
                     periods, duration, pose_in, twist_in, every, method, integrator);
      },
      py::arg("x_profile") = none, py::arg("y_profile") = none, py::arg("rotation") = none,
      py::kw_only(), py::arg("field"), py::arg("part"), py::arg("law") = FrictionLaw{},
      py::arg("step"), py::arg("theta") = 0.5,
      py::arg("periods") = none, py::arg("duration") = none, py::arg("pose") = zero3,
      py::arg("twist") = zero3, py::arg("every") = 1,
      py::arg("x_direction") = ex, py::arg("y_direction") = ey,
      py::arg("method") = Method::time_stepping, py::arg("integrator") = IntegratorOptions{},
      simulate_doc.c_str());

  static const std::string steady_doc = doc(R"doc(
The window-average drift of a part (kept for comparison; the steady state is
planar_steady_state(), the fixed point of the period map, which the CLI's `planar steady` uses):
from `pose` with `twist` at t = 0, runs `transient` table periods
([0, 100000]), then two windows of `window` periods ([1, 100000]); returns a PlanarSteadyResult
with the last window's mean drift velocity and spin relative to the table, its PlanarCensus, the
change of the drift between the two windows, and the end pose. The step must divide the period
into 2 to 1e8 whole steps.
)doc");
  // planar_steady on a PlanarProblem: both overloads below call it.
  const auto planar_steady_of = [](const PlanarProblem& p,
                          const py::object& pose, const py::object& twist, int transient, int window) {
    const PlanarPose start = pose_of(pose, "pose");
    const PlanarTwist u = twist_of(twist, "twist");
    py::gil_scoped_release release;
    return planar_steady(p, start, u, transient, window);
  };
  m.def(
      "planar_steady",
      [planar_steady_of](const PyPlanarProblem& problem,
              const py::object& pose, const py::object& twist, int transient, int window) {
        return planar_steady_of(problem.problem, pose, twist, transient, window);
      },
      py::arg("problem"), py::kw_only(),
      py::arg("pose") = zero3, py::arg("twist") = zero3, py::arg("transient") = 20,
      py::arg("window") = 5,
      steady_doc.c_str());
  m.def(
      "planar_steady",
      [planar_steady_of](const TableProfile* x_profile, const TableProfile* y_profile,
         const TableProfile* rotation, const PlanarField& field, const RigidPart& part,
         const FrictionLaw& law, double step, double theta, 
              const py::object& pose, const py::object& twist, int transient, int window,
              const py::object& x_direction, const py::object& y_direction) {
        return planar_steady_of(problem_of(x_profile, y_profile, rotation, x_direction, y_direction, field,
                                part, law, step, theta),
                     pose, twist, transient, window);
      },
      py::arg("x_profile") = none, py::arg("y_profile") = none, py::arg("rotation") = none,
      py::kw_only(), py::arg("field"), py::arg("part"), py::arg("law") = FrictionLaw{},
      py::arg("step"), py::arg("theta") = 0.5,
      py::arg("pose") = zero3, py::arg("twist") = zero3, py::arg("transient") = 20,
      py::arg("window") = 5,
      py::arg("x_direction") = ex, py::arg("y_direction") = ey, steady_doc.c_str());

  static const std::string steady_state_doc = doc(R"doc(
The planar steady state as the fixed point of the period map (the 1-D criterion; the CLI's
`planar steady`): from `pose` with `twist` at t = 0, after `transient_periods` ([0, 1e5]),
iterates the period map at most `max_periods` ([1, 1e6]) times until the twist at phase 0 and
the displacement per period stop changing (tolerance relative to 1 + |z|; 0: 1e-13 with the
exact point solver, 10 step otherwise). The exact event-driven point solver runs where it
applies (a point part at its centre, a uniform field, a translating table with
piecewise-constant accelerations), Moreau's rigid-part stepper otherwise. A change of the
friction level under the part during the run is reported (level_changed), never averaged
over. Returns a PlanarSteadyState (drift NaN unless converged).
)doc");
  // planar_steady_state on a PlanarProblem: both overloads below call it.
  const auto planar_steady_state_of = [](const PlanarProblem& p,
                          const py::object& pose, const py::object& twist, int transient_periods,
              int max_periods, double tolerance) {
    const PlanarPose start = pose_of(pose, "pose");
    const PlanarTwist u = twist_of(twist, "twist");
    PlanarSteadyStateOptions o;
    o.transient_periods = transient_periods;
    o.max_periods = max_periods;
    o.tolerance = tolerance;
    py::gil_scoped_release release;
    return planar_steady_state(p, start, u, o);
  };
  m.def(
      "planar_steady_state",
      [planar_steady_state_of](const PyPlanarProblem& problem,
              const py::object& pose, const py::object& twist, int transient_periods,
              int max_periods, double tolerance) {
        return planar_steady_state_of(problem.problem, pose, twist, transient_periods, max_periods, tolerance);
      },
      py::arg("problem"), py::kw_only(),
      py::arg("pose") = zero3, py::arg("twist") = zero3, py::arg("transient_periods") = 0,
      py::arg("max_periods") = 2000, py::arg("tolerance") = 0.0,
      steady_state_doc.c_str());
  m.def(
      "planar_steady_state",
      [planar_steady_state_of](const TableProfile* x_profile, const TableProfile* y_profile,
         const TableProfile* rotation, const PlanarField& field, const RigidPart& part,
         const FrictionLaw& law, double step, double theta, 
              const py::object& pose, const py::object& twist, int transient_periods,
              int max_periods, double tolerance,
              const py::object& x_direction, const py::object& y_direction) {
        return planar_steady_state_of(problem_of(x_profile, y_profile, rotation, x_direction, y_direction, field,
                                part, law, step, theta),
                     pose, twist, transient_periods, max_periods, tolerance);
      },
      py::arg("x_profile") = none, py::arg("y_profile") = none, py::arg("rotation") = none,
      py::kw_only(), py::arg("field"), py::arg("part"), py::arg("law") = FrictionLaw{},
      py::arg("step"), py::arg("theta") = 0.5,
      py::arg("pose") = zero3, py::arg("twist") = zero3, py::arg("transient_periods") = 0,
      py::arg("max_periods") = 2000, py::arg("tolerance") = 0.0,
      py::arg("x_direction") = ex, py::arg("y_direction") = ey, steady_state_doc.c_str());

  static const std::string drift_doc = doc(R"doc(
The drift field: from rest at every pose of the grid xs x ys x angles (table coordinates [-],
angles [rad]), the mean drift over `periods` table periods ([1, 100000]), in parallel on
`threads` workers (0: all cores; results independent of the count). Returns a dict:
  xs, ys, angles  the grid (1-D float64)
  x, y, angle, drift_x, drift_y, rotation_rate  float64 arrays shaped
                  (len(ys), len(xs), len(angles)): the start pose and the mean velocity
                  along table x, y [-] and the mean spin relative to the table [-]
  stick, pivot, slip  int64 arrays of that shape: steps of each PatchMode
  failed          bool array of that shape: samples that could not be computed (their
                  numbers NaN, each sample's failure says why); the others are computed
  samples         the same as a list of PlanarDriftSample (angle fastest, then x, then y)
`progress(done, total)`, if given, is called as samples complete (from worker threads, one
call at a time, holding the GIL); Ctrl-C stops the study with KeyboardInterrupt.
)doc");
  // planar_drift_field on a PlanarProblem: both overloads below call it.
  const auto planar_drift_field_of = [](const PlanarProblem& p,
                          const py::object& xs_in, const py::object& ys_in, const py::object& angles_in,
              int periods, int threads, const py::object& progress_in) {
    const std::vector<double> xs = to_vector(xs_in, "xs"), ys = to_vector(ys_in, "ys"),
                              angles = to_vector(angles_in, "angles");
    const PythonProgress progress(progress_in);
    const std::vector<PlanarDriftSample> samples = progress.run([&] {
      return planar_drift_field(p, xs, ys, angles, periods, progress.callback(), threads);
    });
    const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(ys.size()),
                                         static_cast<py::ssize_t>(xs.size()),
                                         static_cast<py::ssize_t>(angles.size())};
    py::array_t<double> x(shape), y(shape), angle(shape), dx(shape), dy(shape), rate(shape);
    py::array_t<std::int64_t> stick(shape), pivot(shape), slip(shape);
    py::array_t<bool> failed(shape);
    py::list list;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const PlanarDriftSample& s = samples[i];
      x.mutable_data()[i] = s.x, y.mutable_data()[i] = s.y;
      angle.mutable_data()[i] = s.angle;
      dx.mutable_data()[i] = s.drift_x, dy.mutable_data()[i] = s.drift_y;
      rate.mutable_data()[i] = s.rotation_rate;
      stick.mutable_data()[i] = s.census.stick, pivot.mutable_data()[i] = s.census.pivot;
      slip.mutable_data()[i] = s.census.slip;
      failed.mutable_data()[i] = !s.failure.empty();
      list.append(py::cast(s));
    }
    py::dict d;
    d["xs"] = to_array(std::vector(xs)), d["ys"] = to_array(std::vector(ys));
    d["angles"] = to_array(std::vector(angles));
    d["x"] = x, d["y"] = y, d["angle"] = angle;
    d["drift_x"] = dx, d["drift_y"] = dy, d["rotation_rate"] = rate;
    d["stick"] = stick, d["pivot"] = pivot, d["slip"] = slip;
    d["failed"] = failed;
    d["samples"] = list;
    return d;
  };
  m.def(
      "planar_drift_field",
      [planar_drift_field_of](const PyPlanarProblem& problem,
              const py::object& xs_in, const py::object& ys_in, const py::object& angles_in,
              int periods, int threads, const py::object& progress_in) {
        return planar_drift_field_of(problem.problem, xs_in, ys_in, angles_in, periods, threads, progress_in);
      },
      py::arg("problem"), py::kw_only(),
      py::arg("xs"), py::arg("ys"), py::arg("angles") = py::make_tuple(0.0), py::arg("periods"),
      py::arg("threads") = 0, py::arg("progress") = none,
      drift_doc.c_str());
  m.def(
      "planar_drift_field",
      [planar_drift_field_of](const TableProfile* x_profile, const TableProfile* y_profile,
         const TableProfile* rotation, const PlanarField& field, const RigidPart& part,
         const FrictionLaw& law, double step, double theta, 
              const py::object& xs_in, const py::object& ys_in, const py::object& angles_in,
              int periods, int threads, const py::object& progress_in,
              const py::object& x_direction, const py::object& y_direction) {
        return planar_drift_field_of(problem_of(x_profile, y_profile, rotation, x_direction, y_direction, field,
                                part, law, step, theta),
                     xs_in, ys_in, angles_in, periods, threads, progress_in);
      },
      py::arg("x_profile") = none, py::arg("y_profile") = none, py::arg("rotation") = none,
      py::kw_only(), py::arg("field"), py::arg("part"), py::arg("law") = FrictionLaw{},
      py::arg("step"), py::arg("theta") = 0.5,
      py::arg("xs"), py::arg("ys"), py::arg("angles") = py::make_tuple(0.0), py::arg("periods"),
      py::arg("threads") = 0, py::arg("progress") = none,
      py::arg("x_direction") = ex, py::arg("y_direction") = ey, drift_doc.c_str());

  static const std::string stop_doc = doc(R"doc(
Stopping in a rough region: from rest at each entry pose (`entries`: an N x 3 array-like of
(x, y, angle) rows, or a list of PlanarPose), runs until the part sticks for a whole table period
(stopped; T_p = the start of that period) or max_periods ([1, 1e6]) pass, in parallel on
`threads` workers (0: all cores). Returns a PlanarStopSummary: every run, the region of the
stopped end positions and the range of their angles. `progress(done, total)` as in
planar_drift_field, per entry; Ctrl-C stops the study after the runs under way.
)doc");
  // planar_stop on a PlanarProblem: both overloads below call it.
  const auto planar_stop_of = [](const PlanarProblem& p,
                          const py::object& entries_in, int max_periods, int threads,
              const py::object& progress_in) {
    const std::vector<PlanarPose> entries = entries_of(entries_in);
    const PythonProgress progress(progress_in);
    return progress.run(
        [&] { return planar_stop(p, entries, max_periods, progress.callback(), threads); });
  };
  m.def(
      "planar_stop",
      [planar_stop_of](const PyPlanarProblem& problem,
              const py::object& entries_in, int max_periods, int threads,
              const py::object& progress_in) {
        return planar_stop_of(problem.problem, entries_in, max_periods, threads, progress_in);
      },
      py::arg("problem"), py::kw_only(),
      py::arg("entries"), py::arg("max_periods"), py::arg("threads") = 0,
      py::arg("progress") = none,
      stop_doc.c_str());
  m.def(
      "planar_stop",
      [planar_stop_of](const TableProfile* x_profile, const TableProfile* y_profile,
         const TableProfile* rotation, const PlanarField& field, const RigidPart& part,
         const FrictionLaw& law, double step, double theta, 
              const py::object& entries_in, int max_periods, int threads,
              const py::object& progress_in,
              const py::object& x_direction, const py::object& y_direction) {
        return planar_stop_of(problem_of(x_profile, y_profile, rotation, x_direction, y_direction, field,
                                part, law, step, theta),
                     entries_in, max_periods, threads, progress_in);
      },
      py::arg("x_profile") = none, py::arg("y_profile") = none, py::arg("rotation") = none,
      py::kw_only(), py::arg("field"), py::arg("part"), py::arg("law") = FrictionLaw{},
      py::arg("step"), py::arg("theta") = 0.5,
      py::arg("entries"), py::arg("max_periods"), py::arg("threads") = 0,
      py::arg("progress") = none,
      py::arg("x_direction") = ex, py::arg("y_direction") = ey, stop_doc.c_str());
}

}  // namespace

void bind_planar(py::module_& m) {
  bind_patches(m);
  bind_fields(m);
  bind_values(m);
  bind_runs(m);
}

}  // namespace selfalign::python
