// Exercise 01.3 ray/triangle (6 points). Read: T. Moeller and B. Trumbore, "Fast, Minimum Storage
// Ray/Triangle Intersection", Journal of Graphics Tools 2(1), 1997.
#include "strahl/ch01/shapes.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch01 {

// Goal: return true and set t, u, v when r hits triangle (v0, v1, v2) from either side (two-sided) with
// r.tmin < t < r.tmax; the hit point is (1-u-v) v0 + u v1 + v v2, and edges and vertices count as inside
// (u >= 0, v >= 0, u + v <= 1). Degenerate triangles, rays parallel to the plane, NaN rays: no hit.
// This is "the same triangle test" every later chapter compares with.
// Hint: Moeller-Trumbore needs two cross products (d x e2 and s x e1) and four dot products, each dot
// product divided by one determinant.
// Why: why would the paper's test |det| < 1e-6 punch holes into the bunny but not into the Cornell box?
// Step by step: HINTS.md, 01.3.
bool intersect_triangle(const ray& r, const vec3& v0, const vec3& v1, const vec3& v2, float& t, float& u,
                        float& v) {
    STRAHL_TODO("01.3 ray/triangle");
}

}  // namespace strahl::ch01
