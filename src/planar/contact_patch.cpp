#include "selfalign/planar/contact_patch.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "selfalign/error.hpp"

namespace selfalign {
namespace {

int require_count(const char* name, int n, int hi) {
  if (n < 1 || n > hi)
    throw InvalidParameter(name, std::to_string(n), "must be in [1, " + std::to_string(hi) + "]");
  return n;
}

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Proper or touching intersection of segments pq and rs (collinear overlap included).
bool segments_meet(double px, double py, double qx, double qy, double rx, double ry, double sx,
                   double sy) {
  const auto orient = [](double ax, double ay, double bx, double by, double cx, double cy) {
    const double v = cross(bx - ax, by - ay, cx - ax, cy - ay);
    return (v > 0) - (v < 0);
  };
  const auto on = [](double ax, double ay, double bx, double by, double cx, double cy) {
    return std::min(ax, bx) <= cx && cx <= std::max(ax, bx) && std::min(ay, by) <= cy &&
           cy <= std::max(ay, by);
  };
  const int o1 = orient(px, py, qx, qy, rx, ry), o2 = orient(px, py, qx, qy, sx, sy);
  const int o3 = orient(rx, ry, sx, sy, px, py), o4 = orient(rx, ry, sx, sy, qx, qy);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && on(px, py, qx, qy, rx, ry)) || (o2 == 0 && on(px, py, qx, qy, sx, sy)) ||
         (o3 == 0 && on(rx, ry, sx, sy, px, py)) || (o4 == 0 && on(rx, ry, sx, sy, qx, qy));
}

void add_triangle(ContactPatch& out, const double* a, const double* b, const double* c, int n,
                  double area) {
  // n^2 congruent sub-triangles of the barycentric grid: the upward ones (i + j <= n - 1) and the
  // downward ones (i + j <= n - 2), each represented by its centroid.
  const double w = area / (static_cast<double>(n) * n);
  const auto point = [&](double u, double v) {
    const double s = 1 - u - v;
    out.push_back({s * a[0] + u * b[0] + v * c[0], s * a[1] + u * b[1] + v * c[1], w});
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      point((i + 1.0 / 3) / n, (j + 1.0 / 3) / n);
      if (i + j <= n - 2) point((i + 2.0 / 3) / n, (j + 2.0 / 3) / n);
    }
}

}  // namespace

ContactPatch point_patch() { return {ContactPoint{0, 0, 1}}; }

ContactPatch disc_patch(double radius, int rings, int sectors) {
  require_positive_moderate("radius", radius);
  require_count("rings", rings, 10000);
  require_count("sectors", sectors, 10000);
  if (static_cast<long long>(rings) * sectors > 1000000)
    throw InvalidParameter("rings", std::to_string(rings) + " x " + std::to_string(sectors) +
                           " sectors", "must give at most 1000000 points");
  ContactPatch out;
  out.reserve(static_cast<std::size_t>(rings) * sectors);
  const double dphi = 2 * std::numbers::pi / sectors;
  const double shrink = sectors == 1 ? 0.0 : std::sin(dphi / 2) / (dphi / 2);
  const double w = 1.0 / (static_cast<double>(rings) * sectors);
  for (int k = 0; k < rings; ++k) {
    const double ra = radius * std::sqrt(static_cast<double>(k) / rings);
    const double rb = radius * std::sqrt(static_cast<double>(k + 1) / rings);
    // centroid of the annular sector: (2/3)(rb^3 - ra^3)/(rb^2 - ra^2) sin(dphi/2)/(dphi/2)
    const double rc = 2.0 / 3.0 * (rb * rb * rb - ra * ra * ra) / (rb * rb - ra * ra) * shrink;
    for (int j = 0; j < sectors; ++j) {
      const double phi = (j + 0.5) * dphi + (k % 2) * 0.5 * dphi;  // staggered rings
      out.push_back({rc * std::cos(phi), rc * std::sin(phi), w});
    }
  }
  return out;
}

ContactPatch rectangle_patch(double length, double width, int nx, int ny) {
  require_positive_moderate("length", length);
  require_positive_moderate("width", width);
  require_count("nx", nx, 10000);
  require_count("ny", ny, 10000);
  if (static_cast<long long>(nx) * ny > 1000000)
    throw InvalidParameter("nx", std::to_string(nx) + " x " + std::to_string(ny),
                           "must give at most 1000000 points");
  ContactPatch out;
  const double w = 1.0 / (static_cast<double>(nx) * ny);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      out.push_back({length * ((i + 0.5) / nx - 0.5), width * ((j + 0.5) / ny - 0.5), w});
  return out;
}

