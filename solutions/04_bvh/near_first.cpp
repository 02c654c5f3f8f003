// Exercise 04.3 near-first traversal. M. Pharr, W. Jakob and G. Humphreys, pbrt-v4, 2023, section 7.3.5
// (the ordered traversal of the flattened BVH).
#include "strahl/ch04/traverse.hpp"
#include <cmath>

namespace strahl::ch04 {

std::uint32_t near_first_traversal(const bvh& tree, const vec3& dir, box_hit_test box_hit, leaf_visit leaf) {
    if (tree.nodes.empty()) return 0;
    // Every push is a far child one level down, so the stack never holds more than the tree's depth.
    std::uint32_t stack[bvh_max_depth + 2];
    int top = 0;
    std::uint32_t index = 0, visited = 0;
    for (;;) {
        const bvh_node& n = tree.nodes[index];
        ++visited;
        // Step 1, the box: skip the node (and all below it) unless the ray still meets its box.
        if (box_hit(n)) {
            if (n.is_leaf()) {
                // Step 2, the leaf: its primitives, through the caller's test; true ends the walk.
                if (leaf(n.offset, std::uint32_t(n.count))) return visited;
            } else {
                // Step 3, near child first. Depth-first layout: the left child follows its parent, the right
                // one is named by offset. Going down the axis (sign bit set, -0 too), the right child (larger
                // coordinates) comes first. Descend into the near one, the far one onto the stack.
                const std::uint32_t left = index + 1, right = n.offset;
                const bool down = std::signbit(dir[n.axis]);
                stack[top++] = down ? left : right;
                index = down ? right : left;
                continue;
            }
        }
        // Step 4, the next node: the most recently deferred far child, until none is left.
        if (top == 0) return visited;
        index = stack[--top];
    }
}

}  // namespace strahl::ch04
