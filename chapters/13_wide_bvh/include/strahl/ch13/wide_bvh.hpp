// The wide BVH: N children per inner node (BVH4, BVH8, BVH16), whose N boxes one SIMD slab test checks at
// once, and leaves of triangles stored in blocks of M that one SIMD triangle test checks at once. Built by
// collapsing a binary BVH (chapters 04 to 06) from the top: an inner node pulls up the children of its
// children until it holds N of them.
//   I. Wald, C. Benthin and S. Boulos, "Getting rid of packets: efficient SIMD single-ray traversal using
//   multi-branching BVHs", IEEE Symposium on Interactive Ray Tracing 2008 (the wide node, the greedy collapse);
//   H. Dammertz, J. Hanika and A. Keller, "Shallow bounding volume hierarchies for fast SIMD ray tracing of
//   incoherent rays", EGSR 2008 (QBVH, the same idea for four children);
//   M. Pinto, "Efficient ray tracing using wide BVHs", 2010, and H. Ylitie, T. Karras and S. Laine,
//   "Efficient incoherent ray traversal on GPUs through compressed wide BVHs", HPG 2017 (the SAH-optimal
//   collapse by dynamic programming).
#pragma once
#include "strahl/ch04/bvh.hpp"
#include "strahl/scene.hpp"
#include "strahl/huge_pages.hpp"
#include <cstdint>
#include <span>
#include <vector>

namespace strahl::ch13 {

// A child reference, 32 bits:
//   an inner node: its index in wide_bvh::nodes (bit 31 clear);
//   a leaf:        bit 31 set, bits 25-30 the number of triangle blocks minus 1 (1 to 64 blocks), bits 0-24
//                  the first block's index in wide_bvh::blocks (2^25 blocks: 134 million triangles at M = 4).
// An unused slot of a node has an empty box (min +inf, max -inf), which no ray enters, and reference 0.
inline constexpr std::uint32_t leaf_bit = 1u << 31;
inline constexpr std::uint32_t max_leaf_blocks = 64;
inline constexpr std::uint32_t max_blocks = 1u << 25;
inline constexpr bool is_leaf(std::uint32_t ref) { return (ref & leaf_bit) != 0; }
inline constexpr std::uint32_t leaf_ref(std::uint32_t first_block, std::uint32_t blocks) {
    return leaf_bit | ((blocks - 1) << 25) | first_block;
}
inline constexpr std::uint32_t leaf_first(std::uint32_t ref) { return ref & (max_blocks - 1); }
inline constexpr std::uint32_t leaf_blocks(std::uint32_t ref) { return ((ref >> 25) & 63) + 1; }

// One node of N children, structure of arrays: each of the six box planes is a row of N floats, one SIMD
// load. Aligned to a 64-byte cache line:
//   N = 4:  6 x 16 bytes of planes + 16 bytes of references + 4 of order =  116, padded to 128 (two lines);
//   N = 8:  6 x 32 + 32 + 8                                              =  232, padded to 256 (four lines);
//   N = 16: 6 x 64 + 64 + 16                                             =  464, padded to 512 (eight lines).
template <int N>
struct alignas(64) wide_node {
    float lo[3][N];  // lo[axis][child]: the children's minimum corners
    float hi[3][N];  // hi[axis][child]: their maximum corners
    std::uint32_t child[N];
    // The any-hit walk's order (child_order.hpp): order[j] is the slot of the j-th child to visit; the
    // collapse writes 0, 1, ..., N-1 (the stored order). Closest hit ignores it.
    std::uint8_t order[N];
    // Closest hit's order per ray octant (child_order.hpp, order_by_octant), 8-wide nodes only (in the
    // padding): for octant o (bit a set where the direction's component a is negative), bits 3j to 3j + 2
    // of the 24-bit little-endian word at octant_order[3 o] are the slot of the j-th child to visit.
    std::uint8_t octant_order[N == 8 ? 24 : 1];
    std::uint32_t octant_word(int o) const {
        const std::uint8_t* p = octant_order + 3 * o;
        return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16;
    }
    void set_octant_word(int o, std::uint32_t w) {
        for (int b = 0; b < 3; ++b) octant_order[3 * o + b] = std::uint8_t(w >> (8 * b));
    }

