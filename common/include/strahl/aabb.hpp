// Axis-aligned bounding box. The empty box has min = +inf and max = -inf, so growing it by anything
// gives that thing's box, and the union of empty boxes stays empty.
#pragma once
#include "strahl/math.hpp"
#include <algorithm>

namespace strahl {

struct aabb {
    vec3 min{inf};
    vec3 max{-inf};

    static aabb empty() { return {}; }
    static aabb from_points(const vec3& a, const vec3& b) { return {glm::min(a, b), glm::max(a, b)}; }

    bool is_empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }

    aabb& grow(const vec3& p) { min = glm::min(min, p); max = glm::max(max, p); return *this; }
    aabb& grow(const aabb& b) { min = glm::min(min, b.min); max = glm::max(max, b.max); return *this; }

    // Size along each axis; zero for the empty box.
    vec3 extent() const { return is_empty() ? vec3(0.0f) : max - min; }
    vec3 centroid() const { return 0.5f * (min + max); }
    // Surface area 2 (xy + yz + zx); zero for the empty box and for points.
    float surface_area() const {
        const vec3 e = extent();
        return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
    int largest_axis() const { return max_axis(extent()); }
    bool contains(const vec3& p) const {
        return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z && p.z <= max.z;
    }
};

inline aabb unite(const aabb& a, const aabb& b) { aabb r = a; return r.grow(b); }

}  // namespace strahl
