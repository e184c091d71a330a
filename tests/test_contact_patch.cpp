// Contact patches and planar friction fields (planar/contact_patch.hpp, planar/planar_field.hpp)
// against closed forms: the quadratures' load sums, centroids and polar moments (an n x m grid
// of cell centres has sum w x^2 = L^2 (1 - 1/n^2) / 12; a disc tends to R^2/2; a polygon's
// subdivided triangles tend to the polygon's exact polar moment about its centroid), each
// field's level at points where it is known by construction, bilinear grids reproducing a
// bilinear function exactly, and the bad input the issue lists.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "selfalign/error.hpp"
#include "selfalign/planar/contact_patch.hpp"
#include "selfalign/planar/planar_field.hpp"
#include "selfalign/planar/planar_rigid.hpp"

namespace selfalign {
namespace {

double load_sum(const ContactPatch& p) {
  double s = 0;
  for (const auto& c : p) s += c.load;
  return s;
}

TEST(ContactPatch, RectangleGridHasTheMidpointMoments) {
  const double length = 0.3, width = 0.1;
  for (int n : {1, 2, 5}) {
    const ContactPatch p = rectangle_patch(length, width, n, n + 1);
    EXPECT_EQ(p.size(), static_cast<std::size_t>(n * (n + 1)));
    EXPECT_NEAR(load_sum(p), 1, 1e-15);
    const double m = n + 1.0;
    const double expected = length * length * (1 - 1.0 / (n * n)) / 12 + width * width * (1 - 1 / (m * m)) / 12;
    EXPECT_NEAR(polar_moment(p), expected, 1e-15);
  }
}

TEST(ContactPatch, DiscTendsToHalfTheRadiusSquared) {
  const double r = 0.5;
  double previous = HUGE_VAL;
  for (int rings : {2, 8, 32}) {
    const ContactPatch p = disc_patch(r, rings, 4 * rings);
    EXPECT_NEAR(load_sum(p), 1, 1e-12);
    const double err = std::abs(polar_moment(p) - r * r / 2);
    EXPECT_LT(err, previous / 4 * 1.5) << rings;  // second order in 1/rings
    previous = err;
  }
  EXPECT_LT(previous, 1e-3 * r * r);
  EXPECT_NO_THROW(validate(disc_patch(r, 8, 16)));  // centred: load centre at the origin
}

TEST(ContactPatch, PolygonQuadratureConvergesToThePolygonsMoments) {
  // An L-shape (non-convex: exercises the ear clipping), clockwise on purpose. Its exact area
  // centroid and polar moment about it from the shoelace formulas, computed here independently.
  const std::vector<double> xs{0, 0, 1, 1, 2, 2}, ys{0, 2, 2, 1, 1, 0};
  double a2 = 0, cx = 0, cy = 0, ixx = 0, iyy = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const std::size_t j = (i + 1) % xs.size();
    const double c = xs[i] * ys[j] - xs[j] * ys[i];
    a2 += c;
    cx += (xs[i] + xs[j]) * c, cy += (ys[i] + ys[j]) * c;
    ixx += (ys[i] * ys[i] + ys[i] * ys[j] + ys[j] * ys[j]) * c;
    iyy += (xs[i] * xs[i] + xs[i] * xs[j] + xs[j] * xs[j]) * c;
  }
  const double area = a2 / 2;
  cx /= 3 * a2, cy /= 3 * a2;
  const double polar = (ixx + iyy) / 12 / area - (cx * cx + cy * cy);
  EXPECT_NEAR(std::abs(area), 3, 1e-15);
  double previous = HUGE_VAL;
  for (int n : {1, 4, 16}) {
    const ContactPatch p = polygon_patch(xs, ys, n);
    EXPECT_NEAR(load_sum(p), 1, 1e-12);
    EXPECT_NO_THROW(validate(p));
    const double err = std::abs(polar_moment(p) - polar);
    EXPECT_LT(err, previous / 8) << n;  // centroid rule: O(1/n^2)
    previous = err;
  }
  EXPECT_LT(previous, 2e-3);
}

TEST(ContactPatch, BadInputNamesTheParameter) {
  const auto throws_naming = [](auto f, const std::string& name) {
    try {
      f();
      ADD_FAILURE() << "no throw for " << name;
    } catch (const InvalidParameter& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  };
  throws_naming([] { polygon_patch({0, 1}, {0, 1}, 1); }, "polygon");
  throws_naming([] { polygon_patch({0, 1, 1, 0}, {0, 1, 0, 1}, 1); }, "polygon");  // bow tie
  throws_naming([] { polygon_patch({0, 1, 2}, {0, 1, 2}, 1); }, "polygon");        // no area
  throws_naming([] { weighted_points_patch({-1, 1}, {0, 0}, {0.4, 0.4}); }, "load_fractions");
  throws_naming([] { weighted_points_patch({-1, 1, 0}, {0, 0, 0}, {0.75, 0.75, -0.5}); },
                "load_fractions");
  throws_naming([] { weighted_points_patch({0, 1}, {0, 0}, {0.5, 0.5}); }, "load_fractions");  // off-centre
  throws_naming([] { validate(RigidPart{0.0, point_patch()}); }, "inertia");
  throws_naming([] { validate(RigidPart{-1.0, point_patch()}); }, "inertia");
  throws_naming([] { validate(PlanarField(GridField{0, 0, 0, 1, 1, 2, 2, {1, NAN, 1, 1}})); }, "levels");
  throws_naming([] { validate(PlanarField(GridField{0, 0, 0, 1, 1, 2, 2, {1, 1, 1}})); }, "levels");
  // zero loads are allowed and dropped
  EXPECT_EQ(weighted_points_patch({-1, 1, 5}, {0, 0, 5}, {0.5, 0.5, 0}).size(), 2u);
}

TEST(PlanarField, LevelsAtKnownPoints) {
  // Each rough region: 1 outside, c_mu deeper than the band, linear in between.
  const StripField strip{1, 0, 0, 0.5, 0.2, 3};  // |x - 1| <= 0.5
  EXPECT_DOUBLE_EQ(planar_level(strip, 0.4, 7), 1);
  EXPECT_DOUBLE_EQ(planar_level(strip, 1.0, -3), 3);
  EXPECT_DOUBLE_EQ(planar_level(strip, 0.6, 0), 1 + 2 * 0.5);  // depth 0.1 of 0.2
  const RectangularPocketField rect{0, 0, std::numbers::pi / 2, 2, 1, 0.5, 2};  // turned: long side along y
  EXPECT_DOUBLE_EQ(planar_level(rect, 0, 1.9), 1 + 0.2);   // depth min(2 - 1.9, 1) = 0.1
  EXPECT_DOUBLE_EQ(planar_level(rect, 0.9, 0), 1 + 0.2);   // depth 0.1 across
  EXPECT_DOUBLE_EQ(planar_level(rect, 1.5, 0), 1);
  const CircularPocketField circle{1, 1, 1, 0.5, 2.5};
  EXPECT_DOUBLE_EQ(planar_level(circle, 1, 1), 2.5);
  EXPECT_NEAR(planar_level(circle, 1.75, 1), 1 + 1.5 * 0.5, 1e-15);
  EXPECT_DOUBLE_EQ(planar_level(circle, 3, 3), 1);
  // A grid sampled from the bilinear function 1 + x + 2 y + x y reproduces it exactly inside,
  // and clamps outside.
  GridField g{0.5, -0.5, 0, 0.5, 0.25, 4, 5, {}};
  const auto f = [](double x, double y) { return 1 + x + 2 * y + x * y + 3; };
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) g.levels.push_back(f(0.5 + i * g.dx, -0.5 + j * g.dy));
  for (double x : {0.5, 0.61, 1.2, 2.0})
    for (double y : {-0.5, -0.3, 0.1, 0.5}) EXPECT_NEAR(planar_level(g, x, y), f(x, y), 1e-14) << x << " " << y;
  EXPECT_NEAR(planar_level(g, 5, 0.1), f(2.0, 0.1), 1e-14);  // clamped to the edge
}

TEST(PlanarField, RotatedFieldsAreRotated) {
  const double a = 0.7, c = std::cos(a), s = std::sin(a);
  GridField g{0.1, 0.2, 0.3, 0.5, 0.4, 3, 3, {1, 2, 3, 2, 3, 4, 3, 4, 6}};
  for (const PlanarField& f : {PlanarField(StripField{0.2, 0.1, 0.4, 0.3, 0.1, 2}),
                               PlanarField(RectangularPocketField{0.3, -0.2, 0.2, 0.5, 0.2, 0.1, 3}),
                               PlanarField(CircularPocketField{0.1, 0.1, 0.4, 0.2, 2}),
                               PlanarField(g)}) {
    const PlanarField r = rotated_field(f, a);
    for (double x : {-0.3, 0.1, 0.35, 0.8})
      for (double y : {-0.4, 0.0, 0.25, 0.6})
        EXPECT_NEAR(planar_level(r, c * x - s * y, s * x + c * y), planar_level(f, x, y), 1e-12);
  }
}

}  // namespace
}  // namespace selfalign
