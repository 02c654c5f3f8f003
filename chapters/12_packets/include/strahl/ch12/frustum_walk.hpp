// A coherent packet through chapter 13's wide BVH by its frustum alone: at each node, one SIMD test of the
// packet's interval-arithmetic frustum against all N child boxes (lanes are children, as in chapter 13's
// single-ray walk, the ray replaced by the packet's bounds), nearest child first; the rays themselves are
// tested only at the leaves, each vector first against the leaf's box. A node costs one test for the whole
// packet, however many rays it holds: the way Embree traces packets and streams flagged coherent.
//   I. Wald, S. Boulos and P. Shirley, "Ray tracing deformable scenes using dynamic bounding volume
//   hierarchies", ACM TOG 26(1), 2007 (the interval-arithmetic frustum);
//   A. Reshetov, A. Soupikov and J. Hurley, "Multi-level ray tracing algorithm", SIGGRAPH 2005 (frusta
//   through the tree, rays at the leaves);
//   I. Wald et al., "Embree: a kernel framework for efficient CPU ray tracing", ACM TOG 33(4), 2014.
// Only for coherent packets (every ray in one octant): the frustum needs one near plane per axis.
#pragma once
#include "strahl/inlining.hpp"
#include "strahl/ch04/bvh.hpp"
#include "strahl/ch05/slab_test.hpp"
#include "strahl/ch12/binary_walks.hpp"
#include "strahl/ch12/packet.hpp"
#include "strahl/ch13/wide_bvh.hpp"
#include <bit>

namespace strahl::ch12 {

// The frustum against the N boxes of node n: exercise 12.2's bounds with lanes being the children. Returns
// the children the frustum may enter and, in `entry`, a lower bound of any ray's entry into each.
// With Cover, the same bounds the other way round too: the children every ray of the packet surely enters.
// A lane's computed entry on axis a is at most the largest of the four products plus the margin, its exit at
// least the smallest less it; so where the largest entry bound (and t0_hi, the lanes' largest t0) lies at or
// below the smallest exit bound (and t1_lo, their smallest t1), each lane's own test would say it enters.
// `covered` receives those children (a subset of the candidates).
template <bool Cover = false, int N, int K, int V>
STRAHL_ALWAYS_INLINE inline unsigned frustum_children(const ray_packet<K, V>& p, const ch13::wide_node<N>& n,
                                                      simd::vfloat<N>& entry, float t0_hi = 0.0f,
                                                        float t1_lo = 0.0f, unsigned* covered = nullptr) {
    using vf = simd::vfloat<N>;
    vf lo(p.t0_lo), hi(p.t1_hi), all_lo(t0_hi), all_hi(t1_lo);
    for (int a = 0; a < 3; ++a) {
        const bool down = (p.octant >> a) & 1;
        const vf near = vf::load(down ? n.hi[a] : n.lo[a]), far = vf::load(down ? n.lo[a] : n.hi[a]);
        const vf ilo(p.inv_lo[a]), ihi(p.inv_hi[a]), olo(p.org_lo[a]), ohi(p.org_hi[a]), m(p.margin[a]);
        const vf n1 = near - ohi, n2 = near - olo, f1 = far - ohi, f2 = far - olo;
        const vf a1 = n1 * ilo, a2 = n1 * ihi, a3 = n2 * ilo, a4 = n2 * ihi;
        const vf b1 = f1 * ilo, b2 = f1 * ihi, b3 = f2 * ilo, b4 = f2 * ihi;
        lo = simd::max(lo, simd::min(simd::min(a1, a2), simd::min(a3, a4)) - m);
        hi = simd::min(hi, simd::max(simd::max(b1, b2), simd::max(b3, b4)) + m);
        if constexpr (Cover) {
            all_lo = simd::max(all_lo, simd::max(simd::max(a1, a2), simd::max(a3, a4)) + m);
            all_hi = simd::min(all_hi, simd::min(simd::min(b1, b2), simd::min(b3, b4)) - m);
        }
    }
    entry = lo;
    const unsigned candidates = simd::movemask(lo <= hi);
    if constexpr (Cover) *covered = simd::movemask(all_lo <= all_hi) & candidates;
    return candidates;
}

// leaf(rays, lanes, at, ref, bmin, bmax) for each vector of the packet with lanes in play, the leaf's box
// given so that the leaf can test the vector against it first (and count the lanes that enter: the
// utilisation of this walk is measured at its leaves, where the rays are tested). Nearest: closest hit (nearest child first,
// children dropped when the frustum's far end has come before them); else any hit (stored order).
template <bool Nearest, int K, int V, int N, int M, class Stats, class Leaf>
void frustum_walk(const ch13::wide_bvh<N, M>& tree, ray_packet<K, V>& p, Stats& stats, Leaf&& leaf) {
    struct entry {
        std::uint32_t ref;
        float t;
        const float* box;  // the leaf's box: lo[0][k] of its parent's slot (the other planes N floats apart)
    };
    entry stack[ch04::bvh_max_depth * (N - 1) + N + 1];  // (a node's children are sorted on top of it)
    int top = 0;
    if (tree.nodes.empty() && !ch13::is_leaf(tree.root_ref)) return;
    float root_box[6 * N];  // the whole tree's box in a slot's layout, for a root that is a leaf
    for (int a = 0; a < 3; ++a) root_box[a * N] = tree.bounds.min[a], root_box[(3 + a) * N] = tree.bounds.max[a];
    entry e{tree.root_ref, -inf, root_box};
    for (;;) {
        if (!ch13::is_leaf(e.ref)) {
            const ch13::wide_node<N>& n = tree.nodes[e.ref];
            stats.node_visit();
            stats.box_test(N);
            simd::vfloat<N> t;
            unsigned bits = frustum_children(p, n, t);
            if (bits != 0) {
                alignas(64) float ts[N];
                t.store(ts);
                if constexpr (Nearest) {
                    // Sorted in place on top of the stack (farthest first), the nearest then taken off again.
                    entry* hits = stack + top;
                    int count = 0;
                    for (; bits != 0; bits &= bits - 1) {
                        const int c = std::countr_zero(bits);
                        const entry h{n.child[c], ts[c], &n.lo[0][c]};
                        int j = count++;
                        for (; j > 0 && hits[j - 1].t <= h.t; --j) hits[j] = hits[j - 1];
                        hits[j] = h;
                    }
                    top += count - 1;
                    e = stack[top];
                } else {
                    // Stored order: the first child next, the others pushed last to first.
                    const int first = std::countr_zero(bits);
                    e = entry{n.child[first], ts[first], &n.lo[0][first]};
                    for (unsigned rest = bits & (bits - 1); rest != 0;) {
                        const int c = 31 - std::countl_zero(rest);
                        stack[top++] = entry{n.child[c], ts[c], &n.lo[0][c]};
                        rest &= ~(1u << c);
                    }
                }
                continue;
            }
        } else {
            const float bmin[3] = {e.box[0], e.box[N], e.box[2 * N]};
            const float bmax[3] = {e.box[3 * N], e.box[4 * N], e.box[5 * N]};
            for (int v = 0; v < V; ++v)
                if (p.active[v] != 0) leaf(load(p, v), p.active[v], [v](int j) { return v * K + j; }, e.ref, bmin, bmax);
            if (p.empty()) return;  // any hit: every ray answered
        }
        for (;;) {
            if (top == 0) return;
            e = stack[--top];
            if (!Nearest || e.t <= p.t1_hi) break;
        }
    }
}

}  // namespace strahl::ch12
