// The order in which the any-hit walk visits a wide node's children. Closest hit sorts the children a ray
// enters by their entry distance; the any-hit walk takes them in an order fixed beforehand, and stops at the
// first blocker: that order decides how soon it meets one.
//
// The collapse leaves the children in the binary tree's order (left before right, split by split), and the
// walk's visit_order::stored takes them so. Each node also holds an order of its own (wide_node::order),
// which visit_order::ranked follows and order_children() writes. For occlusion a better guess puts first
// the children most likely to end the query at least cost: leaves before inner nodes (a leaf's triangles
// answer at once; an inner node costs a descent first), and, within each, the larger box first (a ray that
// enters a node enters a larger child more often, and a large box of a real scene often holds a wall or a
// floor). That holds for rays without end; a segment (a shadow ray to its light) mostly meets large boxes
// of the surfaces it starts from or passes by, and the stored order tests fewer boxes there, so the walks
// follow this order only where tmax is infinite (NOTES.md).
//   T. Ize and C. Hansen, "RTSAH traversal order for occlusion rays", Computer Graphics Forum 30(2)
//   (Eurographics) 2011 (the order by the probability of a hit and the cost to find it; this is its cheap
//   cousin, fixed at build time, with surface area for the probability);
//   J. D. MacDonald and K. S. Booth, "Heuristics for ray tracing using space subdivision", The Visual
//   Computer 6(3), 1990 (surface area as the chance that a ray entering a box enters a child).
#pragma once
#include "strahl/inlining.hpp"
#include "strahl/ch13/wide_bvh.hpp"
#include <algorithm>

namespace strahl::ch13 {

enum class child_order {
    collapsed,         // as the collapse left them: the binary tree's order
    leaves_then_area,  // leaves first, then inner nodes; each by decreasing surface area; unused slots last
};

// A child's rank for leaves_then_area: larger ranks first.
template <int N>
float any_hit_rank(const wide_node<N>& n, int i) {
    if (!n.used(i)) return -1.0f;
    const vec3 d = n.box(i).extent();
    const float area = d.x * d.y + d.y * d.z + d.z * d.x;  // half the surface area: only the order counts
    return is_leaf(n.child[i]) ? 0x1p100f + area : area;  // 2^100 over any area of a finite tree's box
}

// Writes every node's any-hit order (wide_node::order) for `order` (collapsed: the collapse already wrote
// it). The children stay in their slots, so closest hit (which breaks ties between equal entry distances by
// slot) is untouched, and every answer stays the same.
template <int N, int M>
void order_children(wide_bvh<N, M>& tree, child_order order) {
    if (order == child_order::collapsed) return;
    for (wide_node<N>& n : tree.nodes) {
        int slot[N];
        float rank[N];
        for (int i = 0; i < N; ++i) slot[i] = i, rank[i] = any_hit_rank(n, i);
        std::stable_sort(slot, slot + N, [&](int a, int b) { return rank[a] > rank[b]; });
        for (int j = 0; j < N; ++j) n.order[j] = std::uint8_t(slot[j]);
    }
}

// Closest hit's order per ray octant (wide_node::octant_order): for each of the 8 octants of directions, the
// used children by the position of their box's centre along the octant's diagonal (nearest first), unused
// slots last. An estimate of the front-to-back order made once, at build, in place of sorting the boxes a
// ray enters by their entry distance (tinybvh's 8-wide nodes keep such an order, keyed by the near corner;
// the centre measured better on Sponza, whose large boxes overlap: NOTES.md).
template <int M>
void order_by_octant(wide_bvh<8, M>& tree) {
    for (wide_node<8>& n : tree.nodes) {
        float centre[3][8];  // twice each child's centre; an unused slot's is never read
        for (int a = 0; a < 3; ++a)
            for (int k = 0; k < 8; ++k) centre[a][k] = n.lo[a][k] + n.hi[a][k];
        for (int o = 0; o < 8; ++o) {
            float key[8];
            for (int k = 0; k < 8; ++k) {
                float c = 0.0f;
                for (int a = 0; a < 3; ++a) c += ((o >> a) & 1) ? -centre[a][k] : centre[a][k];
                key[k] = n.used(k) ? c : 0x1p127f;  // unused slots last
            }
            // Each slot's place is the number of slots before it (smaller key, or an equal one at a lower
            // slot): no branches, no allocation (a sort per octant cost more than the collapse on small trees).
            std::uint32_t w = 0;
            for (int k = 0; k < 8; ++k) {
                int place = 0;
                for (int j = 0; j < 8; ++j) place += (key[j] < key[k]) | ((key[j] == key[k]) & (j < k));
                w |= std::uint32_t(k) << (3 * place);
            }
            n.set_octant_word(o, w);
        }
    }
}

// The bits of `slots` (a node's children by slot) moved to rank positions: bit j set where the j-th child
// of n.order is in `slots`. The walks visit the result's bits in order, child n.order[j] for bit j.
template <class Node>
STRAHL_ALWAYS_INLINE inline unsigned ranked_bits(const Node& n, unsigned slots) {
    constexpr int N = sizeof(n.order);
    unsigned ranked = 0;
    for (int j = 0; j < N; ++j) ranked |= ((slots >> n.order[j]) & 1u) << j;
    return ranked;
}

}  // namespace strahl::ch13
