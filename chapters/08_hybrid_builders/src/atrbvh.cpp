// RESTRUCTURE-ATRBVH: TRBVH's rounds with agglomerative clustering inside each treelet.
//   L. R. Domingues and H. Pedrini, "Bounding volume hierarchy optimization through agglomerative treelet
//   restructuring", HPG 2015.
#include "strahl/ch08/atrbvh.hpp"
#include <algorithm>
#include <limits>

namespace strahl::ch08 {

treelet_shape agglomerative_shape(std::span<const aabb> leaf_boxes, std::span<const float> leaf_costs,
                                  const ch05::sah_costs& c) {
    constexpr int cap = max_treelet_leaves;
    const int n = int(leaf_boxes.size());
    treelet_shape shape;
    // The clusters in slots 0 .. live - 1: box, cost, and the shape's child code naming them.
    std::array<aabb, cap> box;
    std::array<float, cap> cost;
    std::array<std::uint8_t, cap> code;
    for (int k = 0; k < n; ++k) box[k] = leaf_boxes[k], cost[k] = leaf_costs[k], code[k] = std::uint8_t(k);
    // 1. The distance matrix (upper triangle used): the area of the union of two clusters.
    std::array<std::array<float, cap>, cap> dist;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) dist[i][j] = unite(box[i], box[j]).surface_area();
    // 2. Merge the closest pair until one cluster remains; merge number s makes shape inner node n - 2 - s.
    for (int live = n, made = n - 2; live > 1; --live, --made) {
        int bi = 0, bj = 1;
        float best = std::numeric_limits<float>::infinity();
        for (int i = 0; i < live; ++i)
            for (int j = i + 1; j < live; ++j)
                if (dist[i][j] < best) best = dist[i][j], bi = i, bj = j;
        shape.children[made] = {code[bi], code[bj]};
        // 3. The merged cluster's cost, as the DP prices it.
        box[bi] = unite(box[bi], box[bj]);
        cost[bi] = c.traversal * box[bi].surface_area() + (cost[bi] + cost[bj]);
        code[bi] = std::uint8_t(n + made);
        // The last slot moves into bj; then bi's row and column are recomputed.
        const int last = live - 1;
        if (bj != last) {
            box[bj] = box[last], cost[bj] = cost[last], code[bj] = code[last];
            for (int k = 0; k < last; ++k)
                if (k != bj) dist[std::min(k, bj)][std::max(k, bj)] = dist[std::min(k, last)][std::max(k, last)];
        }
        for (int k = 0; k < last; ++k)
            if (k != bi) dist[std::min(k, bi)][std::max(k, bi)] = unite(box[bi], box[k]).surface_area();
    }
    shape.cost = cost[0];
    return shape;
}

void restructure_atrbvh(binary_tree& t, const atrbvh_params& p, treelet_report* report) {
    const ch05::sah_costs c = p.costs;
    restructure_treelets(t, std::clamp(p.treelet_leaves, 3, max_treelet_leaves), p.rounds, p.gamma, c,
                         [c](std::span<const aabb> boxes, std::span<const float> costs) {
                             return agglomerative_shape(boxes, costs, c);
                         }, report);
}

}  // namespace strahl::ch08
