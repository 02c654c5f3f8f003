// Exercise 06.1 the cost of one rotation (6 points). Read: A. Kensler, "Tree rotations for improving
// bounding volume hierarchies", IEEE Symposium on Interactive Ray Tracing 2008, section 3; the README.
#include "strahl/ch06/refine.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch06 {

// The change of C_T * (sum of inner nodes' areas) that rotation r at the inner node n would bring:
//   rotation::none: 0;
//   the changed child is R for L <-> RL and L <-> RR, L for R <-> LL and R <-> LR; if it is a leaf, the
//     rotation cannot be done: return +infinity;
//   the incoming node is N's other child (L for the first two, R for the last two);
//   the grandchild that stays is the changed child's other child (RR for L <-> RL, RL for L <-> RR,
//     LR for R <-> LL, LL for R <-> LR);
//   return C_T * (A(box(incoming) u box(stays)) - A(box(changed))), with aabb's unite and surface_area.
// Nothing else changes: N keeps its box (the same primitives below it), and so do all its ancestors.
float rotation_cost(const refine_tree& t, std::uint32_t n, rotation r, float c_traversal) {
    STRAHL_TODO("06.1 rotation cost");
}

}  // namespace strahl::ch06
