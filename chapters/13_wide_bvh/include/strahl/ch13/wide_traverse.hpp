// One ray through the wide BVH: at each node, the N children's boxes in one SIMD slab test; the children hit
// are visited nearest first (the others go on a stack with their entry distance, and are dropped when popped
// if a hit found since lies before them); at a leaf, its triangles M at a time (block_test.hpp).
//   I. Wald, C. Benthin and S. Boulos, "Getting rid of packets", IEEE RT 2008 (single rays through wide nodes);
//   A. Williams et al., "An efficient and robust ray-box intersection algorithm", JGT 2005, and T. Ize,
//   "Robust BVH ray traversal", JCGT 2013 (the slab tests: chapter 05's slab_test.hpp, here on N lanes).
#pragma once
#include "strahl/ch04/traverse.hpp"
#include "strahl/ch05/slab_test.hpp"
#include "strahl/ch13/child_order.hpp"
#include "strahl/ch13/quantized_node.hpp"
#include "strahl/ch13/wide_bvh.hpp"
#include "strahl/inlining.hpp"
#include "strahl/simd.hpp"
#include <bit>
#include <cstddef>

namespace strahl::ch13 {

// strahl/tree_query.hpp's ray_slack, bounded from above without a square root: |v| <= |x| + |y| + |z| for
// the distances, |d| >= max(|dx|, |dy|, |dz|) for the direction, and the tree's diagonal (precomputed in
// wide_bvh::diagonal) in place of its own. A larger slack only widens the box tests: never a box lost.
template <int N, int M, class Node>
STRAHL_ALWAYS_INLINE inline float wide_ray_slack(const ray& r, const wide_bvh<N, M, Node>& tree) {
    const vec3 to = r.org - tree.centre;
    const float reach = (std::fabs(to.x) + std::fabs(to.y) + std::fabs(to.z)) + tree.diagonal;
    const float len = std::max(std::fabs(r.dir.x), std::max(std::fabs(r.dir.y), std::fabs(r.dir.z)));
    return (reach * 0x1p-16f + 1e-5f * tree.diagonal) / len * (1.0f + 0x1p-20f);
}

// Where the near and the far plane of each axis sit in a node, chosen once per ray from the direction's
// signs: byte offsets of the rows lo[a] or hi[a].
template <int N>
struct plane_rows {
    std::size_t near_row[3], far_row[3];
    int near_q[3], far_q[3];  // the same rows of a quantised node (qnode::row)
    int octant = 0;           // bit a set where dir[a] is negative (wide_node::octant_order)
    explicit plane_rows(const vec3& dir) {
        octant = int(std::signbit(dir.x)) | int(std::signbit(dir.y)) << 1 | int(std::signbit(dir.z)) << 2;
        for (int a = 0; a < 3; ++a) {
            near_q[a] = std::signbit(dir[a]) ? 3 + a : a;
            far_q[a] = std::signbit(dir[a]) ? a : 3 + a;
            const std::size_t lo = offsetof(wide_node<N>, lo) + a * N * sizeof(float);
            const std::size_t hi = offsetof(wide_node<N>, hi) + a * N * sizeof(float);
            near_row[a] = std::signbit(dir[a]) ? hi : lo;
            far_row[a] = std::signbit(dir[a]) ? lo : hi;
        }
    }
    static const float* row(const wide_node<N>& n, std::size_t offset) {
        return reinterpret_cast<const float*>(reinterpret_cast<const char*>(&n) + offset);
    }
};

// Chapter 05's fast slab test on N boxes: a plane's t = plane * (1 / d) - org * (1 / d), the origin's term
// moved outward once per ray (ch05::fast_slab: its bound covers every box inside the tree's), fused where
// the processor has FMA. entry() is exercise 13.2 (node_entry, below).
template <int N, bool Fused = ch05::fused_plane_default>
struct wide_fast_slab : plane_rows<N> {
    using vf = simd::vfloat<N>;
    vf inv[3], org_near[3], org_far[3];
    explicit wide_fast_slab(const ray& r, const ch05::fast_slab& s) : plane_rows<N>(r.dir) {
        for (int a = 0; a < 3; ++a) inv[a] = vf(s.inv_dir[a]), org_near[a] = vf(s.org_near[a]), org_far[a] = vf(s.org_far[a]);
    }
    // The walk's per-ray set-up: ch05::fast_slab::make's terms computed in float, with twice its widening
    // (eps = 2^-19 (p + |o|), 32 units of rounding where chapter 05's proof needs 16 and the float
    // arithmetic here adds at most 3 more), so no double conversion per ray; widen = 0 drops the bound (the
    // tests show boxes are then lost). ok is false where make() would give nothing (a direction component zero, subnormal, or so small that a plane's t overflows).
    wide_fast_slab(const ray& r, const aabb& bounds, bool& ok, float widen = 0x1p-19f) : plane_rows<N>(r.dir) {
        ok = true;
        for (int a = 0; a < 3; ++a) {
            const float i = 1.0f / r.dir[a], o = r.org[a];
            const float span = std::max(std::fabs(bounds.min[a]), std::fabs(bounds.max[a])) + std::fabs(o);
            const float eps = widen * span, toward = std::copysign(eps, i), tiny = widen > 0.0f ? 0x1p-126f : 0.0f;
            ok = ok && std::fabs(i) <= 0x1p100f && (span + eps) * std::fabs(i) <= 0x1p100f;
            inv[a] = vf(i);
            org_near[a] = vf((o + toward) * i + tiny);
            org_far[a] = vf((o - toward) * i - tiny);
        }
    }
    // A plane's t: plane * inv_dir - org_term, in one fused multiply-add or a multiply and a subtract.
    STRAHL_ALWAYS_INLINE static vf plane_t(vf plane, vf inv_dir, vf org_term) {
        if constexpr (Fused) return simd::fmsub(plane, inv_dir, org_term);
        else return plane * inv_dir - org_term;
    }
    vf entry(const wide_node<N>& n, float t0, float t1, simd::vmask<N>& hit) const;
    // The same on a quantised node, each row decoded where it is read.
    STRAHL_ALWAYS_INLINE vf entry(const qnode<N>& n, float t0, float t1, simd::vmask<N>& hit) const {
        vf lo(t0), hi(t1);
        for (int a = 0; a < 3; ++a) {
            const vf near = plane_t(n.row(this->near_q[a]), inv[a], org_near[a]);
            const vf far = plane_t(n.row(this->far_q[a]), inv[a], org_far[a]);
            lo = simd::max(near, lo);
            hi = simd::min(far, hi);
        }
        hit = lo <= hi;
        return lo;
    }
};

// Exercise 13.2, the slab test of one ray against the N boxes of node n in one go (traversal.cpp): the
// entry distance of every child's box for t in [t0, t1]; hit marks the boxes the ray enters. Lane k computes
// what ch05::fast_slab::entry computes for child k's box, bit for bit.
template <int N, bool Fused>
simd::vfloat<N> node_entry(const wide_node<N>& n, const wide_fast_slab<N, Fused>& s, float t0, float t1,
                           simd::vmask<N>& hit);

template <int N, bool Fused>
STRAHL_ALWAYS_INLINE inline simd::vfloat<N> wide_fast_slab<N, Fused>::entry(const wide_node<N>& n, float t0,
                                                                           float t1, simd::vmask<N>& hit) const {
    return node_entry(n, *this, t0, t1, hit);
}

// A child on the walk's stack, with the distance at which the ray enters its box.
struct stack_entry {
    std::uint32_t ref;
    float t;
};

// Exercise 13.3, the ordered push (traversal.cpp): of a node's children, those whose bits are set in `bits`
// (two or more) with entry distances t[k] and references child[k]. Pushes all but the nearest onto the
// stack (stack[top++]), the farthest first, so that the nearer ones are popped first, and returns the
// nearest child's reference, to be visited now. Equal distances: the lower child index counts as nearer.
template <int N>
std::uint32_t push_ordered(unsigned bits, const float* t, const std::uint32_t* child, stack_entry* stack, int& top);

// The two exercises called on their own, out of line (for the tests; N = 4, 8, 16).
template <int N, bool Fused>
simd::vfloat<N> node_entry_out_of_line(const wide_node<N>& n, const wide_fast_slab<N, Fused>& s, float t0, float t1,
                                       simd::vmask<N>& hit);
template <int N>
std::uint32_t push_ordered_out_of_line(unsigned bits, const float* t, const std::uint32_t* child, stack_entry* stack,
                                       int& top);

// Chapter 05's robust_slab on N boxes, for rays the fast one cannot take (a zero or tiny direction
// component): each box grown by `grow` (space_slack) on every side, t = (plane - org) * (1 / d), a NaN never
// wins a comparison, the exit widened by 1 + 2 gamma(3). The growth is folded into the origin: the near
// plane's origin term moves by grow toward the box, the far plane's away.
template <int N>
struct wide_robust_slab : plane_rows<N> {
    using vf = simd::vfloat<N>;
    vf org_near[3], org_far[3], inv[3];
    wide_robust_slab(const ray& r, float grow) : plane_rows<N>(r.dir) {
        for (int a = 0; a < 3; ++a) {
            const float toward = std::signbit(r.dir[a]) ? -grow : grow;  // near plane is bmin going up the axis
            org_near[a] = vf(r.org[a] + toward), org_far[a] = vf(r.org[a] - toward), inv[a] = vf(1.0f / r.dir[a]);
        }
    }
    STRAHL_ALWAYS_INLINE vf entry(const wide_node<N>& n, float t0, float t1, simd::vmask<N>& hit) const {
        vf lo(t0), hi(t1);
        for (int a = 0; a < 3; ++a) {
            const vf near = (vf::load(this->row(n, this->near_row[a])) - org_near[a]) * inv[a];
            const vf far = (vf::load(this->row(n, this->far_row[a])) - org_far[a]) * inv[a];
            lo = simd::max(near, lo);
            hi = simd::min(far, hi);
        }
        const vf up(1.0f + 2.0f * ch04::gamma(3)), down(1.0f - 2.0f * ch04::gamma(3));
        hi = hi * simd::select(hi > vf(0.0f), up, down);
        hit = lo <= hi;
        return lo;
    }
};

// The walk: calls leaf(ref) for each leaf the ray reaches (nearest first), reading r.tmax (shrunk by hits)
// to prune; stops when leaf returns true. Boxes are tested against [tmin - below, tmax + slack]
// (strahl/tree_query.hpp's ray_slack), as in chapters 04 and 05: below = slack for the exact answer;
// chapter 14's strict variant passes 0 (a measured trade, not exact).
// (g++ 12 thinks the stack may be read before it is written when N = 16; entries are popped only after
// being pushed.)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
// Which child a node hands the walk first when several boxes are hit.
enum class visit_order {
    nearest,  // closest hit: nearest entry first (exercise 13.3), so hits found early prune the rest
    stored,   // any hit: the children in the order the node stores them, no sorting: any hit ends the walk,
              // and the sort costs more than it saves (Embree's any-hit walk does not sort either)
    ranked,   // any hit: the children in the node's own order (wide_node::order, child_order.hpp)
    octant,   // closest hit: the children in the node's order for the ray's octant (wide_node::octant_order)
};

// Exercise 13.3's push, as the walk calls it.
template <int N>
struct ordered_push {
    STRAHL_ALWAYS_INLINE std::uint32_t operator()(unsigned bits, const float* t, const std::uint32_t* child,
                                                  stack_entry* stack, int& top) const {
        return push_ordered<N>(bits, t, child, stack, top);
    }
};

// start: the node (or leaf) the walk begins at, the root unless chapter 14 hands it a ray further down;
// push: the ordered push (chapter 14 brings its own).
template <visit_order Order, int N, int M, class Node, class Slab, class Stats, class Leaf, class Push = ordered_push<N>>
void wide_walk(const wide_bvh<N, M, Node>& tree, const Slab& s, float below, float slack, ray& r, Stats& stats,
               Leaf&& leaf, std::uint32_t start, Push push = {}) {
    stack_entry stack[ch04::bvh_max_depth * (N - 1) + 2];
    int top = 0;
    std::uint32_t ref = start;
    for (;;) {
        if (!is_leaf(ref)) {
            const Node& n = tree.nodes[ref];
            stats.node_visit();
            stats.box_test(N);
            simd::vmask<N> hit;
            simd::vfloat<N> t;
            if constexpr (requires { s.entry(n, 0.0f, 0.0f, hit); }) {
                t = s.entry(n, r.tmin - below, r.tmax + slack, hit);
            } else {
                wide_node<N> scratch;  // a quantised node's planes, decoded for a slab test of float rows
                t = s.entry(planes_of(n, scratch), r.tmin - below, r.tmax + slack, hit);
            }
            const unsigned bits = simd::movemask(hit) & used_slots(n);
            if (bits != 0) {
                if ((bits & (bits - 1)) == 0) {  // one child hit: go there
                    ref = n.child[std::countr_zero(bits)];
                    continue;
                }
                alignas(64) float ts[N];
                t.store(ts);
                if constexpr (Order == visit_order::nearest) {
                    // Several: the nearest now, the others on the stack (exercise 13.3).
                    ref = push(bits, ts, n.child, stack, top);
                } else if constexpr (Order == visit_order::octant) {
                    // Several, in the order for the ray's octant: the hit bits moved to positions, the first
                    // now, the others on the stack, the last deepest.
                    const std::uint32_t w = n.octant_word(s.octant);
                    unsigned ranked = 0;
                    for (int j = 0; j < N; ++j) ranked |= ((bits >> ((w >> (3 * j)) & 7)) & 1u) << j;
                    ref = n.child[(w >> (3 * std::countr_zero(ranked))) & 7];
                    for (unsigned rest = ranked & (ranked - 1); rest != 0;) {
                        const int j = 31 - std::countl_zero(rest);
                        const int k = (w >> (3 * j)) & 7;
                        stack[top++] = {n.child[k], ts[k]};
                        rest &= ~(1u << j);
                    }
                } else if constexpr (Order == visit_order::ranked) {
                    // Several, in the node's order: the hit bits moved to rank positions, the first ranked
                    // now, the others on the stack, the last ranked deepest.
                    const unsigned ranked = ranked_bits(n, bits);
                    ref = n.child[n.order[std::countr_zero(ranked)]];
                    for (unsigned rest = ranked & (ranked - 1); rest != 0;) {
                        const int j = 31 - std::countl_zero(rest);
                        stack[top++] = {n.child[n.order[j]], ts[n.order[j]]};
                        rest &= ~(1u << j);
                    }
                } else {
                    // Several: the first stored now, the others on the stack, the last stored deepest.
                    ref = n.child[std::countr_zero(bits)];
                    for (unsigned rest = bits & (bits - 1); rest != 0;) {
                        const int k = 31 - std::countl_zero(rest);
                        stack[top++] = {n.child[k], ts[k]};
                        rest &= ~(1u << k);
                    }
                }
                continue;
            }
        } else if (leaf(ref)) {
            return;
        }
        // Pop the next child whose entry still lies within the (shrunk) range.
        for (;;) {
            if (top == 0) return;
            const stack_entry e = stack[--top];
            if (e.t <= r.tmax + slack) {
                ref = e.ref;
                break;
            }
        }
    }
}

#pragma GCC diagnostic pop

// The walk on chapter 05's robust slab test alone (wide_robust_slab): for the rays the fast test refuses,
// and for the few rays another chapter's tracer hands to this tree (a packet tracer's refused rays, in the
// stored order: no exercise of this chapter in it). Exact as the fast walk is; slower.
template <visit_order Order = visit_order::stored, int N, int M, class Node, class Stats, class Leaf>
void robust_walk(const wide_bvh<N, M, Node>& tree, ray& r, Stats& stats, Leaf&& leaf) {
    if (tree.nodes.empty() && !is_leaf(tree.root_ref)) return;
    const float slack = wide_ray_slack(r, tree);
    wide_walk<Order>(tree, wide_robust_slab<N>(r, space_slack(r, tree.bounds)), slack, slack, r, stats, leaf,
                     tree.root_ref);
}

// The walk with chapter 05's choice of slab test: the fast one where the ray allows it, else the robust one.
// Flattened: g++ called chapter 05's fast_slab::make and the slab's set-up out of line here, a third of the
// time of a ray that misses the tree (perf, the bunny's primary rays).
template <visit_order Order, int N, int M, class Node, class Stats, class Leaf>
STRAHL_FLATTEN void wide_traverse(const wide_bvh<N, M, Node>& tree, ray& r, Stats& stats, Leaf&& leaf) {
    if (tree.nodes.empty() && !is_leaf(tree.root_ref)) return;
    bool fast = false;
    const wide_fast_slab<N> s(r, tree.bounds, fast);
    if (!fast) return robust_walk<Order>(tree, r, stats, leaf);
    const float slack = wide_ray_slack(r, tree);
    wide_walk<Order>(tree, s, slack, slack, r, stats, leaf, tree.root_ref);
}

}  // namespace strahl::ch13
