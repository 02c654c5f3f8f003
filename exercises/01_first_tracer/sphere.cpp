// Exercise 01.2 ray/sphere (5 points). Read: E. Haines, J. Guenther and T. Akenine-Moeller, "Precision
// Improvements for Ray/Sphere Intersection", Ray Tracing Gems, 2019.
#include "strahl/ch01/shapes.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch01 {

// Goal: return true and set t to the nearest root of |r.org + t r.dir - center| = radius with
// r.tmin < t < r.tmax. r.dir need not be normalised. From inside the sphere that is the far root. A NaN
// anywhere: no hit.
// Hint: take the discriminant as a (radius^2 - |l|^2), with l = f - (b / a) d the offset of the line's
// closest point from the centre (f = org - center), not as b^2 - a c.
// Why: why does b^2 - a c lose every digit for a small sphere far away, and why does the root pair c / q,
// q / a never subtract two nearly equal numbers?
// Step by step: HINTS.md, 01.2.
bool intersect_sphere(const ray& r, const vec3& center, float radius, float& t) {
    STRAHL_TODO("01.2 ray/sphere");
}

}  // namespace strahl::ch01
