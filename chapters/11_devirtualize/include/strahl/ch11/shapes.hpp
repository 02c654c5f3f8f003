// Step 2 of chapter 11: a closed set of primitive types. Chapter 01's primitives are classes behind a
// `virtual` intersect(); here they are plain values in a std::variant, one contiguous array, and the leaf
// test dispatches with std::visit: a jump on the held type's index, no pointer to chase, no call the
// compiler cannot see. The arithmetic is chapter 01's own free functions (exercises 01.2 and 01.3 and
// intersect_plane), so every answer equals brute force over chapter 01's objects bit for bit.
//   B. Stroustrup, "The C++ Programming Language", 4th ed., 2013, section 20.3 (the cost of virtual calls);
//   the std::variant of C++17 (P0088R3, A. Naumann, 2016).
#pragma once
#include "strahl/aabb.hpp"
#include "strahl/ray.hpp"
#include "strahl/scene.hpp"
#include <cstdint>
#include <variant>
#include <vector>

namespace strahl::ch11 {

// Three value types, no base class. A triangle keeps its unit normal (chapter 01's triangle computes it
// the same way in its constructor); a plane's normal is unit length (chapter 01 normalises it too).
struct triangle_shape {
    vec3 v0{0.0f}, v1{0.0f}, v2{0.0f};
    vec3 normal{0.0f, 0.0f, 1.0f};
};
struct sphere_shape {
    vec3 center{0.0f};
    float radius = 1.0f;
};
struct plane_shape {
    vec3 normal{0.0f, 1.0f, 0.0f};
    float offset = 0.0f;
};

// The closed set. Its index is the type: 0 triangle, 1 sphere, 2 plane (type-sorted leaves use it).
using shape = std::variant<triangle_shape, sphere_shape, plane_shape>;
inline constexpr int shape_types = 3;

// The scene's primitives in chapter 01's id order (world.hpp's build_world): the mesh's triangles, then,
// when `with_shapes`, its spheres and its planes. Throws std::invalid_argument for a sphere without a finite
// centre and a radius > 0, or a plane without a finite, non-zero normal (as build_world does).
std::vector<shape> make_shapes(const scene& s, bool with_shapes);
// Each primitive's material id, in the same order.
std::vector<std::uint32_t> make_material_ids(const scene& s, bool with_shapes);

triangle_shape make_triangle(const vec3& v0, const vec3& v1, const vec3& v2);

aabb bounds(const shape& s);                      // a plane's is infinite (the trees leave it loose)
vec3 normal_at(const shape& s, const vec3& p);    // unit, the shape's own side (chapter 01's convention)

// Exercise 11.1 (exercises/11_devirtualize/leaf_tests.cpp): the variant's leaf test. std::visit the shape
// and hand it to chapter 01's test of its type: intersect_triangle, intersect_sphere, intersect_plane
// (strahl/ch01/shapes.hpp). On a hit in (tmin, tmax) set t, and u, v (a triangle's barycentrics, 0 for
// spheres and planes), and return true; on a miss return false and leave t, u, v alone.
bool intersect(const shape& s, const ray& r, float& t, float& u, float& v);

}  // namespace strahl::ch11
