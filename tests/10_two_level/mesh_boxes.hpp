// What chapter 10's tests build trees from: a mesh's triangle boxes and their centroids.
#pragma once
#include "strahl/scene.hpp"
#include <vector>

namespace strahl::test {

inline std::vector<aabb> boxes_of(const triangle_mesh& m) {
    std::vector<aabb> b(m.triangle_count());
    for (std::size_t i = 0; i < b.size(); ++i) {
        const auto t = m.triangle(i);
        b[i].grow(t[0]).grow(t[1]).grow(t[2]);
    }
    return b;
}

inline std::vector<vec3> centroids_of(const std::vector<aabb>& b) {
    std::vector<vec3> c(b.size());
    for (std::size_t i = 0; i < b.size(); ++i) c[i] = b[i].centroid();
    return c;
}

}  // namespace strahl::test
