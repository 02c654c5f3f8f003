// Treelet restructuring (TRBVH): improve a finished binary tree in place, a few nodes at a time. A treelet
// is a node's neighbourhood: the node (its root), grown downwards by turning its largest leaf into an inner
// node until it has n leaves. Those n leaves are whole subtrees that stay as they are; the treelet's n - 1
// inner nodes are rewired into the topology of least SAH cost over the leaves, found exactly by dynamic
// programming over the 2^n subsets of the leaves. Every node whose subtree holds at least gamma primitives
// is a treelet root once per round, bottom up, so that each treelet sees its children's treelets already
// optimised. The paper's default: n = 7 leaves, 3 rounds, gamma = 7 doubled each round.
//   T. Karras and T. Aila, "Fast parallel construction of high-quality bounding volume hierarchies", HPG 2013
//   (section 4.1: forming a treelet; 4.2-4.3: the optimal topology by the subset DP; 5: the bottom-up rounds).
// The paper's cost also lets a subset become one leaf of several primitives; here the tree keeps one
// primitive per leaf and flatten() collapses afterwards, so the DP prices the binary tree as it stands
// (binary_sah_cost's terms, without the division by the root's area).
#pragma once
#include "strahl/ch08/binary_tree.hpp"
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace strahl::ch08 {

inline constexpr int max_treelet_leaves = 16;  // forming (ATRBVH's clustering takes up to 16)
inline constexpr int max_dp_leaves = 8;        // the subset DP: 2^8 subsets, a subset fits in one byte

// A treelet: its root (a node of the tree), its leaves (nodes whose subtrees it keeps whole) and its inner
// nodes (the nodes it may rewire: the root and every node it expanded).
struct treelet {
    std::uint32_t root = none;
    std::vector<std::uint32_t> leaves;
    std::vector<std::uint32_t> inner;
};

// Exercise 08.1 "forming a treelet" (Karras and Aila, section 4.1). Grows the treelet of `root`:
//   root a leaf of t: leaves {root}, inner {} (nothing to rewire);
//   else inner {root}, leaves {left child, right child}; then, while leaves.size() < n_leaves (>= 2): of the
//   treelet leaves that are inner nodes of t (a primitive's leaf cannot be expanded), the one with the
//   largest box surface area, equal areas going to the lower node index, is removed from `leaves`, its
//   left child then its right child appended at the end of `leaves`, and it is appended to `inner`. Stops
//   early when no treelet leaf can be expanded (the subtree has fewer than n_leaves primitives).
// The other leaves keep their order. Reads t only.
treelet form_treelet(const binary_tree& t, std::uint32_t root, int n_leaves);

// The subset DP's answer for n leaves (1 <= n <= max_dp_leaves): per subset S of the leaves, as a bit mask
// (bit k: leaf k; masks 1 .. 2^n - 1; entries 0 and from 2^n on are unspecified):
//   cost[S]      the least SAH cost of any binary tree over exactly the leaves in S;
//   partition[S] for S of two or more leaves, the leaves P of one child in such a tree (S ^ P are the
//                other's): a non-empty proper subset of S reaching the minimum below (any one of them);
//                0 for a single leaf.
struct optimal_topology {
    std::array<float, 1u << max_dp_leaves> cost{};
    std::array<std::uint8_t, 1u << max_dp_leaves> partition{};
};

// Exercise 08.2 "the subset DP" (Karras and Aila, section 4.2, algorithm 2 without the leaf collapse):
// leaf_boxes[k] and leaf_costs[k] (the cost of the subtree under treelet leaf k; a primitive's leaf costs
// C_I * its area) for n = leaf_boxes.size() leaves, leaf_costs the same size, 1 <= n <= max_dp_leaves:
//   cost[{k}] = leaf_costs[k];
//   cost[S]   = C_T * A(S) + min over non-empty proper subsets P of S of (cost[P] + cost[S ^ P]),
// A(S) the surface area of the union of the boxes of S. Every proper subset of S is a smaller number than
// S, so the masks in increasing order see each subset's cost before they need it.
optimal_topology subset_costs(std::span<const aabb> leaf_boxes, std::span<const float> leaf_costs,
                              const ch05::sah_costs& c);

// ---- The restructuring both TRBVH and ATRBVH run (src/trbvh.cpp) ----

// A new topology for a treelet of n leaves: n - 1 inner nodes, children[0] the root's. A child code
// c < n names treelet leaf c, c >= n the shape's inner node c - n. cost: its SAH cost (as subset_costs
// prices it); the treelet is rewired only where this is lower than its cost as it stands.
struct treelet_shape {
    float cost = 0.0f;
    std::array<std::array<std::uint8_t, 2>, max_treelet_leaves - 1> children{};
};
// The optimiser: leaf boxes and leaf costs (n of them, n >= 3) to the best shape it finds. Called from
// several threads at once.
using treelet_optimizer = std::function<treelet_shape(std::span<const aabb>, std::span<const float>)>;

struct treelet_report {
    std::size_t treelets = 0;   // treelets formed, all rounds
    std::size_t rewired = 0;    // of them, rewired to a cheaper shape
    double ms = 0;
};

// Rounds r = 0 .. rounds - 1, each one pass bottom up over the tree in parallel (an atomic counter per
// node: the second child to arrive processes the node, as chapter 07's box fit): every node with at least
// gamma * 2^r primitives in its subtree gets its treelet of n_leaves leaves (form_treelet) optimised by
// `optimize`, and rewired (its inner nodes' indices reused, the root's kept, boxes refitted) where the
// new shape costs less by a relative 1e-5 (so binary_sah_cost never rises through rounding). Treelets
// being processed at once lie in disjoint subtrees: the tree is the same on any number of threads.
void restructure_treelets(binary_tree& t, int n_leaves, int rounds, int gamma, const ch05::sah_costs& costs,
                          const treelet_optimizer& optimize, treelet_report* report = nullptr);

// ---- TRBVH ----

struct trbvh_params {
    int treelet_leaves = 7;  // n, clamped to [3, max_dp_leaves]: the DP costs about 3^n steps per treelet
    int rounds = 3;          // passes over the tree (the paper: 3; most of the gain comes in the first)
    int gamma = 7;           // round r visits the nodes with >= gamma * 2^r primitives (the paper: gamma = n)
    ch05::sah_costs costs;   // C_T and C_I, chapter 05's
};

// RESTRUCTURE-TRBVH: restructure_treelets with the subset DP's optimal topology (subset_costs, then the
// shape read off the partitions from the full set down).
void restructure_trbvh(binary_tree& t, const trbvh_params& p = {}, treelet_report* report = nullptr);

}  // namespace strahl::ch08
