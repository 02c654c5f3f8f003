// One slab test for both SIMD strategies. Chapter 13 put N boxes in the lanes and broadcast one ray;
// chapter 12 put K rays in the lanes and broadcast one box. The arithmetic per lane is the same: chapter
// 05's fast test, t = plane * (1 / d) - org * (1 / d) for the near and the far plane of each axis, the
// largest entry against the smallest exit. Only where the lanes' values come from differs, so the test is
// written once, on L lanes of anything (exercise 14.1), and two adapters fill its inputs.
//   A. Williams et al., "An efficient and robust ray-box intersection algorithm", JGT 2005;
//   I. Wald, C. Benthin and S. Boulos, "Getting rid of packets", IEEE RT 2008 (lanes are boxes);
//   I. Wald, P. Slusallek, C. Benthin and M. Wagner, "Interactive rendering with coherent ray tracing",
//   Eurographics 2001 (lanes are rays).
#pragma once
#include "strahl/inlining.hpp"
#include "strahl/ch05/slab_test.hpp"
#include "strahl/ch12/packet.hpp"
#include "strahl/ch13/wide_traverse.hpp"
#include "strahl/simd.hpp"

namespace strahl::ch14 {

// Exercise 14.1 (hybrid.cpp): per lane, the entry distance into a box for t in [t0, t1], as
// ch05::fast_slab::entry computes it, bit for bit: per axis the near plane's t = near * inv - org_near and
// the far plane's t = far * inv - org_far (in one fused multiply-subtract where ch05::fused_plane_default
// says so, else a multiply and a subtract), then the running maximum of the entries and minimum of the
// exits, in the scalar test's order. Returns the lanes that enter the box; `entry` receives where.
template <int L>
simd::vmask<L> lane_slab(const simd::vfloat<L> (&near)[3], const simd::vfloat<L> (&far)[3],
                         const simd::vfloat<L> (&inv)[3], const simd::vfloat<L> (&org_near)[3],
                         const simd::vfloat<L> (&org_far)[3], simd::vfloat<L> t0, simd::vfloat<L> t1,
                         simd::vfloat<L>& entry);

// Lanes are rays: K rays of a packet against one box (chapter 12's exercise 12.1 through lane_slab). A
// coherent packet (every lane in the octant `octant`) chooses each axis's near and far plane once; the others
// per lane, by the lanes' sign bits.
template <bool Coherent, int K>
STRAHL_ALWAYS_INLINE inline simd::vmask<K> rays_box(const ch12::lane_rays<K>& r, const float* bmin,
                                                    const float* bmax, int octant, simd::vfloat<K>& entry) {
    using vf = simd::vfloat<K>;
    vf near[3], far[3];
    for (int a = 0; a < 3; ++a) {
        if constexpr (Coherent) {
            const bool down = (octant >> a) & 1;
            near[a] = vf(down ? bmax[a] : bmin[a]), far[a] = vf(down ? bmin[a] : bmax[a]);
        } else {
            near[a] = simd::select(r.negative[a], vf(bmax[a]), vf(bmin[a]));
            far[a] = simd::select(r.negative[a], vf(bmin[a]), vf(bmax[a]));
        }
    }
    return lane_slab<K>(near, far, r.inv, r.org_near, r.org_far, r.t0, r.t1, entry);
}

// Lanes are boxes: one ray's terms (a packet lane's, broadcast) against the N children of a wide node
// (chapter 13's exercise 13.2 through lane_slab). A Slab for chapter 13's wide_walk.
template <int N>
struct ray_node_slab : ch13::plane_rows<N> {
    using vf = simd::vfloat<N>;
    vf inv[3], org_near[3], org_far[3];
    // Lane k of packet p, whose direction is `dir`.
    template <int K, int V>
    ray_node_slab(const ch12::ray_packet<K, V>& p, int k, const vec3& dir) : ch13::plane_rows<N>(dir) {
        for (int a = 0; a < 3; ++a)
            inv[a] = vf(p.inv[a][k]), org_near[a] = vf(p.org_near[a][k]), org_far[a] = vf(p.org_far[a][k]);
    }
    STRAHL_ALWAYS_INLINE vf entry(const ch13::wide_node<N>& n, float t0, float t1, simd::vmask<N>& hit) const {
        vf near[3], far[3];
        for (int a = 0; a < 3; ++a)
            near[a] = vf::load(this->row(n, this->near_row[a])), far[a] = vf::load(this->row(n, this->far_row[a]));
        vf t;
        hit = lane_slab<N>(near, far, inv, org_near, org_far, vf(t0), vf(t1), t);
        return t;
    }
};

// Exercise 14.1 called on its own, out of line (for the tests; L = 4, 8, 16).
template <int L>
simd::vmask<L> lane_slab_out_of_line(const simd::vfloat<L> (&near)[3], const simd::vfloat<L> (&far)[3],
                                     const simd::vfloat<L> (&inv)[3], const simd::vfloat<L> (&org_near)[3],
                                     const simd::vfloat<L> (&org_far)[3], simd::vfloat<L> t0, simd::vfloat<L> t1,
                                     simd::vfloat<L>& entry);

}  // namespace strahl::ch14
