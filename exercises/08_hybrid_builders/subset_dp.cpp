// Exercise 08.2 the subset DP (10 points). Read: treelet.hpp; T. Karras and T. Aila, "Fast parallel
// construction of high-quality bounding volume hierarchies", HPG 2013, sections 4.2 and 4.3 (algorithm 2).
#include "strahl/ch08/treelet.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch08 {

// Goal: for the n = leaf_boxes.size() treelet leaves and every subset S of them (a bit mask, 1 .. 2^n - 1),
// cost[S], the least SAH cost of a binary tree over exactly those leaves, and partition[S], the leaves of
// one child of its root: cost[{k}] = leaf_costs[k], and for two or more leaves
//   cost[S] = C_T * A(S) + min over non-empty proper subsets P of S of (cost[P] + cost[S ^ P]),
// A(S) the surface area of the union of S's boxes; partition[S] a P reaching that minimum.
// Hint: the proper subsets of S, largest first: P = (S - 1) & S, then P = (P - 1) & S, until P == 0.
// Why: why can the masks be taken in increasing numeric order, and why does the cost of a subtree over S
// not depend on how the trees over P and S ^ P look inside?
// Step by step: HINTS.md, 08.2.
optimal_topology subset_costs(std::span<const aabb> leaf_boxes, std::span<const float> leaf_costs,
                              const ch05::sah_costs& c) {
    STRAHL_TODO("08.2 the subset DP");
}

}  // namespace strahl::ch08
