// The hybrid tracers (chapter 12's packet tracer with the hybrid walk's hooks), made by name, and the
// exercises' out-of-line entries.
//
// Included once, at the end of hybrid.cpp (exercises 14.1 to 14.3), so that the walk is compiled in the same
// translation unit as the student's slab test, threshold and hand-off, and inlines them.
#pragma once
#include "strahl/ch12/packet_accel.hpp"
#include "strahl/ch14/hybrid_walk.hpp"
#include <functional>
#include <stdexcept>

namespace strahl::ch14 {

namespace {

// What chapter 12's packet tracer asks of a policy: the hooks of one packet's walk (its threshold fixed, or
// estimated from the packet), and that per-ray figures say where rays left their packets.
template <bool Octant>
struct hybrid_policy {
    static constexpr bool departures = true;
    int threshold = automatic;
    threshold_rule rule;
    bool strict = false;  // hybrid_config::strict
    ch13::child_order order = ch13::child_order::leaves_then_area;  // hybrid_config::order
    static constexpr bool octant = Octant;  // hybrid_config::octant_order (packet_accel orders the nodes)
    template <bool Any, bool Coherent, int K, int N, int M, class Stats>
    hybrid_hooks<Any, Coherent, K, N, M, Stats, Octant> hooks(const ch13::wide_bvh<N, M>& tree,
                                                              ch12::ray_packet<K, 1>& p, Stats& stats) const {
        const int t = threshold >= 0 ? threshold : packet_threshold(packet_coherence(p), K, rule);
        return {tree, p, stats, t, strict, order != ch13::child_order::collapsed};
    }
};

template <int K, bool Octant = false>
using hybrid_accel = ch12::packet_accel<ch12::walk_kind::wide, K, 1, hybrid_policy<Octant>>;

}  // namespace

std::unique_ptr<ch12::packet_accel_base> make_accel(std::string name, const hybrid_config& c) {
    if (c.threshold < automatic || c.threshold > c.lanes)
        throw std::invalid_argument("hybrid tracer: threshold " + std::to_string(c.threshold) + " is not in 0.." +
                                    std::to_string(c.lanes) + " (or automatic)");
    const ch12::packet_config pc{ch12::walk_kind::wide, c.lanes, c.tile_w, c.tile_h, c.image_width, c.builder};
    const hybrid_policy<false> policy{c.threshold, {}, c.strict, c.order};
    if (c.octant_order && !(c.lanes == 16 && c.tile_w == 4 && c.tile_h == 4))
        throw std::invalid_argument("hybrid tracer: the lone rays' octant order is built for 16 lanes with 4x4 tiles");
    if (c.octant_order)
        return std::make_unique<hybrid_accel<16, true>>(std::move(name), pc, hybrid_policy<true>{c.threshold, {}, c.strict, c.order});
    if (c.lanes == 8 && c.tile_w == 4 && c.tile_h == 2) return std::make_unique<hybrid_accel<8>>(std::move(name), pc, policy);
    if (c.lanes == 16 && c.tile_w == 4 && c.tile_h == 4) return std::make_unique<hybrid_accel<16>>(std::move(name), pc, policy);
    throw std::invalid_argument("hybrid tracer: " + std::to_string(c.lanes) + " lanes with " + std::to_string(c.tile_w) +
                                "x" + std::to_string(c.tile_h) + " tiles are not built (built: 8 lanes 4x2, 16 lanes 4x4)");
}

// Out-of-line entries to the three exercises for the tests, which call them on their own (the exercises
// themselves are forced inline into the walk).
template <int L>
simd::vmask<L> lane_slab_out_of_line(const simd::vfloat<L> (&near)[3], const simd::vfloat<L> (&far)[3],
                                     const simd::vfloat<L> (&inv)[3], const simd::vfloat<L> (&org_near)[3],
                                     const simd::vfloat<L> (&org_far)[3], simd::vfloat<L> t0, simd::vfloat<L> t1,
                                     simd::vfloat<L>& entry) {
    return lane_slab<L>(near, far, inv, org_near, org_far, t0, t1, entry);
}
template <int K>
coherence packet_coherence_out_of_line(const ch12::ray_packet<K, 1>& p) {
    return packet_coherence(p);
}
template <bool Any, int K>
void hand_off_out_of_line(ch12::ray_packet<K, 1>& p, unsigned lanes, const std::function<void(int, lone_ray&)>& alone) {
    hand_off<Any>(p, lanes, alone);
}
template <int L>
using lanes3 = const simd::vfloat<L> (&)[3];
template simd::vmask<4> lane_slab_out_of_line<4>(lanes3<4>, lanes3<4>, lanes3<4>, lanes3<4>, lanes3<4>, simd::vfloat<4>,
                                                 simd::vfloat<4>, simd::vfloat<4>&);
template simd::vmask<8> lane_slab_out_of_line<8>(lanes3<8>, lanes3<8>, lanes3<8>, lanes3<8>, lanes3<8>, simd::vfloat<8>,
                                                 simd::vfloat<8>, simd::vfloat<8>&);
template simd::vmask<16> lane_slab_out_of_line<16>(lanes3<16>, lanes3<16>, lanes3<16>, lanes3<16>, lanes3<16>,
                                                   simd::vfloat<16>, simd::vfloat<16>, simd::vfloat<16>&);
template coherence packet_coherence_out_of_line<8>(const ch12::ray_packet<8, 1>&);
template coherence packet_coherence_out_of_line<16>(const ch12::ray_packet<16, 1>&);
template void hand_off_out_of_line<false, 16>(ch12::ray_packet<16, 1>&, unsigned, const std::function<void(int, lone_ray&)>&);
template void hand_off_out_of_line<true, 16>(ch12::ray_packet<16, 1>&, unsigned, const std::function<void(int, lone_ray&)>&);

}  // namespace strahl::ch14
