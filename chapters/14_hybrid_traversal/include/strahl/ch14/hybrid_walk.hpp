// The hybrid walk: a packet goes down chapter 13's 8-wide tree as in chapter 12's wide walk (K rays against
// each child box); before it enters a node or a leaf, if as few as `threshold` of its lanes are left, those
// rays leave it: each goes on alone from that node with chapter 13's single-ray walk (one ray against the N
// children at once, its own stack), and comes back with its hit, its shrunk tmax and, for any hit, whether
// it is answered. The packet then goes on without that node, its other entries pruned by the rays' new
// reach. The check happens on the way down and on each pop, so a packet that thins out at depth lets its
// last rays go where it happens.
//   C. Benthin, I. Wald, S. Woop, M. Ernst and W. R. Mark, "Combining single and packet-ray tracing for
//   arbitrary ray distributions on the Intel MIC architecture", IEEE TVCG 18(9), 2012;
//   I. Wald, S. Woop, C. Benthin, G. S. Johnson and M. Ernst, "Embree: a kernel framework for efficient CPU
//   ray tracing", ACM TOG 33(4), 2014 (the hybrid intersectors, section 5.3).
#pragma once
#include "strahl/inlining.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch12/packet.hpp"
#include "strahl/ch13/block_test.hpp"
#include "strahl/ch13/wide_traverse.hpp"
#include "strahl/ch14/accel.hpp"
#include "strahl/ch14/lane_slab.hpp"
#include <bit>
#include <cmath>
#include <functional>

namespace strahl::ch14 {

// A ray out of its packet: the lane's ray (its tmax as far as the packet got), its fast-slab terms, the
// best hit so far (closest hit) or whether it is blocked (any hit).
struct lone_ray {
    ray r;
    float slack = 0.0f;
    hit best;
    bool blocked = false;
};

// Exercise 14.2 (hybrid.cpp): the packet's coherence, from its active lanes (p.active[0]) only.
template <int K>
coherence packet_coherence(const ch12::ray_packet<K, 1>& p);

// Exercise 14.2 (hybrid.cpp): the threshold for a packet of K lanes of this coherence: K / 4 for a packet in
// one octant whose spread is below rule.tight, else K / 2.
int packet_threshold(const coherence& c, int lanes, const threshold_rule& rule);

// Exercise 14.3 (hybrid.cpp): the hand-off. Each ray of `lanes` leaves packet p: its lone_ray is made
// from its lane (org, dir, tmin, tmax, slack, p.best(k)), alone(k, lone) traces it, and the lane takes the
// answer back: closest hit (Any false) the best hit (p.set_best), tmax and t1 = tmax + slack; any hit (Any
// true): a blocked ray is answered (its lane's best hit set to the lone ray's, which names the blocking
// triangle, its bit cleared from p.active[0]). Lanes outside `lanes` are not touched.
template <bool Any, int K, class Alone>
void hand_off(ch12::ray_packet<K, 1>& p, unsigned lanes, Alone&& alone);

// The ordered push of the lone walk: the hit children by entry distance, nearest popped first (exercise
// 13.3's contract).
template <int N>
struct nearest_push {
    STRAHL_ALWAYS_INLINE std::uint32_t operator()(unsigned bits, const float* t, const std::uint32_t* child,
                                                  ch13::stack_entry* stack, int& top) const {
        ch13::stack_entry hits[N];
        int count = 0;
        for (; bits != 0; bits &= bits - 1) {
            const int k = std::countr_zero(bits);
            int j = count++;
            for (; j > 0 && hits[j - 1].t <= t[k]; --j) hits[j] = hits[j - 1];
            hits[j] = {child[k], t[k]};
        }
        for (int j = 0; j + 1 < count; ++j) stack[top++] = hits[j];
        return hits[count - 1].ref;
    }
};

// The walk's hooks (chapter 12's wide_packet_walk): the box test through lane_slab, and the switch.
// Octant: the lone closest-hit walk takes each node's children in its order for the ray's octant
// (hybrid_config::octant_order), else by entry distance. A template parameter, not a flag: with both walks
// compiled into alone() behind a runtime flag, the tracer that never takes the octant's walk ran 10 to 15 %
// slower on the stadium's diffuse rays, with the same counters (the code the compiler made; NOTES.md).
template <bool Any, bool Coherent, int K, int N, int M, class Stats, bool Octant = false>
struct hybrid_hooks {
    const ch13::wide_bvh<N, M>& tree;
    ch12::ray_packet<K, 1>& p;
    Stats& stats;
    int threshold;
    bool strict = false;  // hybrid_config::strict: the lone walk tests boxes from tmin, not tmin - slack
    bool ranked = false;  // any hit: rays without end visit children in the node's order (child_order.hpp)

