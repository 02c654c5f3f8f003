// Refining a built BVH: local changes to its topology that lower the SAH cost, applied after the build.
//   A. Kensler, "Tree rotations for improving bounding volume hierarchies", IEEE Symposium on Interactive
//   Ray Tracing 2008 (ROTATE: swap a child with a grandchild on the other side);
//   J. Bittner, M. Hapala and V. Havran, "Fast insertion-based optimization of bounding volume
//   hierarchies", Computer Graphics Forum 32(1), 2013 (REINSERT: remove a subtree where the tree is
//   inefficient, put it back where the induced cost is lowest, found by branch and bound).
// Both work on an index form of the tree with parent links (refine_tree), then write chapter 04's flat
// 32-byte nodes back, which chapter 04's traversal walks unchanged.
#pragma once
#include "strahl/ch04/bvh.hpp"
#include "strahl/ch05/sah.hpp"
#include <cstdint>
#include <limits>
#include <vector>

namespace strahl::ch06 {

inline constexpr std::uint32_t no_node = std::numeric_limits<std::uint32_t>::max();

// One node of the index form in 48 bytes:
//   bytes  0-23: the box (min and max corner, 6 floats);
//   bytes 24-27: parent: the parent's index, no_node for the root;
//   bytes 28-35: left, right: the children's indices; no_node for both in a leaf;
//   bytes 36-43: first, count: a leaf's range [first, first + count) of the tree's prim_ids;
//   bytes 44-47: height: the longest path down to a leaf (0 for a leaf), for the depth bound.
// Unlike the flat form, any child can be swapped for any other subtree by rewriting two links.
struct refine_node {
    aabb box;
    std::uint32_t parent = no_node;
    std::uint32_t left = no_node, right = no_node;
    std::uint32_t first = 0, count = 0;
    std::int32_t height = 0;

    bool is_leaf() const { return left == no_node; }
};
static_assert(sizeof(refine_node) == 48, "the index form's node is 48 bytes");

struct refine_tree {
    std::vector<refine_node> nodes;
    std::uint32_t root = no_node;          // no_node for an empty tree
    std::vector<std::uint32_t> prim_ids;   // the flat tree's, unchanged: leaves keep their ranges

