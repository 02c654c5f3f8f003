// Exercise 04.3 near child first. M. Pharr, W. Jakob and G. Humphreys, pbrt-v4, 2023, section 7.3.5 (the
// ordered traversal of the flattened BVH).
#include "strahl/ch04/traverse.hpp"
#include <cmath>

namespace strahl::ch04 {

child_order ordered_children(std::uint32_t index, const bvh_node& node, const vec3& dir) {
    // Depth-first layout: the left child follows its parent, the right one is named by offset.
    const std::uint32_t left = index + 1, right = node.offset;
    // Going down the axis (sign bit set, -0 too), the right child (larger coordinates) comes first.
    if (std::signbit(dir[node.axis])) return {right, left};
    return {left, right};
}

}  // namespace strahl::ch04
