// Exercise 04.2 the split of BUILD-HIERARCHY (8 points). Read: J. Goldsmith and J. Salmon, "Automatic
// creation of object hierarchies for ray tracing", IEEE CG&A 1987; pbrt-v4, 2023, section 7.3.2.
#include "strahl/ch04/bvh.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch04 {

// Goal: split the node's range ids (2 or more primitive ids) in place for BUILD-HIERARCHY: choose the longest
// axis of the box around the range's centroids, reorder ids so that the left child's primitives come first,
// and return {axis, mid} with 0 < mid < ids.size() always (bvh.hpp has the full contract: object median,
// spatial median with its fall-back, all centroids equal).
// Hint: std::nth_element and std::partition reorder a range in place; compare by (centroid[axis], id) so that
// equal centroids still have one order.
// Why: why must a split never leave one side empty, and why does splitting equal centroids in half keep the
// tree's depth at log2 of the count?
// Step by step: HINTS.md, 04.2.
split_result partition_split(std::span<std::uint32_t> ids, std::span<const vec3> centroids, split_method m) {
    STRAHL_TODO("04.2 partition");
}

}  // namespace strahl::ch04
