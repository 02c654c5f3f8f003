// Exercise 04.1 the robust slab test (8 points). Read: T. L. Kay and J. T. Kajiya, "Ray tracing complex
// scenes", SIGGRAPH 1986; M. Pharr, W. Jakob and G. Humphreys, pbrt-v4, 2023, section 6.8 (the
// conservative version).
#include "strahl/ch04/traverse.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch04 {

// Does the ray org + t d meet the closed box for some t in [tmin, tmax]? (inv_dir = 1 / d.)
//   start with the interval [t0, t1] = [tmin, tmax];
//   per axis a: near = (box.min[a] - org[a]) * inv_dir[a], far = (box.max[a] - org[a]) * inv_dir[a];
//     if either is NaN (0 * inf: the origin lies on that plane and d[a] is +0 or -0, so the ray runs in the
//     plane, inside the closed slab for every t), skip this axis;
//     swap them if near > far;
//     widen the exit toward +inf (later): far *= 1 + 2 * gamma(3) if far > 0, else 1 - 2 * gamma(3) (a
//     negative exit moves toward zero; +-inf stay);
//     t0 = max(t0, near); t1 = min(t1, far);
//     miss as soon as t0 > t1.
bool slab_test(const aabb& box, const vec3& org, const vec3& inv_dir, float tmin, float tmax) {
    STRAHL_TODO("04.1 slab test");
}

}  // namespace strahl::ch04
