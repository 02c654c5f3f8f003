// Updating a BVH whose primitives moved: refit (keep the tree, recompute its boxes bottom-up) and the
// partial rebuild (refit, then rebuild the subtrees whose SAH cost grew most).
//   I. Wald, S. Boulos and P. Shirley, "Ray tracing deformable scenes using dynamic bounding volume
//   hierarchies", ACM TOG 26(1), 2007 (refit, and when a rebuild pays off);
//   D. Kopta, T. Ize, J. Spjut, E. Brunvand, A. Davis and A. Kensler, "Fast, effective BVH updates for
//   animated scenes", I3D 2012 (a tree degrades where its cost grows: repair it there).
#pragma once
#include "strahl/ch04/accel.hpp"
#include "strahl/ch04/bvh.hpp"
#include <span>
#include <vector>

namespace strahl::ch10 {

// Exercise 10.2 "refit": every node's box recomputed from the primitives' new boxes, the topology kept.
// boxes[i] is primitive i's box now (finite: a primitive that left the finite range needs a rebuild). A
// leaf's box is the union of its primitives' boxes (tree.prim_ids[offset .. offset + count)); an inner
// node's, the union of its two children's (index + 1 and offset). In chapter 04's depth-first array both
// children lie after their parent, so one pass from the last node to the first sees every child before its
// parent. tree.bounds becomes the root's box; an empty tree stays empty.
void refit(ch04::bvh& tree, std::span<const aabb> boxes);

// Each node's subtree cost: C_T A(n) for an inner node plus its children's, N A(n) for a leaf (areas not
// normalised, so costs of different frames compare). cost[0] / A(root) is chapter 05's tree_cost.
std::vector<float> subtree_costs(const ch04::bvh& tree);

struct partial_params {
    // The cut: the highest subtrees holding at most this fraction of the primitives (each a candidate).
    float cut_fraction = 1.0f / 32.0f;
    // How many of the cut's subtrees are rebuilt per update: those whose cost grew most since their build.
    int subtrees = 4;
};

struct partial_result {
    int rebuilt = 0;             // subtrees rebuilt
    std::size_t primitives = 0;  // primitives in them
    bool full = false;           // the tree was rebuilt whole (its subtrees were not contiguous, or too deep)
};

// The partial rebuild, after refit(tree, boxes): the cut's subtrees ranked by cost now minus cost at their
// last build (baseline, one float per node, kept up to date here), the worst rebuilt by builder over their
// primitives (boxes and centroids), the tree re-flattened around them. Ancestors' boxes are unchanged (a
// rebuilt subtree bounds the same primitives).
partial_result partial_rebuild(ch04::bvh& tree, std::vector<float>& baseline, std::span<const aabb> boxes,
                               const ch04::bvh_builder& builder, const partial_params& params = {});

}  // namespace strahl::ch10
