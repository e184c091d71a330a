#include "selfalign/planar/outline.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "selfalign/error.hpp"
#include "selfalign/overloaded.hpp"

namespace selfalign {

namespace {

using Vec = std::array<double, 2>;

double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1]; }
double cross(const Vec& a, const Vec& b) { return a[0] * b[1] - a[1] * b[0]; }
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1]}; }

double signed_area(const PolygonOutline& p) {
  double a = 0;
  const std::size_t n = p.xs.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    a += p.xs[i] * p.ys[j] - p.xs[j] * p.ys[i];
  }
  return a / 2;
}

// A polygon at a world pose, its vertices counter-clockwise on demand (no allocation).
struct WorldPolygon {
  const PolygonOutline& p;
  double x, y, c, s;
  bool ccw;
  std::size_t n;

  WorldPolygon(const PolygonOutline& poly, const PlanarPose& pose)
      : p(poly), x(pose.x), y(pose.y), c(std::cos(pose.angle)), s(std::sin(pose.angle)),
        ccw(signed_area(poly) > 0), n(poly.xs.size()) {}

  Vec v(std::size_t i) const {
    i %= n;
    const std::size_t k = ccw ? i : n - 1 - i;
    return {x + c * p.xs[k] - s * p.ys[k], y + s * p.xs[k] + c * p.ys[k]};
  }
  // the outward unit normal of face i (from vertex i to vertex i + 1)
  Vec normal(std::size_t i) const {
    const Vec e = sub(v(i + 1), v(i));
    const double len = std::hypot(e[0], e[1]);
    return {e[1] / len, -e[0] / len};
  }
};

// The face of `ref` along whose normal `inc` is separated most: max over ref's faces of the
// smallest signed distance of inc's vertices to the face (the separating-axis test).
std::pair<double, std::size_t> max_separation(const WorldPolygon& ref, const WorldPolygon& inc) {
  double best = -std::numeric_limits<double>::infinity();
  std::size_t face = 0;
  for (std::size_t i = 0; i < ref.n; ++i) {
    const Vec nrm = ref.normal(i), v = ref.v(i);
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < inc.n; ++j) lowest = std::min(lowest, dot(sub(inc.v(j), v), nrm));
    if (lowest > best) best = lowest, face = i;
  }
  return {best, face};
}

// Keeps the part of segment pts[0..count) on the side d(p) = dot(p - o, dir) >= 0.
int clip(std::array<Vec, 2>& pts, int count, const Vec& o, const Vec& dir) {
  if (count < 2) return count;
  const double d0 = dot(sub(pts[0], o), dir), d1 = dot(sub(pts[1], o), dir);
  std::array<Vec, 2> out{};
  int k = 0;
  if (d0 >= 0) out[static_cast<std::size_t>(k++)] = pts[0];
  if (d1 >= 0) out[static_cast<std::size_t>(k++)] = pts[1];
  if (d0 * d1 < 0) {
    const double t = d0 / (d0 - d1);
    out[static_cast<std::size_t>(k++)] = {pts[0][0] + t * (pts[1][0] - pts[0][0]),
                                          pts[0][1] + t * (pts[1][1] - pts[0][1])};
  }
  pts = out;
  return k;
}

