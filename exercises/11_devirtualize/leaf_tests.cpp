// Exercises 11.1 (the variant's leaf test, 3 points) and 11.2 (the triangle test from precomputed edges,
// 4 points). Read: T. Moeller and B. Trumbore, "Fast, Minimum Storage Ray/Triangle Intersection", JGT 2(1),
// 1997; cppreference on std::visit.
#include "strahl/ch01/shapes.hpp"
#include "strahl/ch11/shapes.hpp"
#include "strahl/ch11/triangles.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch11 {

// Exercise 11.1: hand the shape to chapter 01's test of its type (intersect_triangle, intersect_sphere,
// intersect_plane in strahl/ch01/shapes.hpp) through std::visit. Spheres and planes set u = v = 0.
// Hint: a struct with one operator() per type is a visitor; so is a lambda taking `const auto&` together
// with `if constexpr (std::is_same_v<...>)`. No `if` on s.index() and no std::get: let std::visit dispatch.
// Why: std::visit jumps on the index stored beside each value; a virtual call loads a pointer, then a vtable. What
// can the compiler do with the jump that it cannot with the call, and why may a scene of triangles alone not care?
bool intersect(const shape& s, const ray& r, float& t, float& u, float& v) {
    STRAHL_TODO("11.1 the variant's leaf test");
}

// Exercise 11.2: exercise 01.3's test (solutions/01_first_tracer/triangle.cpp, or your own) starting
// from e1 = v1 - v0 and e2 = v2 - v0 instead of v1 and v2. Keep every step and every comparison as 01.3 has
// them, in the same order: the tests check the answers bit for bit against intersect_triangle.
// Why: e1 and e2 are the very floats 01.3 subtracts per test; why is that not enough: what would a dot product
// summed in another order, equal in exact arithmetic, change for a ray that grazes an edge?
bool intersect_edges(const ray& r, const vec3& v0, const vec3& e1, const vec3& e2, float& t, float& u, float& v) {
    STRAHL_TODO("11.2 the triangle test from precomputed edges");
}

}  // namespace strahl::ch11

// Steps 2, 5 and 6 compiled here, with the two functions above inlined into their walks.
#include "strahl/ch11/steps_impl.hpp"
