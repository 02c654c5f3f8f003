// The k-d tree's flat form and its builder. The builder sees only boxes (one per primitive).
//   I. Wald and V. Havran, "On building fast kd-trees for ray tracing, and on doing that in O(N log N)",
//   2006 (we build the simpler O(N log^2 N) variant: events sorted again at every node).
#pragma once
#include "strahl/ch03/sah.hpp"
#include <cstdint>
#include <span>
#include <vector>

namespace strahl::ch03 {

// One node in 8 bytes:
//   bytes 0-3: inner node: the split position (float); leaf: the number of primitive references;
//   bytes 4-7: bits 0-1 the axis (0, 1, 2) or 3 for a leaf; bits 2-31 for an inner node the index of its
//              left child (the right child follows it directly), for a leaf the offset of its first
//              reference in prim_refs.
struct kd_node {
    union {
        float split;
        std::uint32_t count;
    };
    std::uint32_t bits;

    bool is_leaf() const { return (bits & 3u) == 3u; }
    int axis() const { return int(bits & 3u); }
    std::uint32_t left() const { return bits >> 2; }  // the right child is left() + 1
    std::uint32_t first() const { return bits >> 2; }

    static kd_node inner(int axis, float split, std::uint32_t left) {
        kd_node n;
        n.split = split;
        n.bits = (left << 2) | std::uint32_t(axis);
        return n;
    }
    static kd_node leaf(std::uint32_t first, std::uint32_t count) {
        kd_node n;
        n.count = count;
        n.bits = (first << 2) | 3u;
        return n;
    }
};
static_assert(sizeof(kd_node) == 8, "the node layout is 8 bytes");

struct kd_build_params {
    sah_params sah;
    int max_depth = -1;  // -1: 8 + 1.3 log2 N ("termination by depth"), capped at kd_max_depth
};
inline constexpr int kd_max_depth = 48;  // also bounds the traversal stack

// Numbers about a built tree, for the program and the tests.
struct kd_stats {
    std::size_t primitives = 0, inner = 0, leaves = 0, empty_leaves = 0, references = 0;
    int depth = 0, depth_limit = 0;
    std::size_t max_leaf = 0;
    double build_ms = 0.0;
    // Duplication: references per primitive (1.0 means no triangle straddles a plane).
    double refs_per_prim() const { return primitives ? double(references) / double(primitives) : 0.0; }
};

struct kd_tree {
    aabb bounds;                           // the root's box: the union of all primitive boxes
    std::vector<kd_node> nodes;            // nodes[0] is the root (absent for an empty tree)
    std::vector<std::uint32_t> prim_refs;  // leaf contents, primitive ids in ascending order per leaf
    std::vector<std::uint32_t> loose;      // primitives with a non-finite box: not in the tree, tested by every ray
    sah_params sah;
    kd_stats stats;

    std::size_t memory_bytes() const { return nodes.size() * sizeof(kd_node) + prim_refs.size() * 4; }
    // The SAH cost of the tree, normalised by the root's area:
    //   (1 / A(root)) * (sum over inner nodes of C_T A(node) + sum over leaves of C_I n A(leaf)).
    double sah_cost() const;
};

// Builds over the primitives' boxes (primitive id i has box boxes[i]).
kd_tree build_kd_tree(std::span<const aabb> boxes, const kd_build_params& params = {});

// The depth limit for n primitives: 8 + 1.3 log2 n, at most kd_max_depth.
int depth_limit(std::size_t n);

// The split planes of the first `levels` levels, each clipped to its node's box: the 4 corners of the
// rectangle per plane (for drawing). level 0 is the root's plane.
struct kd_plane {
    int level;
    int axis;
    vec3 corners[4];
};
std::vector<kd_plane> split_planes(const kd_tree& tree, int levels);

}  // namespace strahl::ch03
