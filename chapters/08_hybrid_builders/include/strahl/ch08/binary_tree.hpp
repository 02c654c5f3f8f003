// The binary BVH in index form that this chapter's builders produce and transform: one primitive per leaf,
// every inner node with two children, a parent link everywhere. The bottom-up builders (PLOC) merge into
// it, the restructuring ones (TRBVH, ATRBVH) rewire its treelets, HLBVH assembles it from clusters; then one
// SAH collapse writes chapter 04's flat nodes, so that chapter 05's fast traversal walks every tree the same
// way and their SAH costs compare with chapter 05's and 07's.
//   T. Karras and T. Aila, "Fast parallel construction of high-quality bounding volume hierarchies",
//   HPG 2013 (the one-primitive-per-leaf form, the SAH collapse after restructuring).
#pragma once
#include "strahl/aabb.hpp"
#include "strahl/ch04/bvh.hpp"
#include "strahl/ch05/sah.hpp"
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace strahl::ch08 {

inline constexpr std::uint32_t none = 0xffffffffu;

struct tree_node {
    aabb box;
    std::uint32_t left = none, right = none;  // children (inner nodes); none for a leaf
    std::uint32_t parent = none;              // none for the root
    std::uint32_t prim = none;                // a leaf's primitive id; none for an inner node
    bool is_leaf() const { return left == none; }
};

// n primitives in the tree give n leaves and n - 1 inner nodes, in any order in `nodes`; `root` names the
// root (none for an empty tree). Primitives with a non-finite box or centroid (ch04::fits_in_tree) are not
// in the tree: `loose` lists them, and every ray tests them, as in chapters 04 to 07.
struct binary_tree {
    std::vector<tree_node> nodes;
    std::uint32_t root = none;
    std::vector<std::uint32_t> loose;
    std::size_t leaves() const { return (nodes.size() + 1) / 2; }
};

// Whether t is a well-formed binary tree over exactly the primitives ids [0, primitives) not in t.loose:
// each once in a leaf; parent and child links agree; every inner node's box is the union of its children's
// and every leaf's box is its primitive's box. Returns "" if so, else what is wrong (for tests).
std::string check_tree(const binary_tree& t, std::span<const aabb> boxes);

// The SAH cost of the binary tree as it stands (not collapsed), normalised by the root's area:
// C_T * sum over inner nodes of A(n)/A(root) + C_I * sum over leaves of A(l)/A(root). 0 for an empty tree.
double binary_sah_cost(const binary_tree& t, const ch05::sah_costs& c = {});

// FLATTEN: the SAH collapse, then chapter 04's flat nodes. Bottom up, a subtree of at most max_leaf
// primitives becomes one leaf where the SAH prices it lower as a leaf (C_I N A) than as it stands
// (C_T A + its children's costs); then the tree is written depth first, left child next. Where a subtree
// would reach deeper than max_depth (chapter 04's traversal stack), it is written from depth max_depth - 32
// by halving its primitives in tree order instead (32 halvings reach single primitives). The leaves'
// primitives stand in prim_ids in tree order; loose is copied.
struct flatten_params {
    ch05::sah_costs costs;
    int max_leaf = 4;                        // clamped to [1, 255]
    int max_depth = ch04::bvh_max_depth;     // clamped to [33, ch04::bvh_max_depth]
};
ch04::bvh flatten(const binary_tree& t, const flatten_params& p = {});

// The LBVH of chapter 07 before its collapse (30- or 63-bit Morton codes, Karras's hierarchy): the usual
// start of the restructuring builders.
binary_tree lbvh_binary_tree(std::span<const aabb> boxes, std::span<const vec3> centroids, int bits_per_axis = 10);

// Refits every inner node's box bottom up from the leaves (after children were rewired).
void refit(binary_tree& t);

}  // namespace strahl::ch08
