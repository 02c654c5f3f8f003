// Exercise 09.1 clip a triangle to a slab (6 points). Read: clip.hpp; M. Stich, H. Friedrich and
// A. Dietrich, "Spatial splits in bounding volume hierarchies", HPG 2009, section 3.
#include "strahl/ch09/clip.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch09 {

// Goal: the box of the part of t with lo <= x[axis] <= hi, intersected with `box`; the empty box aabb{}
// where nothing is left. Clip the triangle as a polygon against the plane x[axis] = lo (keep the side
// above), then against x[axis] = hi (keep the side below): walk each edge p -> q, keep p if it is inside,
// and add the crossing point where p and q lie on opposite sides, its x[axis] set to the plane exactly.
// An infinite lo or hi clips nothing. Then the box of the corners left, and its intersection with `box`.
// Hint: at most 5 corners remain (each plane adds one). Compute the corners in double and round the box
// outwards when converting back to float (std::nextafter where float(d) lands on the wrong side of d), so
// that it contains the exact part; a corner on a plane is inside.
// Why: why clip the triangle rather than its box: draw a long thin diagonal triangle, cut its box in two,
// and compare the two halves' boxes with the boxes of the triangle's two parts.
// Step by step: HINTS.md, 09.1.
aabb clip_to_slab(const triangle& t, int axis, float lo, float hi, const aabb& box) {
    STRAHL_TODO("09.1 clip a triangle to a slab");
}

}  // namespace strahl::ch09
