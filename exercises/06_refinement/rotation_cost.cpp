// Exercise 06.1 the cost of one rotation (6 points). Read: A. Kensler, "Tree rotations for improving
// bounding volume hierarchies", IEEE Symposium on Interactive Ray Tracing 2008, section 3; the README.
#include "strahl/ch06/refine.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch06 {

// Goal: the change of C_T * (sum of inner nodes' areas) that rotation r at the inner node n would bring:
// 0 for rotation::none; +infinity when the changed child is a leaf (the rotation cannot be done); otherwise
// C_T times the changed child's new area minus its old one.
// Hint: the README's table names, for each rotation, the changed child and its new box.
// Why: why does no other node's area change: what happens to the box of N and to those of its ancestors?
// Step by step: HINTS.md, 06.1.
float rotation_cost(const refine_tree& t, std::uint32_t n, rotation r, float c_traversal) {
    STRAHL_TODO("06.1 rotation cost");
}

}  // namespace strahl::ch06
