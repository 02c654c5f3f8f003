// Exercise 04.1 the robust slab test (8 points). Read: T. L. Kay and J. T. Kajiya, "Ray tracing complex
// scenes", SIGGRAPH 1986; M. Pharr, W. Jakob and G. Humphreys, pbrt-v4, 2023, section 6.8 (the
// conservative version).
#include "strahl/ch04/traverse.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch04 {

// Goal: whether the ray org + t d (inv_dir = 1 / d) meets the closed box for some t in [tmin, tmax], never
// missing a box the exact ray touches: intersect the three slabs' [entry, exit] intervals with [tmin, tmax],
// the exit widened by pbrt's factor 1 + 2 gamma(3) (traverse.hpp has the full contract, +0, -0 and NaN).
// Hint: (box.min[a] - org[a]) * inv_dir[a] is NaN only when the origin lies on that plane and d[a] is a zero:
// the ray then runs inside the closed slab, so the axis can be skipped.
// Why: the exit is widened, not the entry; why is widening one side enough, and why must a negative exit
// move towards zero to be widened?
// Step by step: HINTS.md, 04.1.
bool slab_test(const aabb& box, const vec3& org, const vec3& inv_dir, float tmin, float tmax) {
    STRAHL_TODO("04.1 slab test");
}

}  // namespace strahl::ch04