ContactPatch polygon_patch(const std::vector<double>& xs, const std::vector<double>& ys,
                           int subdivisions) {
  require_count("subdivisions", subdivisions, 100);
  const std::size_t n = xs.size();
  if (ys.size() != n)
    throw InvalidParameter("polygon", std::to_string(xs.size()) + " x and " +
                                          std::to_string(ys.size()) + " y coordinates",
                           "needs as many y as x coordinates");
  if (n < 3)
    throw InvalidParameter("polygon", std::to_string(n) + " vertices", "needs at least 3 vertices");
  for (std::size_t i = 0; i < n; ++i) {
    require_moderate("polygon vertex x", xs[i]);
    require_moderate("polygon vertex y", ys[i]);
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const std::size_t i1 = (i + 1) % n, j1 = (j + 1) % n;
      if (j == i1 || i == j1) continue;  // adjacent edges share a vertex
      if (segments_meet(xs[i], ys[i], xs[i1], ys[i1], xs[j], ys[j], xs[j1], ys[j1]))
        throw InvalidParameter("polygon", "edges " + std::to_string(i) + " and " +
                                              std::to_string(j) + " intersect",
                               "must be a simple polygon (no self-intersection)");
    }
  double area2 = 0;
  for (std::size_t i = 0; i < n; ++i)
    area2 += cross(xs[i], ys[i], xs[(i + 1) % n], ys[(i + 1) % n]);
  double scale = 0;
  for (std::size_t i = 0; i < n; ++i) scale = std::max({scale, std::abs(xs[i]), std::abs(ys[i])});
  if (!(std::abs(area2) > 1e-12 * scale * scale))
    throw InvalidParameter("polygon", "area 0", "must enclose a non-zero area");
  // Ear clipping on the counter-clockwise vertex list.
  std::vector<std::array<double, 2>> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = {xs[i], ys[i]};
  if (area2 < 0) std::reverse(v.begin(), v.end());
  ContactPatch out;
  const double total = std::abs(area2) / 2;
  while (v.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < v.size() && !clipped; ++i) {
      const auto& a = v[(i + v.size() - 1) % v.size()];
      const auto& b = v[i];
      const auto& c = v[(i + 1) % v.size()];
      const double turn = cross(b[0] - a[0], b[1] - a[1], c[0] - b[0], c[1] - b[1]);
      if (turn <= 0) continue;  // reflex or straight: not an ear
      bool inside = false;
      for (std::size_t k = 0; k < v.size() && !inside; ++k) {
        const auto& p = v[k];
        if (&p == &a || &p == &b || &p == &c) continue;
        inside = cross(b[0] - a[0], b[1] - a[1], p[0] - a[0], p[1] - a[1]) >= 0 &&
                 cross(c[0] - b[0], c[1] - b[1], p[0] - b[0], p[1] - b[1]) >= 0 &&
                 cross(a[0] - c[0], a[1] - c[1], p[0] - c[0], p[1] - c[1]) >= 0;
      }
      if (inside) continue;
      add_triangle(out, a.data(), b.data(), c.data(), subdivisions, turn / 2 / total);
      v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) break;  // only collinear remainders: zero area left
  }
  if (v.size() == 3) {
    const double a3 = cross(v[1][0] - v[0][0], v[1][1] - v[0][1], v[2][0] - v[1][0],
                            v[2][1] - v[1][1]);
    if (a3 > 0) add_triangle(out, v[0].data(), v[1].data(), v[2].data(), subdivisions,
                             a3 / 2 / total);
  }
  double cx = 0, cy = 0, sum = 0;
  for (const auto& p : out) cx += p.load * p.x, cy += p.load * p.y, sum += p.load;
  for (auto& p : out) p.x -= cx / sum, p.y -= cy / sum, p.load /= sum;
  return out;
}

ContactPatch weighted_points_patch(const std::vector<double>& xs, const std::vector<double>& ys,
                                   const std::vector<double>& load_fractions) {
  if (xs.size() != ys.size() || xs.size() != load_fractions.size() || xs.empty())
    throw InvalidParameter("points", std::to_string(xs.size()) + " x, " +
                                         std::to_string(ys.size()) + " y, " +
                                         std::to_string(load_fractions.size()) + " loads",
                           "need the same number (>= 1) of x, y and load_fractions");
  ContactPatch out;
  for (std::size_t i = 0; i < xs.size(); ++i) out.push_back({xs[i], ys[i], load_fractions[i]});
  validate(out);
  std::erase_if(out, [](const ContactPoint& p) { return p.load == 0; });
  return out;
}

void validate(const ContactPatch& patch) {
  if (patch.empty()) throw InvalidParameter("points", "none", "need at least one contact point");
  double sum = 0, cx = 0, cy = 0, size = 0;
  for (const auto& p : patch) {
    require_moderate("point x", p.x);
    require_moderate("point y", p.y);
    if (!(p.load >= 0) || !std::isfinite(p.load))
      throw InvalidParameter("load_fractions", p.load, "must be >= 0 and finite");
    sum += p.load, cx += p.load * p.x, cy += p.load * p.y;
    size = std::max(size, std::hypot(p.x, p.y));
  }
  if (!(std::abs(sum - 1) <= 1e-9))
    throw InvalidParameter("load_fractions", "sum " + std::to_string(sum), "must sum to 1");
  if (!(std::hypot(cx, cy) <= 1e-9 * std::max(size, 1e-300)))
    throw InvalidParameter("load_fractions",
                           "load centre (" + std::to_string(cx) + ", " + std::to_string(cy) + ")",
                           "must be at the centre of mass (0, 0)");
}

double polar_moment(const ContactPatch& patch) {
  double j = 0;
  for (const auto& p : patch) j += p.load * (p.x * p.x + p.y * p.y);
  return j;
}

double patch_radius(const ContactPatch& patch) {
  double r = 0;
  for (const auto& p : patch) r = std::max(r, std::hypot(p.x, p.y));
  return r;
}

}  // namespace selfalign
