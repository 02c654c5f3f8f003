// ROTATE: one bottom-up pass of tree rotations over the whole tree.
//   A. Kensler, "Tree rotations for improving bounding volume hierarchies", IEEE Symposium on Interactive
//   Ray Tracing 2008.
// Steps, per inner node in post order (children before their parent):
//   1. REFIT the node (its height may have changed below it; its box cannot have: the same primitives);
//   2. EVALUATE the four rotations and APPLY the best one if it lowers the SAH cost (exercise 06.2).
// Post order lets a change made low in the tree be improved on by its ancestors within the same pass.
// Passes repeat (refine.cpp) until one applies no rotation: each applied rotation lowers the sum of inner
// areas strictly, so that fixed point is reached after finitely many passes.
#include "strahl/ch06/refine.hpp"

namespace strahl::ch06 {

namespace {

std::size_t rotate_below(refine_tree& t, std::uint32_t n, int depth, float c_traversal, int max_depth) {
    if (t.nodes[n].is_leaf()) return 0;
    // The children first. A rotation at a child rewrites the child's links, never the child itself, so
    // n's two links stay valid.
    std::size_t moves = rotate_below(t, t.nodes[n].left, depth + 1, c_traversal, max_depth);
    moves += rotate_below(t, t.nodes[n].right, depth + 1, c_traversal, max_depth);
    // Step 1, REFIT; step 2, EVALUATE and APPLY.
    t.refit(n);
    return moves + (apply_best_rotation(t, n, depth, max_depth, c_traversal).r != rotation::none ? 1 : 0);
}

}  // namespace

std::size_t rotation_pass(refine_tree& t, float c_traversal, int max_depth) {
    if (t.root == no_node) return 0;
    return rotate_below(t, t.root, 0, c_traversal, max_depth);
}

}  // namespace strahl::ch06
