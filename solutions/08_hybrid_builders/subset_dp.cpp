// Exercise 08.2 the subset DP (10 points). Read: treelet.hpp; T. Karras and T. Aila, "Fast parallel
// construction of high-quality bounding volume hierarchies", HPG 2013, sections 4.2 and 4.3 (algorithm 2).
#include "strahl/ch08/treelet.hpp"
#include <bit>
#include <limits>

namespace strahl::ch08 {

// 08.2: the least SAH cost of a tree over every subset of the leaves, and its root's partition.
optimal_topology subset_costs(std::span<const aabb> leaf_boxes, std::span<const float> leaf_costs,
                              const ch05::sah_costs& c) {
    optimal_topology out;
    const auto n = unsigned(leaf_boxes.size());
    const unsigned subsets = 1u << n;
    // 1. The area of every subset's box: a subset's box is its lowest leaf's box united with the box of
    //    the rest, a smaller mask already done.
    std::array<aabb, 1u << max_dp_leaves> box;
    for (unsigned s = 1; s < subsets; ++s) {
        const unsigned low = s & (0u - s);
        const unsigned k = unsigned(std::countr_zero(s));
        box[s] = s == low ? leaf_boxes[k] : unite(box[s ^ low], leaf_boxes[k]);
    }
    // 2. Single leaves cost what their subtrees cost.
    for (unsigned k = 0; k < n; ++k) out.cost[1u << k] = leaf_costs[k], out.partition[1u << k] = 0;
    // 3. Larger subsets in increasing mask order (every proper subset is a smaller number): the best split
    //    into P and S ^ P. Each unordered pair once: P holds S's lowest leaf, plus any proper subset of the
    //    rest (r runs down through the subsets of `rest` below it, 0 included).
    for (unsigned s = 1; s < subsets; ++s) {
        if (std::has_single_bit(s)) continue;
        const unsigned low = s & (0u - s), rest = s ^ low;
        float best = std::numeric_limits<float>::infinity();
        unsigned best_p = low;
        for (unsigned r = (rest - 1) & rest;; r = (r - 1) & rest) {
            const unsigned p = r | low;
            const float split = out.cost[p] + out.cost[s ^ p];
            if (split < best) best = split, best_p = p;
            if (r == 0) break;
        }
        out.cost[s] = c.traversal * box[s].surface_area() + best;
        out.partition[s] = std::uint8_t(best_p);
    }
    return out;
}

}  // namespace strahl::ch08
