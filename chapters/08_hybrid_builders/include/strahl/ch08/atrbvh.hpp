// Agglomerative treelet restructuring (ATRBVH): TRBVH's treelets and rounds, but each treelet's new
// topology found greedily, bottom up, by agglomerative clustering of its leaves instead of the exact
// subset DP: repeatedly merge the two clusters whose union box has the least surface area, until one
// remains. n - 1 merges over at most n(n - 1)/2 distances each, against the DP's 3^n steps: larger
// treelets (the paper's choice: 9 leaves, 2 rounds) at a fraction of the cost, the topology no longer
// optimal within a treelet.
//   L. R. Domingues and H. Pedrini, "Bounding volume hierarchy optimization through agglomerative treelet
//   restructuring", HPG 2015 (section 3: the distance matrix, the merges, the rewrite only where the
//   treelet's cost falls);
//   T. Karras and T. Aila, "Fast parallel construction of high-quality bounding volume hierarchies",
//   HPG 2013 (the treelets and the bottom-up rounds, shared: treelet.hpp).
#pragma once
#include "strahl/ch08/treelet.hpp"

namespace strahl::ch08 {

struct atrbvh_params {
    int treelet_leaves = 9;  // n, clamped to [3, max_treelet_leaves]
    int rounds = 2;          // passes over the tree, bottom up
    int gamma = 9;           // round r visits the nodes with >= gamma * 2^r primitives (the paper: gamma = n)
    ch05::sah_costs costs;   // C_T and C_I, chapter 05's
};

// The agglomerative shape of one treelet's leaves (n = leaf_boxes.size(), 2 <= n <= max_treelet_leaves):
//   1. the distance matrix: for every pair of clusters (at first the leaves), the area of their union box;
//   2. n - 1 times: merge the pair (i < j) of least distance (equal distances: the first pair in the
//      order (0,1), (0,2), ..., (1,2), ...): the merged cluster takes slot i, the last slot moves into j,
//      and row i of the matrix is recomputed;
//   3. its cost as subset_costs prices a tree: C_T * A + (cost of one child + cost of the other) per merge.
// The last merge is the shape's root (inner node 0).
treelet_shape agglomerative_shape(std::span<const aabb> leaf_boxes, std::span<const float> leaf_costs,
                                  const ch05::sah_costs& c);

// RESTRUCTURE-ATRBVH: restructure_treelets (treelet.hpp) with agglomerative_shape.
void restructure_atrbvh(binary_tree& t, const atrbvh_params& p = {}, treelet_report* report = nullptr);

}  // namespace strahl::ch08