// polygon-polygon: the reference face's normal from a to b and the clipped incident points
ContactManifold polygons(const PolygonOutline& pa, const PlanarPose& a, const PolygonOutline& pb,
                         const PlanarPose& b) {
  const WorldPolygon A(pa, a), B(pb, b);
  const auto [sa, ia] = max_separation(A, B);
  const auto [sb, ib] = max_separation(B, A);
  const double size = outline_radius(pa) + outline_radius(pb);
  const bool flip = sb > sa + 1e-12 * size;
  const WorldPolygon& ref = flip ? B : A;
  const WorldPolygon& inc = flip ? A : B;
  const std::size_t face = flip ? ib : ia;
  const Vec n = ref.normal(face), v1 = ref.v(face), v2 = ref.v(face + 1);
  // the incident face: the most anti-parallel to n
  std::size_t j = 0;
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < inc.n; ++k)
    if (const double d = dot(inc.normal(k), n); d < lowest) lowest = d, j = k;
  std::array<Vec, 2> pts{inc.v(j), inc.v(j + 1)};
  const Vec e = sub(v2, v1);
  const double len = std::hypot(e[0], e[1]);
  const Vec t{e[0] / len, e[1] / len};
  int count = clip(pts, 2, v1, t);
  count = clip(pts, count, v2, Vec{-t[0], -t[1]});
  if (count < 2) {  // degenerate: the incident polygon's deepest vertex alone
    double deepest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < inc.n; ++k)
      if (const double d = dot(sub(inc.v(k), v1), n); d < deepest) deepest = d, pts[0] = inc.v(k);
    count = 1;
  }
  ContactManifold m;
  m.count = count;
  m.nx = flip ? -n[0] : n[0], m.ny = flip ? -n[1] : n[1];
  for (int k = 0; k < count; ++k) {
    const Vec& p = pts[static_cast<std::size_t>(k)];
    const double gap = dot(sub(p, v1), n);
    const Vec q{p[0] - gap * n[0], p[1] - gap * n[1]};  // on the reference face
    ManifoldPoint& mp = m.points[static_cast<std::size_t>(k)];
    mp.gap = gap;
    const Vec& on_a = flip ? p : q;
    const Vec& on_b = flip ? q : p;
    mp.ax = on_a[0], mp.ay = on_a[1], mp.bx = on_b[0], mp.by = on_b[1];
  }
  return m;
}

// polygon-disc: the normal from the polygon to the disc and the one point
ContactManifold polygon_disc(const PolygonOutline& pp, const PlanarPose& a, double r,
                             const PlanarPose& b) {
  const WorldPolygon P(pp, a);
  const Vec c{b.x, b.y};
  double deepest = -std::numeric_limits<double>::infinity();
  std::size_t face = 0;
  for (std::size_t i = 0; i < P.n; ++i)
    if (const double s = dot(sub(c, P.v(i)), P.normal(i)); s > deepest) deepest = s, face = i;
  Vec n{}, q{};
  double distance = 0;
  if (deepest <= 0) {  // the centre inside: the face of least penetration
    n = P.normal(face);
    distance = deepest;
    q = {c[0] - deepest * n[0], c[1] - deepest * n[1]};
  } else {  // outside: the closest boundary point
    distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < P.n; ++i) {
      const Vec v = P.v(i), e = sub(P.v(i + 1), v);
      const double u = std::clamp(dot(sub(c, v), e) / dot(e, e), 0.0, 1.0);
      const Vec p{v[0] + u * e[0], v[1] + u * e[1]};
      if (const double d = std::hypot(c[0] - p[0], c[1] - p[1]); d < distance) distance = d, q = p;
    }
    n = {(c[0] - q[0]) / distance, (c[1] - q[1]) / distance};
  }
  ContactManifold m;
  m.count = 1;
  m.nx = n[0], m.ny = n[1];
  m.points[0] = {q[0], q[1], c[0] - r * n[0], c[1] - r * n[1], distance - r};
  return m;
}

ContactManifold discs(double ra, const PlanarPose& a, double rb, const PlanarPose& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, d = std::hypot(dx, dy);
  ContactManifold m;
  m.count = 1;
  if (d > 0) m.nx = dx / d, m.ny = dy / d;
  m.points[0] = {a.x + ra * m.nx, a.y + ra * m.ny, b.x - rb * m.nx, b.y - rb * m.ny, d - (ra + rb)};
  return m;
}

// The manifold with a and b exchanged: the normal turned round, each point's ends swapped.
ContactManifold swapped(ContactManifold m) {
  m.nx = -m.nx, m.ny = -m.ny;
  for (ManifoldPoint& p : m.points) std::swap(p.ax, p.bx), std::swap(p.ay, p.by);
  return m;
}

}  // namespace

