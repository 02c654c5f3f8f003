// Steps 4 to 6 of chapter 11: triangles only. A scene made of triangles needs no type at all: the leaf
// holds triangles, stored in the order the tree's leaves list them (leaf k's triangles are slots
// [first, first + count): no index array to go through), each with its two edges precomputed, so the test
// starts from what Moeller and Trumbore compute first. Spheres and planes, where a scene has them, are
// traced beside the tree by a loop of their own.
//   T. Moeller and B. Trumbore, "Fast, Minimum Storage Ray/Triangle Intersection", JGT 2(1), 1997;
//   I. Wald, "Realtime Ray Tracing and Interactive Global Illumination", PhD thesis, Saarland University,
//   2004, section 7.1 (precomputed triangle data laid out for the test).
#pragma once
#include "strahl/ray.hpp"
#include <cstdint>
#include <vector>

namespace strahl::ch11 {

// Array of structures (steps 4 and 5): one triangle in 36 bytes, v0 and the edges e1 = v1 - v0 and
// e2 = v2 - v0. The subtractions are the ones exercise 01.3 makes per test, so their floats are the same.
struct edge_triangle {
    vec3 v0{0.0f}, e1{0.0f}, e2{0.0f};
};
static_assert(sizeof(edge_triangle) == 36, "three vec3, no padding");

inline edge_triangle make_edge_triangle(const vec3& v0, const vec3& v1, const vec3& v2) { return {v0, v1 - v0, v2 - v0}; }

// Structure of arrays (step 6): the same nine numbers per triangle, each in an array of its own: v0's x of
// every triangle, then v0's y, ... A leaf's triangles are then nine short runs of consecutive floats.
struct edge_triangles_soa {
    std::vector<float> c[9];  // v0.x v0.y v0.z e1.x e1.y e1.z e2.x e2.y e2.z

    std::size_t size() const { return c[0].size(); }
    void push_back(const edge_triangle& t) {
        const float f[9] = {t.v0.x, t.v0.y, t.v0.z, t.e1.x, t.e1.y, t.e1.z, t.e2.x, t.e2.y, t.e2.z};
        for (int k = 0; k < 9; ++k) c[k].push_back(f[k]);
    }
    edge_triangle operator[](std::size_t i) const {
        return {vec3(c[0][i], c[1][i], c[2][i]), vec3(c[3][i], c[4][i], c[5][i]), vec3(c[6][i], c[7][i], c[8][i])};
    }
    std::size_t memory_bytes() const { return 9 * size() * sizeof(float); }
};

// Exercise 11.2 (exercises/11_devirtualize/leaf_tests.cpp): exercise 01.3's test from precomputed edges.
// The same steps in the same order (determinant, u, v, t) and the same rules (two-sided; u >= 0, v >= 0,
// u + v <= 1; tmin < t < tmax; degenerate triangles, parallel and NaN rays: no hit), so the answers equal
// intersect_triangle(r, v0, v0 + e1, v0 + e2, ...)'s bit for bit whenever v1 - v0 == e1 and v2 - v0 == e2.
bool intersect_edges(const ray& r, const vec3& v0, const vec3& e1, const vec3& e2, float& t, float& u, float& v);

}  // namespace strahl::ch11
