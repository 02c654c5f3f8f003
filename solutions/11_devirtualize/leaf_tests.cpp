// Exercises 11.1 (the variant's leaf test, 3 points) and 11.2 (the triangle test from precomputed edges,
// 4 points). Read: T. Moeller and B. Trumbore, "Fast, Minimum Storage Ray/Triangle Intersection", JGT 2(1),
// 1997; cppreference on std::visit.
#include "strahl/ch01/shapes.hpp"
#include "strahl/ch11/shapes.hpp"
#include "strahl/ch11/triangles.hpp"

namespace strahl::ch11 {

// Exercise 11.1: one overload per type, std::visit picks it from the variant's index.
bool intersect(const shape& s, const ray& r, float& t, float& u, float& v) {
    struct visitor {
        const ray& r;
        float &t, &u, &v;
        bool operator()(const triangle_shape& tri) const { return ch01::intersect_triangle(r, tri.v0, tri.v1, tri.v2, t, u, v); }
        bool operator()(const sphere_shape& sp) const {
            if (!ch01::intersect_sphere(r, sp.center, sp.radius, t)) return false;
            u = v = 0.0f;
            return true;
        }
        bool operator()(const plane_shape& pl) const {
            if (!ch01::intersect_plane(r, pl.normal, pl.offset, t)) return false;
            u = v = 0.0f;
            return true;
        }
    };
    return std::visit(visitor{r, t, u, v}, s);
}

// Exercise 11.2: exercise 01.3's four steps, the edges given.
bool intersect_edges(const ray& r, const vec3& v0, const vec3& e1, const vec3& e2, float& t, float& u, float& v) {
    // Step 1, the determinant: det = e1 . (d x e2); zero or NaN: no hit.
    const vec3 p = glm::cross(r.dir, e2);
    const float det = glm::dot(e1, p);
    if (!(det != 0.0f)) return false;
    const float inv_det = 1.0f / det;
    // Step 2, u = (org - v0) . p / det in [0, 1].
    const vec3 s = r.org - v0;
    const float bu = glm::dot(s, p) * inv_det;
    if (!(bu >= 0.0f && bu <= 1.0f)) return false;
    // Step 3, v = d . (s x e1) / det, v >= 0 and u + v <= 1.
    const vec3 q = glm::cross(s, e1);
    const float bv = glm::dot(r.dir, q) * inv_det;
    if (!(bv >= 0.0f && bu + bv <= 1.0f)) return false;
    // Step 4, t = e2 . q / det in (tmin, tmax).
    const float bt = glm::dot(e2, q) * inv_det;
    if (!(bt > r.tmin && bt < r.tmax)) return false;
    t = bt;
    u = bu;
    v = bv;
    return true;
}

}  // namespace strahl::ch11

// Steps 2, 5 and 6 compiled here, with the two functions above inlined into their walks.
#include "strahl/ch11/steps_impl.hpp"
