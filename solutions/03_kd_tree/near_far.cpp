// Exercise 03.3 near/far order and the t-split rule. V. Havran, "Heuristic Ray Shooting Algorithms", PhD
// thesis, Czech Technical University, 2000 (chapter 4, the recursive traversal).
#include "strahl/ch03/traverse.hpp"

namespace strahl::ch03 {

child_visit near_far(const ray& r, const vec3& inv_dir, int axis, float split, float t0, float t1, float slack) {
    child_visit v;
    const auto add = [&v](int child, float a, float b) {
        if (!(a <= b)) return;  // the segment does not reach this child
        v.child[v.count] = std::uint8_t(child);
        v.t0[v.count] = a;
        v.t1[v.count] = b;
        ++v.count;
    };
    const float o = r.org[axis], d = r.dir[axis];
    // A ray parallel to the plane (d = +0 or -0) stays on its origin's side; one lying in the plane
    // touches both children along its whole segment. No 0 * inf here.
    if (d == 0.0f) {
        if (o <= split) add(0, t0, t1);
        if (o >= split) add(1, t0, t1);
        return v;
    }
    // The t-split: where the ray crosses the plane (exactly 0 when it starts on it: no 0 * inf).
    const float t_split = o == split ? 0.0f : (split - o) * inv_dir[axis];
    const float lo = t_split - slack, hi = t_split + slack;
    // Near/far by the direction's sign: going up the axis, the ray is left of the plane before t_split
    // and right of it after; going down, the other way round. Each child gets its part of [t0, t1].
    const int near_child = d > 0.0f ? 0 : 1;
    add(near_child, t0, std::min(t1, hi));
    add(1 - near_child, std::max(t0, lo), t1);
    return v;
}

}  // namespace strahl::ch03
