// Exercise 06.1 the cost of one rotation. A. Kensler, "Tree rotations for improving bounding volume
// hierarchies", IEEE Symposium on Interactive Ray Tracing 2008, section 3 (the four rotations at a node).
#include "strahl/ch06/refine.hpp"

namespace strahl::ch06 {

float rotation_cost(const refine_tree& t, std::uint32_t n, rotation r, float c_traversal) {
    if (r == rotation::none) return 0.0f;
    const refine_node& x = t.nodes[n];
    // The side that loses a grandchild (the changed child) and the child of N that moves into it.
    const bool into_right = r == rotation::left_right_left || r == rotation::left_right_right;
    const refine_node& changed = t.nodes[into_right ? x.right : x.left];
    const refine_node& incoming = t.nodes[into_right ? x.left : x.right];
    if (changed.is_leaf()) return std::numeric_limits<float>::infinity();
    // The grandchild that stays: RR for L <-> RL, RL for L <-> RR, LR for R <-> LL, LL for R <-> LR.
    const bool takes_first = r == rotation::left_right_left || r == rotation::right_left_left;
    const refine_node& stays = t.nodes[takes_first ? changed.right : changed.left];
    // Only the changed child's box changes: its area, times C_T, is the SAH's change (times A(root)).
    return c_traversal * (unite(incoming.box, stays.box).surface_area() - changed.box.surface_area());
}

}  // namespace strahl::ch06