PolygonOutline rectangle_outline(double length, double width) {
  const double a = length / 2, b = width / 2;
  return {{-a, a, a, -a}, {-b, -b, b, b}};
}

double ContactManifold::gap() const {
  double g = std::numeric_limits<double>::infinity();
  for (int k = 0; k < count; ++k) g = std::min(g, points[static_cast<std::size_t>(k)].gap);
  return g;
}

double outline_radius(const Outline& outline) {
  return std::visit(Overloaded{[](const NoOutline&) { return 0.0; },
                               [](const DiscOutline& d) { return d.radius; },
                               [](const PolygonOutline& p) {
                                 double r = 0;
                                 for (std::size_t i = 0; i < p.xs.size(); ++i)
                                   r = std::max(r, std::hypot(p.xs[i], p.ys[i]));
                                 return r;
                               }},
                    outline);
}

void validate(const Outline& outline) {
  std::visit(
      Overloaded{[](const NoOutline&) {},
                 [](const DiscOutline& d) {
                   if (!(d.radius > 0 && d.radius <= 1e50))
                     throw InvalidParameter("radius", d.radius, "must be in (0, 1e50]");
                 },
                 [](const PolygonOutline& p) {
                   const std::size_t n = p.xs.size();
                   if (p.ys.size() != n)
                     throw InvalidParameter("outline", std::to_string(p.ys.size()) + " y values",
                                            "needs one y per x (" + std::to_string(n) + ")");
                   if (n < 3)
                     throw InvalidParameter("outline", std::to_string(n) + " vertices",
                                            "a polygon needs at least 3");
                   for (std::size_t i = 0; i < n; ++i)
                     if (!(std::abs(p.xs[i]) <= 1e50 && std::abs(p.ys[i]) <= 1e50))
                       throw InvalidParameter("outline", "vertex " + std::to_string(i),
                                              "coordinates must be finite, |x|, |y| <= 1e50");
                   const double area = signed_area(p), size = outline_radius(p);
                   if (!(std::abs(area) > 1e-12 * size * size))
                     throw InvalidParameter("outline", area, "a polygon needs a non-zero area");
                   // convex: every vertex on the inner side of every face (or on it)
                   const double sign = area > 0 ? 1 : -1;
                   for (std::size_t i = 0; i < n; ++i) {
                     const std::size_t i1 = (i + 1) % n;
                     const Vec v{p.xs[i], p.ys[i]}, e{p.xs[i1] - p.xs[i], p.ys[i1] - p.ys[i]};
                     if (!(std::hypot(e[0], e[1]) > 1e-12 * size))
                       throw InvalidParameter("outline", "vertex " + std::to_string(i1),
                                              "repeats the vertex before it");
                     for (std::size_t j = 0; j < n; ++j)
                       if (sign * cross(e, sub(Vec{p.xs[j], p.ys[j]}, v)) < -1e-12 * size * size)
                         throw InvalidParameter("outline", "vertex " + std::to_string(j),
                                                "lies outside face " + std::to_string(i) +
                                                    ": the polygon must be convex");
                   }
                 }},
      outline);
}

ContactManifold contact_manifold(const Outline& a, const PlanarPose& pa, const Outline& b,
                                 const PlanarPose& pb) {
  return std::visit(
      Overloaded{[&](const DiscOutline& da, const DiscOutline& db) {
                   return discs(da.radius, pa, db.radius, pb);
                 },
                 [&](const PolygonOutline& qa, const DiscOutline& db) {
                   return polygon_disc(qa, pa, db.radius, pb);
                 },
                 [&](const DiscOutline& da, const PolygonOutline& qb) {
                   return swapped(polygon_disc(qb, pb, da.radius, pa));
                 },
                 [&](const PolygonOutline& qa, const PolygonOutline& qb) {
                   return polygons(qa, pa, qb, pb);
                 },
                 [](const auto&, const auto&) { return ContactManifold{}; }},
      a, b);
}

}  // namespace selfalign
