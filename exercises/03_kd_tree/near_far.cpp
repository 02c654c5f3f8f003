// Exercise 03.3 near/far order and the t-split rule (7 points). Read: V. Havran, "Heuristic Ray Shooting
// Algorithms", PhD thesis, Czech Technical University, 2000 (chapter 4, the recursive traversal).
#include "strahl/ch03/traverse.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch03 {

// The ray's segment [t0, t1] lies in a node split at `split` on `axis`. Return the children it enters, in
// the order it enters them (child 0 = left, below the plane; 1 = right), each with its part of [t0, t1]:
//   d = r.dir[axis] == 0 (+0 or -0): the ray stays on its origin's side: left if org < split, right if
//     org > split, both (left first, each with the whole [t0, t1]) if org == split. No division here.
//   otherwise t_split = (split - org) * inv_dir[axis], but exactly 0 when org == split (0 * inf is NaN);
//     lo = t_split - slack, hi = t_split + slack;
//     near = left if d > 0, else right; far = the other;
//     near gets [t0, min(t1, hi)], far gets [max(t0, lo), t1]; a child whose range is empty (start > end)
//     is not visited. (So a plane behind the ray or beyond t1 gives one child only.)
child_visit near_far(const ray& r, const vec3& inv_dir, int axis, float split, float t0, float t1, float slack) {
    STRAHL_TODO("03.3 near/far and t-split");
}

}  // namespace strahl::ch03