    STRAHL_ALWAYS_INLINE simd::vmask<K> box(const ch12::lane_rays<K>& r, const float* bmin, const float* bmax,
                                            int octant, simd::vfloat<K>& entry) const {
        return rays_box<Coherent>(r, bmin, bmax, octant, entry);
    }

    // The check runs at every node and stays in the walk; the hand-off is out of line (a call the walk pays
    // for only where rays leave).
    STRAHL_ALWAYS_INLINE bool leave(unsigned lanes, std::uint32_t ref) {
        if (std::popcount(lanes) > threshold) return false;
        leave_now(lanes, ref);
        return true;
    }
    [[gnu::noinline]] void leave_now(unsigned lanes, std::uint32_t ref) {
        hand_off<Any>(p, lanes, [&](int k, lone_ray& l) {
            if constexpr (requires { stats.left(k); }) stats.left(k);
            alone(k, l, ref);
        });
    }

    // Lane k's ray through `ref` alone: chapter 13's walk started there, its leaves' blocks by chapter
    // 13's block test.
    void alone(int k, lone_ray& l, std::uint32_t ref) {
        const ray_node_slab<N> s(p, k, l.r.dir);
        const ch13::ray_lanes<M> lanes(l.r);
        ray& r = l.r;
        const auto leaf = [&](std::uint32_t leaf_ref) STRAHL_INLINE_LAMBDA {
            const ch13::triangle_block<M>* b = &tree.blocks[ch13::leaf_first(leaf_ref)];
            for (std::uint32_t n = ch13::leaf_blocks(leaf_ref); n-- > 0; ++b) {
                stats.prim_test(M);
                simd::vfloat<M> t, u, v;
                unsigned bits = simd::movemask(ch13::intersect_block(*b, lanes, r.tmin, r.tmax, t, u, v));
                if (bits == 0) continue;
                if constexpr (Any) {
                    l.blocked = true, l.best.prim = b->id[std::countr_zero(bits)];
                    return true;
                }
                alignas(64) float ts[M], us[M], vs[M];
                t.store(ts), u.store(us), v.store(vs);
                for (; bits != 0; bits &= bits - 1) {
                    const int i = std::countr_zero(bits);
                    ch01::record_closest(b->id[i], ts[i], us[i], vs[i], r, l.best);
                }
            }
            return false;
        };
        const float below = strict ? 0.0f : l.slack;
        if constexpr (!Any) {
            if constexpr (Octant) ch13::wide_walk<ch13::visit_order::octant>(tree, s, below, l.slack, r, stats, leaf, ref);
            else ch13::wide_walk<ch13::visit_order::nearest>(tree, s, below, l.slack, r, stats, leaf, ref, nearest_push<N>{});
        }
        else if (ranked && std::isinf(r.tmax))
            ch13::wide_walk<ch13::visit_order::ranked>(tree, s, below, l.slack, r, stats, leaf, ref, nearest_push<N>{});
        else
            ch13::wide_walk<ch13::visit_order::stored>(tree, s, below, l.slack, r, stats, leaf, ref, nearest_push<N>{});
    }
};

// The exercises 14.2 and 14.3 called on their own, out of line (for the tests; K = 8 and 16 for the
// coherence, 16 for the hand-off).
template <int K>
coherence packet_coherence_out_of_line(const ch12::ray_packet<K, 1>& p);
template <bool Any, int K>
void hand_off_out_of_line(ch12::ray_packet<K, 1>& p, unsigned lanes, const std::function<void(int, lone_ray&)>& alone);

}  // namespace strahl::ch14
