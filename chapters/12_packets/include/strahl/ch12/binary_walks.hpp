// Packets through chapter 05's binary BVH, two ways.
//   masked_walk: K rays, one SIMD vector; a node is visited while any of the lanes that entered its parent
//     enters its box (both children tested at the parent); a lane that misses rides along, masked off (I. Wald, P. Slusallek, C. Benthin and
//     M. Wagner, "Interactive rendering with coherent ray tracing", Eurographics 2001).
//   ranged_walk: V vectors of K rays (a large packet, 64 rays and more); at each node the walk tests the
//     first vector still in play (an early hit costs one SIMD test for the whole packet); where it misses,
//     the packet's interval-arithmetic frustum may cull the node for all its rays in one test; else the next
//     vectors are tested until one enters, and the rest of the subtree starts from that vector
//     (I. Wald, S. Boulos and P. Shirley, "Ray tracing deformable scenes using dynamic bounding volume
//     hierarchies", ACM TOG 26(1), 2007).
// Both visit the nearer child first, as seen by the first lane that entered the node: its direction's sign
// on the node's split axis. The leaf test is the caller's: leaf(rays, lanes, at, first, count) for the rays
// of `lanes` (lane j is the packet's ray at(j)), the leaf's primitives first .. first + count - 1 of the
// tree's prim_ids. Any-hit leaves clear the lanes they answer from the packet's active bits.
#pragma once
#include "strahl/inlining.hpp"
#include "strahl/ch04/bvh.hpp"
#include "strahl/ch12/packet.hpp"
#include <bit>

namespace strahl::ch12 {

// Counts, for each vector tested at a node, the lanes that enter it (the SIMD work that was useful), where
// Stats can take them (lane_counting, the chapter's program and the tests), nothing otherwise.
template <class Stats>
STRAHL_ALWAYS_INLINE inline void count_lanes(Stats& stats, int active, int width) {
    if constexpr (requires { stats.lanes(active, width); }) stats.lanes(active, width);
}

template <bool Coherent, int K, int V, class Stats, class Leaf>
void masked_walk(const ch04::bvh& tree, ray_packet<K, V>& p, Stats& stats, Leaf&& leaf) {
    static_assert(V == 1, "the masked walk traces one vector of K rays");
    struct entry {
        std::uint32_t node;
        unsigned lanes;
    };
    entry stack[ch04::bvh_max_depth + 2];
    int top = 0;
    const ch04::bvh_node* nodes = tree.nodes.data();
    const auto at = [](int j) { return j; };
    lane_rays<K> r = load(p, 0);
    simd::vfloat<K> t;
    // The root's box; below it, both children's boxes are tested at their parent (as chapter 05's fast walk
    // does), each with the lanes that entered the parent: a child no lane enters is never fetched.
    stats.box_test(std::popcount(p.active[0]));
    unsigned lanes = simd::movemask(packet_box<Coherent>(r, nodes[0].bmin, nodes[0].bmax, p.octant, t)) & p.active[0];
    std::uint32_t index = 0;
    for (;;) {
        if (lanes != 0) {
            const ch04::bvh_node& n = nodes[index];
            stats.node_visit();
            count_lanes(stats, std::popcount(lanes), K);
            if (n.is_leaf()) {
                leaf(r, lanes, at, n.offset, std::uint32_t(n.count));
                reload_reach(r, p, 0);  // tmax shrunk by the hits
            } else {
                const std::uint32_t left = index + 1, right = n.offset;
                stats.box_test(2 * std::popcount(lanes));
                const unsigned in_left = simd::movemask(packet_box<Coherent>(r, nodes[left].bmin, nodes[left].bmax, p.octant, t)) & lanes;
                const unsigned in_right = simd::movemask(packet_box<Coherent>(r, nodes[right].bmin, nodes[right].bmax, p.octant, t)) & lanes;
                if (in_left != 0 && in_right != 0) {
                    // Both: the near child first, as the first lane that entered the node sees it (its direction's
                    // sign on the split axis); the other on the stack with its own lanes.
                    const bool down = std::signbit(p.dir[n.axis][std::countr_zero(lanes)]);
                    stack[top++] = down ? entry{left, in_left} : entry{right, in_right};
                    index = down ? right : left, lanes = down ? in_right : in_left;
                    continue;
                }
                if (in_left != 0 || in_right != 0) {
                    index = in_left != 0 ? left : right, lanes = in_left | in_right;
                    continue;
                }
            }
        }
        // Pop the next child whose lanes are still in play (any hit: lanes answered since it was pushed).
        for (;;) {
            if (top == 0) return;
            --top;
            index = stack[top].node, lanes = stack[top].lanes & p.active[0];
            if (lanes != 0) break;
        }
    }
}

template <bool Coherent, int K, int V, class Stats, class Leaf>
void ranged_walk(const ch04::bvh& tree, ray_packet<K, V>& p, Stats& stats, Leaf&& leaf) {
    struct entry {
        std::uint32_t node;
        int first;
    };
    entry stack[ch04::bvh_max_depth + 2];
    int top = 0;
    const ch04::bvh_node* nodes = tree.nodes.data();
    std::uint32_t index = 0;
    int first = 0;
    for (;;) {
        while (first < V && p.active[first] == 0) ++first;  // (vectors answered whole: any hit)
        if (first < V) {
            const ch04::bvh_node& n = nodes[index];
            stats.node_visit();
            // Vector v against the node's box: the lanes in play that enter it.
            simd::vfloat<K> t;
            const auto test = [&](int v) {
                const unsigned in = simd::movemask(packet_box<Coherent>(load(p, v), n.bmin, n.bmax, p.octant, t)) & p.active[v];
                stats.box_test(std::popcount(p.active[v]));
                count_lanes(stats, std::popcount(in), K);
                return in;
            };
            // 1. The first vector in play: an early hit enters the node for the whole packet.
            int f = first;
            unsigned in = test(f);
            bool enter = in != 0;
            // 2. Else the frustum: one test culls the node for every ray of the packet.
            if (!enter && !(Coherent && frustum_misses(p, n.bmin, n.bmax))) {
                // 3. Else the next vectors, until one enters: the subtree starts from there.
                for (++f; f < V && !enter; f += enter ? 0 : 1) {
                    if (p.active[f] == 0) continue;
                    in = test(f);
                    enter = in != 0;
                }
            }
            if (enter) {
                if (n.is_leaf()) {
                    // The leaf for every vector from f on, each masked by its own box test.
                    leaf(load(p, f), in, [f](int j) { return f * K + j; }, n.offset, std::uint32_t(n.count));
                    for (int v = f + 1; v < V; ++v) {
                        if (p.active[v] == 0) continue;
                        if (const unsigned b = test(v))
                            leaf(load(p, v), b, [v](int j) { return v * K + j; }, n.offset, std::uint32_t(n.count));
                    }
                } else {
                    const bool down = std::signbit(p.dir[n.axis][f * K + std::countr_zero(in)]);
                    stack[top++] = {down ? index + 1 : n.offset, f};
                    index = down ? n.offset : index + 1;
                    first = f;
                    continue;
                }
            }
        }
        if (top == 0) return;
        --top;
        index = stack[top].node, first = stack[top].first;
    }
}

}  // namespace strahl::ch12
