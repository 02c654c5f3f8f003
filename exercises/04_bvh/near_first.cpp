// Exercise 04.3 near-first traversal (10 points). Read: M. Pharr, W. Jakob and G. Humphreys, pbrt-v4,
// 2023, section 7.3.5 (the ordered traversal of the flattened BVH).
#include "strahl/ch04/traverse.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch04 {

// Goal: walk tree.nodes from the root (index 0) with a stack of node indices, visiting every node whose
// box box_hit(node) accepts, near child first; hand each accepted leaf to leaf(node.offset, node.count) and
// stop at once if it returns true. Return the number of nodes visited (box_hit calls). Depth-first layout:
// an inner node's left child is index + 1, its right child node.offset. The left child is near when
// dir[node.axis] has its sign bit clear (+0 too), the right one when it is set (-0 too: std::signbit).
// Hint: a fixed array std::uint32_t stack[bvh_max_depth + 2] is enough: each push is a far child one level
// further down.
// Why: a closest-hit leaf test shrinks the ray's tmax, which box_hit reads. Why does visiting the near
// child first make later box tests fail more often, and why must the walk still not stop at the first hit?
// Step by step: HINTS.md, 04.3.
std::uint32_t near_first_traversal(const bvh& tree, const vec3& dir, box_hit_test box_hit, leaf_visit leaf) {
    STRAHL_TODO("04.3 near-first traversal");
}

}  // namespace strahl::ch04
