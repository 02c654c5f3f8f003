// Exercise 01.3 ray/triangle: T. Moeller and B. Trumbore, "Fast, Minimum Storage Ray/Triangle
// Intersection", Journal of Graphics Tools 2(1), 1997. Two-sided, no precomputed plane.
#include "strahl/ch01/shapes.hpp"

namespace strahl::ch01 {

bool intersect_triangle(const ray& r, const vec3& v0, const vec3& v1, const vec3& v2, float& t, float& u,
                        float& v) {
    // Step 1, the edges and the determinant: det = e1 . (d x e2). Zero for a ray parallel to the plane or
    // a degenerate triangle; NaN for a NaN ray. Either way: no hit. Its sign is ignored (two-sided).
    const vec3 e1 = v1 - v0;
    const vec3 e2 = v2 - v0;
    const vec3 p = glm::cross(r.dir, e2);
    const float det = glm::dot(e1, p);
    if (!(det != 0.0f)) return false;
    const float inv_det = 1.0f / det;
    // Step 2, the first barycentric: u = (org - v0) . p / det, inside when 0 <= u <= 1.
    const vec3 s = r.org - v0;
    const float bu = glm::dot(s, p) * inv_det;
    if (!(bu >= 0.0f && bu <= 1.0f)) return false;
    // Step 3, the second barycentric: v = d . q / det with q = s x e1, inside when v >= 0 and u + v <= 1.
    const vec3 q = glm::cross(s, e1);
    const float bv = glm::dot(r.dir, q) * inv_det;
    if (!(bv >= 0.0f && bu + bv <= 1.0f)) return false;
    // Step 4, the distance: t = e2 . q / det, accepted only in (tmin, tmax).
    const float bt = glm::dot(e2, q) * inv_det;
    if (!(bt > r.tmin && bt < r.tmax)) return false;
    t = bt;
    u = bu;
    v = bv;
    return true;
}

}  // namespace strahl::ch01
