// Exercise 01.3 ray/triangle (6 points). Read: T. Moeller and B. Trumbore, "Fast, Minimum Storage
// Ray/Triangle Intersection", Journal of Graphics Tools 2(1), 1997.
#include "strahl/ch01/shapes.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch01 {

// Return true and set t, u, v when r hits triangle (v0, v1, v2) from either side (two-sided) with
// r.tmin < t < r.tmax; the hit point is (1-u-v) v0 + u v1 + v v2, and edges and vertices count as inside
// (u >= 0, v >= 0, u + v <= 1). Degenerate triangles, rays parallel to the plane, NaN rays: no hit.
// This is "the same triangle test" every later chapter compares with.
//   Step 1, the edges and the determinant: e1 = v1 - v0, e2 = v2 - v0, p = d x e2, det = e1 . p;
//           det == 0 (or NaN): no hit. Do not reject negative det: the test is two-sided. Do not use the
//           paper's absolute EPSILON (1e-6) either: det scales with the triangle's area, and the bunny's
//           small triangles would fall through it (the raster oracle test checks that).
//   Step 2, the first barycentric: s = org - v0, u = (s . p) / det; outside [0, 1]: no hit.
//   Step 3, the second barycentric: q = s x e1, v = (d . q) / det; v < 0 or u + v > 1: no hit.
//   Step 4, the distance: t = (e2 . q) / det, accepted only in (tmin, tmax).
bool intersect_triangle(const ray& r, const vec3& v0, const vec3& v1, const vec3& v2, float& t, float& u,
                        float& v) {
    STRAHL_TODO("01.3 ray/triangle");
}

}  // namespace strahl::ch01
