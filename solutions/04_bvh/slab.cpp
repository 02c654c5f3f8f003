// Exercise 04.1 the robust slab test. T. L. Kay and J. T. Kajiya, "Ray tracing complex scenes", SIGGRAPH
// 1986; made conservative as in M. Pharr, W. Jakob and G. Humphreys, pbrt-v4, 2023, section 6.8.
#include "strahl/ch04/traverse.hpp"
#include <cmath>

namespace strahl::ch04 {

bool slab_test(const aabb& box, const vec3& org, const vec3& inv_dir, float tmin, float tmax) {
    float t0 = tmin, t1 = tmax;
    for (int a = 0; a < 3; ++a) {
        // The slab's two planes in t, ordered entry first.
        float near = (box.min[a] - org[a]) * inv_dir[a];
        float far = (box.max[a] - org[a]) * inv_dir[a];
        // A NaN (0 * inf) means the origin lies on one of the slab's planes and the direction component is
        // +0 or -0: the ray runs in that plane, inside the closed slab for every t. No constraint.
        if (std::isnan(near) || std::isnan(far)) continue;
        if (near > far) std::swap(near, far);
        // Conservative: the exit pushed away from zero by the factor 1 + 2 gamma(3) (towards zero for a
        // negative exit: the factor 1 - 2 gamma(3)); +-inf stay as they are.
        far *= far > 0.0f ? 1.0f + 2.0f * gamma(3) : 1.0f - 2.0f * gamma(3);
        // Narrow the interval.
        if (near > t0) t0 = near;
        if (far < t1) t1 = far;
        if (t0 > t1) return false;
    }
    return true;
}

}  // namespace strahl::ch04
