// Exercise 03.3 near/far order and the t-split rule (7 points). Read: V. Havran, "Heuristic Ray Shooting
// Algorithms", PhD thesis, Czech Technical University, 2000 (chapter 4, the recursive traversal).
#include "strahl/ch03/traverse.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch03 {

// Goal: the ray's segment [t0, t1] lies in a node split at `split` on `axis`. Return the children it
// enters, in the order it enters them (child 0 = left, below the plane; 1 = right), each with its part of
// [t0, t1], the crossing widened by `slack` on both sides; a child whose part is empty is not visited.
// Hint: a direction component of +0 or -0 needs no division: the ray stays on its origin's side, and one
// lying in the plane visits both children (left first) with the whole [t0, t1].
// Why: why widen the crossing by slack instead of cutting [t0, t1] exactly at t_split: what could a
// triangle lying in the split plane, or a rounded t_split, make the walk miss?
// Step by step: HINTS.md, 03.3.
child_visit near_far(const ray& r, const vec3& inv_dir, int axis, float split, float t0, float t1, float slack) {
    STRAHL_TODO("03.3 near/far and t-split");
}

}  // namespace strahl::ch03
