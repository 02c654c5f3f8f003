// Exercises 12.1 the packet's box test (3 points), 12.2 the frustum test (4 points) and 12.3 the active-ray
// partition (4 points). Read: I. Wald, S. Boulos and P. Shirley, "Ray tracing deformable scenes using
// dynamic bounding volume hierarchies", ACM TOG 26(1), 2007, section 4 (the interval-arithmetic frustum);
// R. Overbeck, R. Ramamoorthi and W. R. Mark, "Large ray packets for real-time Whitted ray tracing", IEEE RT
// 2008, section 3 (the partition); chapter 05's slab_test.hpp (fast_slab, the test 12.1 puts on lanes).
#include "strahl/inlining.hpp"
#include "strahl/ch05/slab_test.hpp"
#include "strahl/ch12/packet.hpp"
#include "strahl/ch12/partition_walk.hpp"

namespace strahl::ch12 {

// 12.1: per axis the near and the far plane, broadcast (chosen once for a coherent packet, per lane by the
// sign bits otherwise), their t as ch05::plane_t computes it, the running maximum of the entries and minimum
// of the exits, as fast_slab::entry does.
template <bool Coherent, int K>
STRAHL_ALWAYS_INLINE inline simd::vmask<K> packet_box(const lane_rays<K>& r, const float* bmin, const float* bmax,
                                                      int octant, simd::vfloat<K>& entry) {
    using vf = simd::vfloat<K>;
    vf lo = r.t0, hi = r.t1;
    for (int a = 0; a < 3; ++a) {
        vf near_plane, far_plane;
        if constexpr (Coherent) {
            const bool down = (octant >> a) & 1;
            near_plane = vf(down ? bmax[a] : bmin[a]), far_plane = vf(down ? bmin[a] : bmax[a]);
        } else {
            near_plane = simd::select(r.negative[a], vf(bmax[a]), vf(bmin[a]));
            far_plane = simd::select(r.negative[a], vf(bmin[a]), vf(bmax[a]));
        }
        vf near, far;
        if constexpr (ch05::fused_plane_default)
            near = simd::fmsub(near_plane, r.inv[a], r.org_near[a]), far = simd::fmsub(far_plane, r.inv[a], r.org_far[a]);
        else
            near = near_plane * r.inv[a] - r.org_near[a], far = far_plane * r.inv[a] - r.org_far[a];
        lo = simd::max(near, lo);  // near > lo ? near : lo
        hi = simd::min(far, hi);   // far < hi ? far : hi
    }
    entry = lo;
    return lo <= hi;
}

// 12.2: per axis, the four products of the plane less either end of the origins' range with either end of
// the range of 1 / d (one sign: a coherent packet), their smallest less the margin bounding every lane's
// entry from below, their largest plus the margin every exit from above. The packet misses if the largest
// lower bound of the entries exceeds the smallest upper bound of the exits.
template <int K, int V>
bool frustum_misses(const ray_packet<K, V>& p, const float* bmin, const float* bmax) {
    float lo = p.t0_lo, hi = p.t1_hi;
    for (int a = 0; a < 3; ++a) {
        const bool down = (p.octant >> a) & 1;
        const float near = down ? bmax[a] : bmin[a], far = down ? bmin[a] : bmax[a];
        const float n1 = near - p.org_hi[a], n2 = near - p.org_lo[a], f1 = far - p.org_hi[a], f2 = far - p.org_lo[a];
        const float near_t = std::min(std::min(n1 * p.inv_lo[a], n1 * p.inv_hi[a]), std::min(n2 * p.inv_lo[a], n2 * p.inv_hi[a]));
        const float far_t = std::max(std::max(f1 * p.inv_lo[a], f1 * p.inv_hi[a]), std::max(f2 * p.inv_lo[a], f2 * p.inv_hi[a]));
        lo = std::max(lo, near_t - p.margin[a]);
        hi = std::min(hi, far_t + p.margin[a]);
    }
    return lo > hi;
}

// 12.3: K rays a call (enters(at): bits for ids[at .. at + K - 1]); each ray that enters is swapped to the
// next place of the front part. A swap only touches places already tested: the next call's rays are intact.
template <int K, class Enters>
STRAHL_ALWAYS_INLINE inline int partition_active(std::uint16_t* ids, int count, Enters&& enters) {
    int front = 0;
    for (int at = 0; at < count; at += K) {
        unsigned bits = enters(at);
        if (count - at < K) bits &= (1u << (count - at)) - 1;
        for (; bits != 0; bits &= bits - 1) std::swap(ids[front++], ids[at + std::countr_zero(bits)]);
    }
    return front;
}

}  // namespace strahl::ch12

// The packet tracers compiled here, with the three functions above inlined into them.
#include "strahl/ch12/packet_accel_impl.hpp"
