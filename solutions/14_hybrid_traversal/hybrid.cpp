// Exercises 14.1 one slab test for both kinds of lanes (3 points), 14.2 the switch's threshold from the
// packet's coherence (3 points) and 14.3 the hand-off (4 points). Read: C. Benthin, I. Wald, S. Woop,
// M. Ernst and W. R. Mark, "Combining single and packet-ray tracing for arbitrary ray distributions on the
// Intel MIC architecture", IEEE TVCG 18(9), 2012, sections 4 and 5; chapter 05's slab_test.hpp.
#include "strahl/inlining.hpp"
#include "strahl/ch14/hybrid_walk.hpp"

namespace strahl::ch14 {

// 14.1: chapter 05's fast test on L lanes, whatever the lanes hold.
template <int L>
STRAHL_ALWAYS_INLINE inline simd::vmask<L> lane_slab(const simd::vfloat<L> (&near)[3], const simd::vfloat<L> (&far)[3],
                                                     const simd::vfloat<L> (&inv)[3],
                                                       const simd::vfloat<L> (&org_near)[3],
                                                       const simd::vfloat<L> (&org_far)[3], simd::vfloat<L> t0,
                                                       simd::vfloat<L> t1, simd::vfloat<L>& entry) {
    using vf = simd::vfloat<L>;
    vf lo = t0, hi = t1;
    for (int a = 0; a < 3; ++a) {
        vf n, f;
        if constexpr (ch05::fused_plane_default)
            n = simd::fmsub(near[a], inv[a], org_near[a]), f = simd::fmsub(far[a], inv[a], org_far[a]);
        else
            n = near[a] * inv[a] - org_near[a], f = far[a] * inv[a] - org_far[a];
        lo = simd::max(n, lo);  // n > lo ? n : lo
        hi = simd::min(f, hi);  // f < hi ? f : hi
    }
    entry = lo;
    return lo <= hi;
}

// 14.2: the octant of every active lane, and per axis the range of the unit directions' components, K lanes
// at a time (a few SIMD steps per packet: the estimate must cost far less than the nodes it saves).
template <int K>
coherence packet_coherence(const ch12::ray_packet<K, 1>& p) {
    using vf = simd::vfloat<K>;
    coherence c;
    const unsigned active = p.active[0];
    if (active == 0) return c;
    alignas(64) float on[K];
    for (int k = 0; k < K; ++k) on[k] = (active >> k) & 1u ? 1.0f : 0.0f;
    const simd::vmask<K> live = vf(0.0f) < vf::load(on);
    const vf x = vf::load(p.dir[0]), y = vf::load(p.dir[1]), z = vf::load(p.dir[2]);
    const vf scale = vf(1.0f) / simd::sqrt(x * x + y * y + z * z);  // one divide, not three
    const vf unit[3] = {x * scale, y * scale, z * scale};
    for (int a = 0; a < 3; ++a) {
        const unsigned down = simd::movemask(simd::as_int(unit[a]) < simd::vint<K>(0)) & active;
        c.one_octant = c.one_octant && (down == 0 || down == active);
        const float lo = simd::reduce_min(simd::select(live, unit[a], vf(inf)));
        const float hi = simd::reduce_max(simd::select(live, unit[a], vf(-inf)));
        c.spread = std::max(c.spread, hi - lo);
    }
    return c;
}

int packet_threshold(const coherence& c, int lanes, const threshold_rule& rule) {
    return c.one_octant && c.spread < rule.tight ? lanes / 4 : lanes / 2;
}

// 14.3: out of the packet, traced alone, the answer back into the lane.
template <bool Any, int K, class Alone>
STRAHL_ALWAYS_INLINE inline void hand_off(ch12::ray_packet<K, 1>& p, unsigned lanes, Alone&& alone) {
    for (; lanes != 0; lanes &= lanes - 1) {
        const int k = std::countr_zero(lanes);
        lone_ray l;
        l.r = ray{{p.org[0][k], p.org[1][k], p.org[2][k]}, {p.dir[0][k], p.dir[1][k], p.dir[2][k]}, p.tmin[k], p.tmax[k]};
        l.slack = p.slack[k];
        l.best = p.best(k);
        alone(k, l);
        if constexpr (Any) {
            if (l.blocked) p.set_best(k, l.best), p.active[0] &= ~(1u << k);
        } else {
            p.set_best(k, l.best), p.tmax[k] = l.r.tmax, p.t1[k] = l.r.tmax + p.slack[k];
        }
    }
}

}  // namespace strahl::ch14

// The hybrid tracers compiled here, with the functions above inlined into them.
#include "strahl/ch14/hybrid_accel_impl.hpp"
