// Exercise 01.2 ray/sphere (5 points). Read: E. Haines, J. Guenther and T. Akenine-Moeller, "Precision
// Improvements for Ray/Sphere Intersection", Ray Tracing Gems, 2019.
#include "strahl/ch01/shapes.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch01 {

// Return true and set t to the nearest root of |r.org + t r.dir - center| = radius with r.tmin < t < r.tmax.
// r.dir need not be normalised. From inside the sphere that is the far root. A NaN anywhere: no hit.
//   Step 1, the quadratic: f = org - center; a t^2 + 2 b t + c = 0 with a = d.d, b = f.d, c = f.f - radius^2.
//   Step 2, a robust discriminant: b^2 - a c = a (radius^2 - |l|^2) with l = f - (b / a) d; negative: miss.
//   Step 3, the stable pair of roots: q = -(b + sign(b) sqrt(disc)), t0 = c / q, t1 = q / a (sort them).
//     sign(b) is +1 or -1, never 0: std::copysign(sqrt(disc), b) (glm::sign(0) is 0, and q = 0 for b = 0).
//   Step 4, the nearest root in (tmin, tmax): t0 if it lies there, else t1, else no hit.
bool intersect_sphere(const ray& r, const vec3& center, float radius, float& t) {
    STRAHL_TODO("01.2 ray/sphere");
}

}  // namespace strahl::ch01
