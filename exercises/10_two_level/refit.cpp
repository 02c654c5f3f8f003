// Exercise 10.2 refit (6 points). Read: refit.hpp; Wald, Boulos and Shirley 2007, section 4.
#include "strahl/ch10/refit.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch10 {

// Goal: every node's box (bmin, bmax) recomputed from the primitives' new boxes, the tree's shape kept:
// a leaf bounds its primitives (prim_ids[offset .. offset + count)), an inner node its two children
// (index + 1 and offset); tree.bounds the root's box (empty for an empty tree).
// Hint: one loop over the node array, from the last node to the first.
// Why: why does that order see every child before its parent, and why may a refit tree trace slower than
// a rebuilt one although every box is tight?
// Step by step: HINTS.md, 10.2.
void refit(ch04::bvh& tree, std::span<const aabb> boxes) {
    STRAHL_TODO("10.2 refit");
}

}  // namespace strahl::ch10
