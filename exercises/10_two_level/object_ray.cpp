// Exercise 10.1 the ray's object-space transform (4 points). Read: object_ray.hpp; pbrt-v4, section 7.1.5.
#include "strahl/ch10/object_ray.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch10 {

// Goal: the world ray r as the instance's mesh sees it: its origin and direction through to_object (the
// inverse of the instance's to_world), tmin and tmax as they are.
// Hint: affine has point() (with the translation) and vector() (without it); which one fits a direction?
// Why: why may the direction not be normalised after the transform, and why does a hit's t then need no
// conversion back to world space?
// Step by step: HINTS.md, 10.1.
ray to_object(const ray& r, const affine& to_object) {
    STRAHL_TODO("10.1 the ray's object-space transform");
}

}  // namespace strahl::ch10
