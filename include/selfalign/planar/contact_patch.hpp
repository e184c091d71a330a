#pragma once
/// \file contact_patch.hpp
/// The flat contact patch of a rigid part (issue 13): weighted contact points in the part's body
/// frame, centred on the centre of mass. Each point carries its load fraction w_i (its share of
/// the normal load m g): the points are where friction acts, the fractions how much.
///
/// Uniform pressure over a disc, a rectangle or a polygon is turned into points by quadrature
/// (equal-area cells, each represented by its centroid, weight = area fraction), so that the
/// total load is 1 and the load centre is the shape's centroid. A part lying flat on a table is
/// in moment balance about horizontal axes only when its centre of mass is above that load
/// centre, so shapes are expressed about their centroid, and user points must have their load
/// centre at the origin (the centre of mass).

#include <vector>

namespace selfalign {

/// One contact point: body-frame position relative to the centre of mass [-] and its load
/// fraction w [-] (share of m g).
struct ContactPoint {
  double x = 0, y = 0;
  double load = 1;
  friend bool operator==(const ContactPoint&, const ContactPoint&) = default;
};

/// The contact points of a part; their loads sum to 1.
using ContactPatch = std::vector<ContactPoint>;

/// A single point at the centre of mass (the point contact of planar_point.hpp).
ContactPatch point_patch();

/// Uniform pressure over a disc of radius r: `rings` equal-area annuli, `sectors` equal sectors
/// each, one point per cell at its centroid (weight 1/(rings sectors)). r finite > 0, rings and
/// sectors in [1, 10000]. The cells' centroids give the exact polar moment sum w_i |p_i|^2 to
/// O(1/rings^2) of r^2/2.
ContactPatch disc_patch(double radius, int rings, int sectors);

/// Uniform pressure over a length x width rectangle centred on the origin (length along the
/// body x axis), nx by ny equal cells, one point per cell centre.
ContactPatch rectangle_patch(double length, double width, int nx, int ny);

/// Uniform pressure over a simple polygon (vertices in order, either orientation; at least 3,
/// not self-intersecting, non-zero area). The polygon is triangulated by ear clipping, each
/// triangle split into n^2 congruent sub-triangles (n = subdivisions, in [1, 100]) represented by
/// their centroids, and the points shifted so that the area centroid is the origin. Throws
/// InvalidParameter naming "polygon" for fewer than 3 vertices, a self-intersection (naming
/// the two edges) or zero area.
ContactPatch polygon_patch(const std::vector<double>& xs, const std::vector<double>& ys,
                           int subdivisions);

/// User points with load fractions: finite positions, fractions >= 0 summing to 1 (to 1e-9),
/// and the load centre sum w_i p_i at the origin (to 1e-9 of the patch size). Points with zero
/// load are dropped. Throws InvalidParameter naming "load_fractions" or "points".
ContactPatch weighted_points_patch(const std::vector<double>& xs, const std::vector<double>& ys,
                                   const std::vector<double>& load_fractions);

/// Throws InvalidParameter unless the patch is non-empty, its points finite and moderate, its
/// loads >= 0 summing to 1 with their centre at the origin (the checks of weighted_points_patch).
void validate(const ContactPatch& patch);

/// sum w_i |p_i|^2 [-]: the patch's polar moment per unit load (r^2/2 for a uniform disc).
double polar_moment(const ContactPatch& patch);

/// The largest |p_i| [-].
double patch_radius(const ContactPatch& patch);

}  // namespace selfalign
