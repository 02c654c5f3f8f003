// Clipping a triangle to a slab: the part of a triangle that lies between two planes perpendicular to an
// axis, as a box. Spatial splits need it twice: chopped binning (chopped_bins.hpp) boxes the part of each
// reference inside each bin, and the split itself boxes a straddling reference's two halves.
//   M. Stich, H. Friedrich and A. Dietrich, "Spatial splits in bounding volume hierarchies", HPG 2009,
//   section 3 (split the triangle, not its box: the halves' boxes are tighter);
//   I. E. Sutherland and G. W. Hodgman, "Reentrant polygon clipping", CACM 17(1), 1974 (the polygon clipper).
#pragma once
#include "strahl/aabb.hpp"

namespace strahl::ch09 {

// A triangle's three corners (the builder copies them out of the mesh once).
struct triangle {
    vec3 v0, v1, v2;
    aabb bounds() const { return aabb{}.grow(v0).grow(v1).grow(v2); }
};

// Exercise 09.1 "clip a triangle to a slab": the box of the part of triangle t whose coordinate on `axis`
// lies in [lo, hi] (lo <= hi; either may be -inf or +inf), intersected with `box` (the reference's current
// box: a reference split before is already only part of its triangle). The empty box (aabb{}) where no
// part of the triangle lies in the slab or the intersection with `box` is empty.
//   STEP 1, clip: the triangle as a polygon (3 corners), clipped against x[axis] >= lo, then against
//     x[axis] <= hi (Sutherland-Hodgman: walk the edges; keep the corners inside, add the point where an
//     edge crosses the plane, with x[axis] set to the plane's value exactly);
//   STEP 2, box: the box around the remaining corners (none: empty);
//   STEP 3, intersect: that box with `box`, per axis max of the minima and min of the maxima (empty if
//     any minimum exceeds its maximum).
// The box must contain the exact part: a coordinate computed by interpolation may be off by rounding, so
// compute the crossing points in double and round the box outwards to float (down for minima, up for
// maxima). Corners on a plane count as inside (a triangle lying in the plane is kept whole).
aabb clip_to_slab(const triangle& t, int axis, float lo, float hi, const aabb& box);

// The largest number of corners a triangle clipped by two parallel planes has: each plane adds one.
inline constexpr int max_clipped_corners = 5;

}  // namespace strahl::ch09
