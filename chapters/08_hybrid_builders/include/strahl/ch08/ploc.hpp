// Parallel locally-ordered clustering (PLOC): agglomerative clustering, bottom up, made parallel by looking
// for each cluster's nearest neighbour only among its neighbours along the Morton curve. Start from the
// primitives sorted by Morton code, each its own cluster; then, until one cluster remains, every cluster
// finds its nearest neighbour within `radius` positions on either side (distance: the surface area of the
// box around both); every pair of mutual nearest neighbours merges into one new cluster, which takes the
// place of the pair's first member; and the list is compacted, keeping the curve's order. A larger radius
// finds nearer neighbours (the tree's SAH cost falls) for more distance evaluations per iteration.
//   D. Meister and J. Bittner, "Parallel locally-ordered clustering for bounding volume hierarchy
//   construction", IEEE TVCG 24(3), 2018 (the algorithm: search, merge, compact, until one cluster);
//   B. Walter, K. Bala, M. Kulkarni and K. Pingali, "Fast agglomerative clustering for rendering", IEEE
//   Symposium on Interactive Ray Tracing 2008 (the same distance, merging mutual nearest neighbours).
// The builder sees only boxes and centroids. Its result is chapter 08's binary tree (one primitive per
// leaf), which flatten() collapses by the SAH into chapter 04's nodes.
#pragma once
#include "strahl/ch08/binary_tree.hpp"
#include <span>
#include <string>

namespace strahl::ch08 {

struct ploc_params {
    // The search radius r: each cluster looks at the r clusters before it and the r after it in the current
    // (Morton) order, 2r distances per cluster per iteration. The quality knob: r = 1 merges only
    // neighbours along the curve, r = 16 (the paper's choice for the GPU) finds nearly the clusters that a
    // global search would. Clamped to [1, 256].
    int radius = 16;
    // 10 (30-bit Morton codes) or 21 (63-bit): the codes only order the initial clusters, so 10 suffices
    // unless very many primitives share a cell of the 2^10 grid.
    int bits_per_axis = 10;
};
std::string to_string(const ploc_params& p);  // "ploc16", "ploc4-63", ...

// Per-build counts, for the chapter's program (and the tests).
struct ploc_report {
    std::size_t iterations = 0;   // search-merge-compact rounds until one cluster remained
    double codes_sort_ms = 0, cluster_ms = 0;
};

// BUILD-PLOC:
//   1. codes and sort: chapter 07's Morton codes of the centroids, radix sorted; the primitives that do not
//      fit in a tree (ch04::fits_in_tree) go to t.loose;
//   2. clusters: the sorted leaves, in order;
//   3. until one cluster remains:
//      a. nearest neighbour: per cluster i, the j != i with |i - j| <= r whose union box with i has the
//         least surface area; among equal areas the nearer position wins, then the pair whose lower position
//         is even, then the lower position (an order on pairs: the globally least pair is mutual, so every
//         round merges, and equal boxes (copies) pair up as (0,1), (2,3), ... rather than all choosing the
//         first);
//      b. merge: each mutual pair (nn[nn[i]] == i) becomes one inner node, made by the pair's lower
//         position, the lower one its left child;
//      c. compact: the clusters that remain, in order, by prefix sums over fixed chunks (which also number
//         the new inner nodes).
// Leaves are nodes 0..n-1 in Morton order, inner nodes n.. in the order they were made. Search, merge and
// compaction run over chunks in parallel; the tree is the same on any number of threads.
binary_tree build_ploc(std::span<const aabb> boxes, std::span<const vec3> centroids, const ploc_params& p = {},
                       ploc_report* report = nullptr);

// Step 3a alone, as build_ploc runs it: for clusters whose boxes are listed in the curve's order, each
// position's nearest neighbour within `radius` positions (radius clamped to [1, 256]; the list at least 2
// long). The chapter's figure shows one round with it.
std::vector<std::uint32_t> ploc_nearest_neighbours(std::span<const aabb> boxes, int radius);

}  // namespace strahl::ch08
