// A packet of K rays through chapter 13's wide BVH: at each node, the K rays against each of its N child
// boxes in turn (K lanes, one box broadcast), as Embree's hybrid kernels do (a coherent packet only against
// the boxes its frustum may enter, found by one test of all N); the children that any ray
// enters are visited nearest first (by the smallest entry distance over the rays that enter), each with the
// lanes that entered it. Leaves: every triangle of the leaf's blocks against the K rays.
//   I. Wald, C. Benthin and S. Boulos, "Getting rid of packets", IEEE RT 2008 (wide nodes);
//   I. Wald, S. Woop, C. Benthin, G. S. Johnson and M. Ernst, "Embree: a kernel framework for efficient CPU
//   ray tracing", ACM TOG 33(4), 2014 (packets through wide nodes, section 5).
#pragma once
#include "strahl/inlining.hpp"
#include "strahl/ch04/bvh.hpp"
#include "strahl/ch12/binary_walks.hpp"
#include "strahl/ch12/frustum_walk.hpp"
#include "strahl/ch12/packet.hpp"
#include "strahl/ch13/child_order.hpp"
#include "strahl/ch13/wide_bvh.hpp"
#include <bit>
#include <cmath>

namespace strahl::ch12 {

// What chapter 14 changes in this walk. box: K rays against one box (chapter 12: exercise 12.1's
// packet_box). leave(lanes, ref): called before the packet enters node or leaf `ref` with `lanes` (on the way
// down and after a pop); true when it has traced those lanes' rays through `ref` by other means (chapter 14:
// each alone), so that the packet skips `ref` (chapter 12: never); it may change those lanes' tmax, t1, best
// hit and active bit, nothing else of the packet.
template <bool Coherent>
struct packet_hooks {
    template <int K>
    STRAHL_ALWAYS_INLINE simd::vmask<K> box(const lane_rays<K>& r, const float* bmin, const float* bmax, int octant,
                                            simd::vfloat<K>& entry) const {
        return packet_box<Coherent>(r, bmin, bmax, octant, entry);
    }
    static constexpr bool leave(unsigned, std::uint32_t) { return false; }
};

// Which child a node hands the walk first (chapter 13's visit_order): nearest for closest hit; for any hit
// no sorting: the node's own order where no lane's ray ends, else the stored order.
template <bool Nearest, bool Coherent, int K, int N, int M, class Stats, class Leaf, class Hooks = packet_hooks<Coherent>>
void wide_packet_walk(const ch13::wide_bvh<N, M>& tree, ray_packet<K, 1>& p, Stats& stats, Leaf&& leaf,
                      Hooks&& hooks = {}) {
    struct entry {
        std::uint32_t ref;
        unsigned lanes;
        float t;
    };
    entry stack[ch04::bvh_max_depth * (N - 1) + 2];
    int top = 0;
    const auto at = [](int j) { return j; };
    std::uint32_t ref = tree.root_ref;
    unsigned lanes = p.active[0];
    lane_rays<K> r = load(p, 0);
    // The lanes' extremes of t0 and t1 (over every lane: lanes out of play only make them more cautious),
    // computed again only when t1 changes (after a leaf, or rays that left).
    const float t0_hi = simd::reduce_max(r.t0);
    float t1_lo = simd::reduce_min(r.t1), t1_hi = simd::reduce_max(r.t1);
    const auto reach = [&] {
        reload_reach(r, p, 0);
        t1_lo = simd::reduce_min(r.t1), t1_hi = simd::reduce_max(r.t1);
        p.t1_hi = t1_hi;  // the frustum's far end
    };
    if (tree.nodes.empty() && !ch13::is_leaf(ref)) return;
    for (;;) {
        if (hooks.leave(lanes, ref)) {
            // The lanes' rays went on alone through `ref`: the packet skips it, with their new reach.
            if (p.active[0] == 0) return;  // any hit: every ray answered
            reach();
        } else if (!ch13::is_leaf(ref)) {
            const ch13::wide_node<N>& n = tree.nodes[ref];
            stats.node_visit();
            if constexpr (Coherent) stats.box_test(N);  // the frustum's test
            count_lanes(stats, std::popcount(lanes), K);
            entry hits[N];
            int count = 0;
            // A coherent packet first tests its frustum against all N boxes at once (frustum_walk.hpp): the
            // rays themselves are tested only against the boxes the frustum may enter.
            // Children that every lane surely enters keep the packet's lanes untested.
            unsigned candidates = (1u << N) - 1, covered = 0;
            alignas(64) float bounds[N];
            if constexpr (Coherent) {
                simd::vfloat<N> bound;
                candidates = frustum_children<true>(p, n, bound, t0_hi, t1_lo, &covered);
                bound.store(bounds);
            }
            // Any hit on rays without end (every lane's t1 infinite): the children in the node's own order
            // (chapter 13's child_order.hpp; the collapse's is the stored order), the candidates' bits moved
            // to rank positions.
            const bool ranked = !Nearest && std::isinf(t1_lo);
            const unsigned visit = ranked ? ch13::ranked_bits(n, candidates) : candidates;
            for (unsigned rest = visit; rest != 0; rest &= rest - 1) {
                const int c = ranked ? n.order[std::countr_zero(rest)] : std::countr_zero(rest);
                if (!n.used(c)) continue;
                if ((covered >> c) & 1u) {
                    int j = count++;
                    if constexpr (Nearest)
                        for (; j > 0 && hits[j - 1].t <= bounds[c]; --j) hits[j] = hits[j - 1];
                    hits[j] = {n.child[c], lanes, bounds[c]};
                    continue;
                }
                stats.box_test(std::popcount(lanes));
                const float bmin[3] = {n.lo[0][c], n.lo[1][c], n.lo[2][c]};
                const float bmax[3] = {n.hi[0][c], n.hi[1][c], n.hi[2][c]};
                simd::vfloat<K> t;
                const simd::vmask<K> enters = hooks.box(r, bmin, bmax, p.octant, t);
                const unsigned in = simd::movemask(enters) & lanes;
                if (in == 0) continue;
                // The nearest entry, over every lane that enters (lanes outside `lanes` too: a smaller value
                // only orders and prunes more cautiously), in a few SIMD steps.
                float nearest = inf;
                if constexpr (Nearest && Coherent) nearest = bounds[c];
                else if constexpr (Nearest) nearest = simd::reduce_min(simd::select(enters, t, simd::vfloat<K>(inf)));
                // Insertion by distance, farthest first (stored order: appended).
                int j = count++;
                if constexpr (Nearest)
                    for (; j > 0 && hits[j - 1].t <= nearest; --j) hits[j] = hits[j - 1];
                hits[j] = {n.child[c], in, nearest};
            }
            if (count > 0) {
                if constexpr (Nearest) {
                    for (int j = 0; j + 1 < count; ++j) stack[top++] = hits[j];
                    ref = hits[count - 1].ref, lanes = hits[count - 1].lanes;
                } else {
                    for (int j = count - 1; j > 0; --j) stack[top++] = hits[j];
                    ref = hits[0].ref, lanes = hits[0].lanes;
                }
                continue;
            }
        } else {
            leaf(r, lanes, at, ref);
            if (p.active[0] == 0) return;  // any hit: every ray answered
            reach();  // tmax shrunk by the hits
        }
        // Pop the next child whose lanes are still in play and whose nearest entry still lies within reach.
        for (;;) {
            if (top == 0) return;
            const entry e = stack[--top];
            unsigned keep = e.lanes & p.active[0];
            if (keep == 0) continue;
            if constexpr (Nearest)
                if (!(e.t <= t1_hi)) continue;
            ref = e.ref, lanes = keep;
            break;
        }
    }
}

}  // namespace strahl::ch12
