// Exercise 01.2 ray/sphere, with the precision improvements of E. Haines, J. Guenther and
// T. Akenine-Moeller, "Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems, 2019.
#include "strahl/ch01/shapes.hpp"

namespace strahl::ch01 {

bool intersect_sphere(const ray& r, const vec3& center, float radius, float& t) {
    // Step 1, the quadratic: |f + t d|^2 = radius^2 with f = org - center, i.e. a t^2 + 2 b t + c = 0.
    const vec3 f = r.org - center;
    const float a = glm::dot(r.dir, r.dir);
    const float b = glm::dot(f, r.dir);
    const float c = glm::dot(f, f) - radius * radius;
    // Step 2, a robust discriminant: b^2 - a c = a (radius^2 - |l|^2), l = f - (b / a) d the offset of the
    // line's closest point from the centre; no cancellation of two huge numbers for a far sphere.
    const vec3 l = f - (b / a) * r.dir;
    const float disc = a * (radius * radius - glm::dot(l, l));
    if (!(disc >= 0.0f)) return false;  // a miss, or a NaN somewhere
    // Step 3, the stable pair of roots: q = -(b + sign(b) sqrt(disc)), t0 = c / q, t1 = q / a; sign(b) is
    // +-1, never 0 (glm::sign(0) would make q = 0 for b = 0): copysign.
    const float q = -(b + std::copysign(std::sqrt(disc), b));
    float t0 = q != 0.0f ? c / q : 0.0f;
    float t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    // Step 4, the nearest root in (tmin, tmax): the near one, or the far one when the near one is behind
    // (the origin is inside the sphere).
    if (t0 > r.tmin && t0 < r.tmax) { t = t0; return true; }
    if (t1 > r.tmin && t1 < r.tmax) { t = t1; return true; }
    return false;
}

}  // namespace strahl::ch01