    // REFIT one node: its box is the union of its children's, its height one more than theirs.
    void refit(std::uint32_t n) {
        refine_node& x = nodes[n];
        if (x.is_leaf()) return;
        x.box = unite(nodes[x.left].box, nodes[x.right].box);
        x.height = 1 + std::max(nodes[x.left].height, nodes[x.right].height);
    }
    // Makes new_child the child of parent in old_child's place (and parent its parent).
    void replace_child(std::uint32_t parent, std::uint32_t old_child, std::uint32_t new_child) {
        refine_node& p = nodes[parent];
        (p.left == old_child ? p.left : p.right) = new_child;
        nodes[new_child].parent = parent;
    }
    // The number of links from the root down to n.
    int depth_of(std::uint32_t n) const {
        int d = 0;
        for (; nodes[n].parent != no_node; n = nodes[n].parent) ++d;
        return d;
    }
};

// The flat tree into the index form, and back: depth first, left child next; prim_ids regrouped in leaf
// order; the split axis of each inner node set to the axis on which its children's box centres lie
// farthest apart, the child with the lower centre first (the traversal's near-first order reads it);
// bounds and stats (inner, leaves, max_leaf, depth) recomputed; loose, primitives and build_ms kept.
refine_tree to_refine_tree(const ch04::bvh& flat);
ch04::bvh to_bvh(const refine_tree& t, const ch04::bvh& original);

// ---- ROTATE (Kensler 2008) ----

// The four rotations at an inner node N with children L and R: a child of N trades places with a
// grandchild on the other side. The one inner child whose content changes gets a new box; N's box, and
// so every ancestor's, stays the same.
enum class rotation : std::uint8_t {
    none,
    left_right_left,    // L <-> RL: R becomes (L, RR)
    left_right_right,   // L <-> RR: R becomes (RL, L)
    right_left_left,    // R <-> LL: L becomes (R, LR)
    right_left_right,   // R <-> LR: L becomes (LL, R)
};
const char* to_string(rotation r);

// Exercise 06.1 "rotation cost": the change of the tree's SAH cost, times A(root), that rotation r at the
// inner node n would bring: C_T * (A(new box of the changed child) - A(its old box)), e.g. for
// L <-> RL: C_T * (A(box(L) u box(RR)) - A(box(R))). Leaves do not change, so the C_I terms cancel.
// 0 for rotation::none; +inf when r cannot be done at n (the child whose grandchild it takes is a leaf).
float rotation_cost(const refine_tree& t, std::uint32_t n, rotation r, float c_traversal);

// Exercise 06.2 "best rotation": evaluates the four rotations at the inner node n, which lies at depth
// `depth`, and applies the one with the lowest (most negative) cost change, if that change is < 0:
// rewrites the links (replace_child), then refits the changed child and n. A rotation is skipped when it
// cannot be done, or when it would put a node deeper than max_depth (the child that moves down goes two
// levels below n: depth + 2 + its height must be <= max_depth). Ties go to the first in enum order.
// Returns the rotation applied and its cost change ({none, 0} when none was).
struct rotation_choice {
    rotation r = rotation::none;
    float delta = 0.0f;
};
rotation_choice apply_best_rotation(refine_tree& t, std::uint32_t n, int depth, int max_depth, float c_traversal);

// One ROTATE pass: bottom up (post order), apply_best_rotation at every inner node. Returns the number of
// rotations applied.
std::size_t rotation_pass(refine_tree& t, float c_traversal, int max_depth);

// ---- REINSERT (Bittner, Hapala and Havran 2013) ----

// One REINSERT iteration: the `batch` inner nodes with the largest inefficiency among those not yet tried
// in this round (tried: a flag per node, kept between iterations) have each of their two children removed
// and reinserted at the best place (which may be where it was). When every inner node has been tried, the
// round is over and the flags clear. (Every cost compared is a sum of inner nodes' areas: C_T drops out.)
struct reinsertion_result {
    std::size_t moves = 0;
    bool round_over = false;
};
reinsertion_result reinsertion_pass(refine_tree& t, std::size_t batch, int max_depth, std::vector<std::uint8_t>& tried);

// ---- Both, on a flat tree ----

enum class refine_method : std::uint8_t { rotations, reinsertion };
enum class start_tree : std::uint8_t { median, binned16 };  // ch04's object median; ch05's binned SAH (16 bins)
const char* to_string(refine_method m);
const char* to_string(start_tree s);

struct refine_params {
    refine_method method = refine_method::rotations;
    int max_iterations = 64;       // rotations: passes; reinsertion: batches. Both stop early at a fixed point:
                                   // a pass, or a whole round of batches, that moves nothing
    float batch_fraction = 0.05f;  // reinsertion: the share of inner nodes reinserted per iteration
    ch05::sah_costs costs;         // C_T (the C_I terms never change: leaves stay as they are)
    int max_depth = ch04::bvh_max_depth;  // never deeper than this (the traversal's stack is sized for it)
    start_tree start = start_tree::binned16;  // for make_accel only: the tree that is refined
};

struct refine_stats {
    double before = 0.0, after = 0.0;  // ch05::tree_cost with params.costs
    double ms = 0.0;                   // the refinement alone, conversions included
    int iterations = 0;                // passes or batches run
    std::size_t moves = 0;             // rotations or reinsertions applied
};

// Refines tree in place. Never raises its SAH cost: a result that came out worse is thrown away.
refine_stats refine(ch04::bvh& tree, const refine_params& params = {});

}  // namespace strahl::ch06
