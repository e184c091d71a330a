#pragma once
/// \file outline.hpp
/// The outline of a planar part (issue 24, docs/rows.md section 10): the convex shape other
/// parts cannot enter, in the part's body frame about its centre of mass. A closed set: none
/// (the part touches no other part), a disc, a convex polygon (a rectangle is one). Separate
/// from the contact patch (contact_patch.hpp), which is where the table's friction acts.
///
/// contact_manifold() is the contact detection between two outlines at given poses: the
/// normal, and one point (a disc on anything, a vertex on a face) or two (parallel faces:
/// the incident face clipped to the reference face, as in Box2D's b2CollidePolygons) with
/// their gaps. Signed distances are along the normal of the feature of least penetration
/// (separating-axis test), so a gap > 0 proves the outlines apart and a gap <= 0 measures the
/// overlap.

#include <array>
#include <variant>
#include <vector>

#include "selfalign/planar/rigid_part.hpp"

namespace selfalign {

/// No outline: the part has no contact with other parts.
struct NoOutline {};

/// A disc of `radius` [-] (> 0) about the centre of mass.
struct DiscOutline {
  double radius = 0;
};

/// A convex polygon, vertices in the body frame about the centre of mass [-], in order (either
/// orientation), at least 3, strictly convex or with collinear vertices, non-zero area.
struct PolygonOutline {
  std::vector<double> xs, ys;
};

/// The outline of a planar part (a closed set: visit it).
using Outline = std::variant<NoOutline, DiscOutline, PolygonOutline>;

/// A length x width rectangle centred on the centre of mass, length along the body x axis.
PolygonOutline rectangle_outline(double length, double width);

/// Throws InvalidParameter naming "radius" (a disc: in (0, 1e50]) or "outline" (a polygon with
/// fewer than 3 vertices, non-finite or huge coordinates, zero area, or not convex: naming
/// the vertex where it turns the other way).
void validate(const Outline& outline);

/// The largest distance of the outline from the centre of mass [-] (0: NoOutline).
double outline_radius(const Outline& outline);

/// One point of a contact manifold: where it lies on a's outline and on b's (world
/// coordinates [-]) and their gap along the normal (negative: overlap) [-].
struct ManifoldPoint {
  double ax = 0, ay = 0, bx = 0, by = 0;
  double gap = 0;
};

/// The contact between outlines a and b: the unit normal from a to b (world axes) and one or
/// two points. count = 0 when either outline is NoOutline.
struct ContactManifold {
  double nx = 1, ny = 0;
  int count = 0;
  std::array<ManifoldPoint, 2> points{};
  /// The smallest gap of the points (+infinity when count = 0) [-].
  double gap() const;
};

/// The manifold of outlines `a` and `b` at world poses `pa` and `pb`:
///   disc-disc      the line of centres (n = (1, 0) for coincident centres), one point;
///   disc-polygon   the polygon's closest boundary point to the centre (the face of least
///                  penetration when the centre is inside), one point;
///   polygon-polygon the separating axis of largest separation over both polygons' face
///                  normals (the reference face; a's face unless b's separates more by
///                  1e-12 of the outlines' size), the other polygon's most anti-parallel face
///                  (incident) clipped to the reference face's side planes: two points, one
///                  where a vertex meets a face inside the face's span.
/// Validated outlines only (validate()).
ContactManifold contact_manifold(const Outline& a, const PlanarPose& pa, const Outline& b,
                                 const PlanarPose& pb);

}  // namespace selfalign
