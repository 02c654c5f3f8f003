// Hierarchical LBVH (HLBVH): the LBVH where it is good, the SAH where it matters. Primitives whose Morton
// codes share their top bits lie in one cell of a coarse grid, a *cluster*; below the clusters the radix
// tree of chapter 07 (fast, and good enough among near neighbours), above them a binned SAH build over the
// clusters' boxes (few clusters, so the SAH's cost is small, and it decides the top levels, which every ray
// visits and where the Morton curve's jumps cost most).
//   J. Pantaleoni and D. Luebke, "HLBVH: hierarchical LBVH construction for real-time ray tracing of
//   dynamic geometry", HPG 2010 (clusters by the codes' top bits, the SAH over them);
//   K. Garanzha, J. Pantaleoni and D. McAllister, "Simpler and faster HLBVH with work queues", HPG 2011
//   (the binned SAH over the clusters, top down, to one cluster per leaf).
// The builder sees only boxes and centroids. Its result is chapter 08's binary tree (one primitive per
// leaf), which flatten() collapses by the SAH into chapter 04's nodes.
#pragma once
#include "strahl/ch05/sah.hpp"
#include "strahl/ch08/binary_tree.hpp"
#include <span>
#include <string>

namespace strahl::ch08 {

struct hlbvh_params {
    int bits_per_axis = 10;  // 10 (30-bit Morton codes) or 21 (63-bit)
    // The top cluster_bits bits of a code name its cluster: a cell of the grid of 2^(cluster_bits / 3)
    // cells per axis over the centroid box (15 bits: 32^3 cells). Clamped to [0, 3 * bits_per_axis]:
    // 0 is one cluster (chapter 07's LBVH), 3 * bits_per_axis a cluster per distinct code (nearly the SAH
    // over all primitives). More bits: more of the tree decided by the SAH, and a slower top level.
    int cluster_bits = 15;
    // The top level's bins per axis, over the clusters' centroid box (clamped to [2, 256]).
    int bins = 16;
    // C_T and C_I for the top level's splits. A cluster counts as its number of primitives.
    ch05::sah_costs costs;
};
std::string to_string(const hlbvh_params& p);  // "hlbvh15", "hlbvh15-63" (63-bit codes), ...

// Per-build counts and phase times, for the chapter's program (and the tests).
struct hlbvh_report {
    std::size_t clusters = 0;
    double codes_sort_ms = 0, bottom_ms = 0, top_ms = 0;
};

// BUILD-HLBVH:
//   1. codes and sort: chapter 07's Morton codes of the centroids, radix sorted; the primitives that do not
//      fit in a tree (ch04::fits_in_tree) go to t.loose;
//   2. clusters: the runs of sorted codes with equal top cluster_bits bits (contiguous, as the codes are
//      sorted);
//   3. bottom: per cluster, the radix tree over its codes, boxes bottom up. One call of chapter 07's Karras
//      builder over all codes builds them all at once: codes that share a prefix form one subtree of a
//      radix tree (its split bits lie below the prefix), so each cluster is the subtree over its range;
//      the nodes above the clusters are dropped;
//   4. top: the binned SAH, top down over the clusters (their boxes, their boxes' centres as centroids),
//      always split, down to one cluster per leaf; the object median by position where no bin boundary
//      separates them (all centres in one point) and below depth ch04::spatial_depth_limit;
//   5. the clusters' subtrees hung under the top tree's leaves.
// Leaves are nodes 0..n-1 in Morton order; an inner node that splits after sorted position g is node n + g
// (in the radix trees g is the split, at the top g runs over the clusters' last positions), so the
// numbering is compact and the tree is the same on any number of threads.
binary_tree build_hlbvh(std::span<const aabb> boxes, std::span<const vec3> centroids, const hlbvh_params& p = {},
                        hlbvh_report* report = nullptr);

}  // namespace strahl::ch08
