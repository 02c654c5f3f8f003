// Triangle/box overlap by separating axes: T. Akenine-Moeller, "Fast 3D Triangle-Box Overlap Testing",
// Journal of Graphics Tools 6(1), 2001. The box is moved to the origin; on each candidate axis the
// triangle's projection is compared with the box's projection radius.
#include "strahl/ch02/tri_box.hpp"
#include <algorithm>
#include <array>
#include <cmath>

namespace strahl::ch02 {

namespace {

// Whether axis separates the triangle (vertices relative to the box centre) from a box of half-size h.
bool separates(const vec3& axis, const std::array<vec3, 3>& v, const vec3& h) {
    const float p0 = glm::dot(axis, v[0]), p1 = glm::dot(axis, v[1]), p2 = glm::dot(axis, v[2]);
    const float r = h.x * std::abs(axis.x) + h.y * std::abs(axis.y) + h.z * std::abs(axis.z);
    return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
}

}  // namespace

bool triangle_overlaps_box(const vec3& v0, const vec3& v1, const vec3& v2, const aabb& b) {
    const vec3 c = b.centroid(), h = 0.5f * (b.max - b.min);
    const std::array<vec3, 3> v{v0 - c, v1 - c, v2 - c};
    // Step 1, the box's normals: the triangle's own box against the box.
    for (int a = 0; a < 3; ++a) {
        if (std::min({v[0][a], v[1][a], v[2][a]}) > h[a] || std::max({v[0][a], v[1][a], v[2][a]}) < -h[a])
            return false;
    }
    // Step 2, the nine cross products of the box's axes with the triangle's edges.
    const std::array<vec3, 3> e{v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    for (int a = 0; a < 3; ++a) {
        vec3 unit(0.0f);
        unit[a] = 1.0f;
        for (const vec3& edge : e)
            if (separates(glm::cross(unit, edge), v, h)) return false;
    }
    // Step 3, the triangle's plane (a zero normal, a degenerate triangle, separates nothing).
    return !separates(glm::cross(e[0], e[1]), v, h);
}

}  // namespace strahl::ch02
