// Exercise 06.2 the best rotation at a node, applied (10 points). Read: A. Kensler, "Tree rotations for
// improving bounding volume hierarchies", IEEE Symposium on Interactive Ray Tracing 2008, section 3.
#include "strahl/ch06/refine.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch06 {

// Goal: evaluate the four rotations at the inner node n (at depth `depth`), skipping those that cannot be
// done or would put the incoming subtree deeper than max_depth; apply the best if it lowers the cost, and
// return it ({rotation::none, 0} when none does). The first of equal rotations, in enum order, wins.
// Hint: applying is two replace_child calls, then a refit of the changed child before one of n.
// Why: why does a pass visit the nodes bottom up (children before parents), and why must repeated passes
// of such strictly improving rotations stop?
// Step by step: HINTS.md, 06.2.
rotation_choice apply_best_rotation(refine_tree& t, std::uint32_t n, int depth, int max_depth, float c_traversal) {
    STRAHL_TODO("06.2 best rotation");
}

}  // namespace strahl::ch06
