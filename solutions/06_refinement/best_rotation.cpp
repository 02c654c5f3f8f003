// Exercise 06.2 the best rotation at a node, applied. A. Kensler, "Tree rotations for improving bounding
// volume hierarchies", IEEE Symposium on Interactive Ray Tracing 2008, section 3 (evaluate the four
// rotations, take the one that lowers the SAH cost most).
#include "strahl/ch06/refine.hpp"

namespace strahl::ch06 {

rotation_choice apply_best_rotation(refine_tree& t, std::uint32_t n, int depth, int max_depth, float c_traversal) {
    const std::uint32_t l = t.nodes[n].left, r = t.nodes[n].right;
    rotation_choice best;
    for (const rotation rot : {rotation::left_right_left, rotation::left_right_right, rotation::right_left_left,
                               rotation::right_left_right}) {
        // The changed child, the child of n that moves down into it, the grandchild that stays.
        const bool into_right = rot == rotation::left_right_left || rot == rotation::left_right_right;
        const std::uint32_t changed = into_right ? r : l, incoming = into_right ? l : r;
        if (t.nodes[changed].is_leaf()) continue;
        // The depth bound: the incoming subtree ends up two levels below n.
        if (depth + 2 + t.nodes[incoming].height > max_depth) continue;
        const bool takes_first = rot == rotation::left_right_left || rot == rotation::right_left_left;
        const std::uint32_t stays = takes_first ? t.nodes[changed].right : t.nodes[changed].left;
        // The cost change (exercise 06.1's formula, written out: each exercise is graded on its own).
        const float delta = c_traversal * (unite(t.nodes[incoming].box, t.nodes[stays].box).surface_area() -
                                           t.nodes[changed].box.surface_area());
        if (delta < best.delta) best = {rot, delta};
    }
    if (best.r == rotation::none) return best;
    // Apply: the incoming child and the grandchild that leaves trade places; refit the changed child, then n.
    const bool into_right = best.r == rotation::left_right_left || best.r == rotation::left_right_right;
    const std::uint32_t changed = into_right ? r : l, incoming = into_right ? l : r;
    const bool takes_first = best.r == rotation::left_right_left || best.r == rotation::right_left_left;
    const std::uint32_t leaves = takes_first ? t.nodes[changed].left : t.nodes[changed].right;
    t.replace_child(n, incoming, leaves);
    t.replace_child(changed, leaves, incoming);
    t.refit(changed);
    t.refit(n);
    return best;
}

}  // namespace strahl::ch06