    aabb box(int i) const {
        return {vec3(lo[0][i], lo[1][i], lo[2][i]), vec3(hi[0][i], hi[1][i], hi[2][i])};
    }
    bool used(int i) const { return lo[0][i] <= hi[0][i]; }
};
static_assert(sizeof(wide_node<4>) == 128 && sizeof(wide_node<8>) == 256 && sizeof(wide_node<16>) == 512);

// M triangles in structure of arrays, what the leaf test needs precomputed: the first vertex and the two
// edges e1 = v1 - v0, e2 = v2 - v0 (computed as exercise 01.3 computes them, so the test rounds the same),
// and the primitive ids. Lanes past a leaf's last triangle repeat it: the same answer twice changes nothing.
template <int M>
struct alignas(64) triangle_block {
    float v0[3][M];
    float e1[3][M];
    float e2[3][M];
    std::uint32_t id[M];
};

enum class collapse_method {
    greedy,   // Wald et al. 2008: open the child of largest surface area until N children (exercise 13.1)
    optimal,  // Pinto 2010 / Ylitie et al. 2017: the SAH-cheapest choice of N descendants, by dynamic programming
};
const char* to_string(collapse_method m);

struct collapse_stats {
    std::size_t inner = 0, leaves = 0, blocks = 0, triangles = 0, used_slots = 0;
    double sah = 0.0;  // the wide tree's SAH cost: C_node per inner node, C_block per block (sah_of below)
    double ms = 0.0;   // the collapse alone
};

// The wide tree. nodes[0] is the root unless the whole tree is one leaf (root_ref says which). Node: the
// float node above, or its quantised form (quantized_node.hpp, made from a collapsed tree by quantize()).
template <int N, int M, class Node = wide_node<N>>
struct wide_bvh {
    using node_type = Node;
    aabb bounds;
    vec3 centre{0.0f};     // the bounds' centre and an upper bound on their diagonal's length, for the
    float diagonal = 0.0f; // per-ray slack (wide_traverse.hpp)
    std::uint32_t root_ref = 0;
    huge_vector<Node> nodes;                  // (huge_pages.hpp: written once, on 2 MiB pages where offered)
    huge_vector<triangle_block<M>> blocks;
    std::vector<std::uint32_t> loose;  // primitives the binary tree left out (non-finite boxes)
    collapse_stats stats;

    // The bounds, with the centre and diagonal the walk's slack reads.
    void set_bounds(const aabb& b) {
        bounds = b;
        if (b.is_empty()) return;
        centre = b.centroid();
        const vec3 e = b.extent();
        diagonal = e.x + e.y + e.z;  // >= the diagonal's length
    }
    std::size_t memory_bytes() const {
        return nodes.size() * sizeof(Node) + blocks.size() * sizeof(triangle_block<M>) + loose.size() * 4;
    }
};

struct collapse_config {
    collapse_method method = collapse_method::greedy;
    double c_node = 1.0;   // the SAH's cost of one wide node (its N boxes in one test) ...
    double c_block = 1.0;  // ... and of one block of M triangles (one SIMD triangle test)
    int max_leaf = 8;      // optimal only: the most triangles it may gather into one leaf from a subtree
};

// Collapses the binary tree `tree` over `mesh`'s triangles (primitive i is triangle i) into a wide tree.
// Each leaf of the result holds the triangles of one binary subtree (greedy: one binary leaf) in blocks of
// M, in leaf order. Throws std::length_error where a leaf would need more than max_leaf_blocks blocks, or
// the whole tree more than max_blocks.
template <int N, int M>
wide_bvh<N, M> collapse(const ch04::bvh& tree, const triangle_mesh& mesh, const collapse_config& config = {});

// Exercise 13.1: of a node's children (their surface areas, and whether each is a leaf), the one the greedy
// collapse opens next: the inner child of largest area, the lowest index among equals; -1 when every child
// is a leaf.
int child_to_open(std::span<const float> areas, std::span<const bool> leaf);

// The wide tree's SAH cost, normalised by the root's area: c_node per inner node visited (all N boxes in one
// test), c_block per triangle block: sum over inner nodes of A(n) c_node + sum over leaves of blocks(l)
// A(l) c_block, divided by A(root).
template <int N, int M>
double sah_of(const wide_bvh<N, M>& tree, double c_node = 1.0, double c_block = 1.0);

}  // namespace strahl::ch13
