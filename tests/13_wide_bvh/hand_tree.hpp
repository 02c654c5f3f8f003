// A binary tree made by hand for chapter 13's collapse tests (both the graded greedy one and the optimal one).
#pragma once
#include "strahl/ch04/bvh.hpp"
#include "strahl/scene.hpp"

namespace strahl::test {

inline ch04::bvh_node node(vec3 lo, vec3 hi, std::uint32_t offset, std::uint16_t count) {
    ch04::bvh_node n{};
    for (int a = 0; a < 3; ++a) n.bmin[a] = lo[a], n.bmax[a] = hi[a];
    n.offset = offset;
    n.count = count;
    return n;
}

// A binary tree made by hand over 6 triangles, depth first (left child = next node):
//   root (0) -> A (1, box [0,8]^3, area 384) and B (6, [8,16]x[0,2]x[0,2], area 72);
//   A -> leaf A1 (2, triangle 0) and A2 (3, [0,7]^3, area 294) -> leaves 4 (triangle 1) and 5 (triangle 2);
//   B -> leaves 7 (triangles 3 and 4) and 8 (triangle 5).
// The greedy collapse into 4 children opens A (384 > 72), then A2 (294 > 72): {A1, B, 4, 5}.
inline ch04::bvh hand_tree() {
    ch04::bvh t;
    t.bounds = aabb{vec3(0), vec3(16)};
    t.nodes = {
        node(vec3(0), vec3(16), 6, 0),                            // 0 root: left 1, right 6
        node(vec3(0), vec3(8), 3, 0),                             // 1 A: left 2, right 3
        node(vec3(0), vec3(1), 0, 1),                             // 2 A1: tri 0
        node(vec3(0), vec3(7), 5, 0),                             // 3 A2: left 4, right 5
        node(vec3(0), vec3(1), 1, 1),                             // 4: tri 1
        node(vec3(6), vec3(7), 2, 1),                             // 5: tri 2
        node(vec3(8, 0, 0), vec3(16, 2, 2), 8, 0),                // 6 B: left 7, right 8
        node(vec3(8, 0, 0), vec3(9, 1, 1), 3, 2),                 // 7: tris 3, 4
        node(vec3(9, 0, 0), vec3(10, 1, 1), 5, 1),                // 8: tri 5
    };
    t.prim_ids = {0, 1, 2, 3, 4, 5};
    return t;
}

inline triangle_mesh six_triangles() {
    triangle_mesh m;
    for (int i = 0; i < 6; ++i) {
        const float x = float(i);
        const auto b = std::uint32_t(m.positions.size());
        m.positions.insert(m.positions.end(), {vec3(x, 0, 0), vec3(x + 1, 0, 0), vec3(x, 1, 1)});
        m.indices.push_back(uvec3(b, b + 1, b + 2));
    }
    return m;
}

}  // namespace strahl::test
