// The root box clip: where a ray's segment lies inside the k-d tree's box.
// (The slab test of T. L. Kay and J. T. Kajiya, "Ray tracing complex scenes", SIGGRAPH 1986, written so
// that direction components of +0 and -0 never produce 0 * inf.)
#include "strahl/ch03/traverse.hpp"

namespace strahl::ch03 {

namespace {
// Where the ray meets the plane x[axis] = p; exactly 0 when it starts in it.
float plane_t(float p, float o, float inv) { return p == o ? 0.0f : (p - o) * inv; }
}  // namespace

bool clip_to_box(const ray& r, const vec3& inv_dir, const aabb& box, float slack, float& t0, float& t1) {
    float enter = -inf, exit = inf;
    for (int a = 0; a < 3; ++a) {
        if (r.dir[a] == 0.0f) {
            // Parallel to this slab: inside it for every t, or never.
            if (r.org[a] < box.min[a] || r.org[a] > box.max[a]) return false;
            continue;
        }
        float ta = plane_t(box.min[a], r.org[a], inv_dir[a]);
        float tb = plane_t(box.max[a], r.org[a], inv_dir[a]);
        if (ta > tb) std::swap(ta, tb);
        enter = std::max(enter, ta);
        exit = std::min(exit, tb);
    }
    // Widened by the slack (a hit computed a rounding error outside the box is still found), then
    // clamped to the ray's own interval.
    t0 = std::max(r.tmin, enter - slack);
    t1 = std::min(r.tmax, exit + slack);
    return t0 <= t1;
}

}  // namespace strahl::ch03
