// Exercises 14.1 one slab test for both kinds of lanes (3 points), 14.2 the switch's threshold from the
// packet's coherence (3 points) and 14.3 the hand-off (4 points). Read: C. Benthin, I. Wald, S. Woop,
// M. Ernst and W. R. Mark, "Combining single and packet-ray tracing for arbitrary ray distributions on the
// Intel MIC architecture", IEEE TVCG 18(9), 2012, sections 4 and 5; chapter 05's slab_test.hpp.
#include "strahl/inlining.hpp"
#include "strahl/ch14/hybrid_walk.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch14 {

// 14.1: the entry into a box on L lanes, whether the lanes hold L rays (one box broadcast) or L boxes (one
// ray broadcast): lane_slab.hpp states the contract.
// Hint: chapter 05's fast_slab::entry, with every float an L-lane vector (simd::fmsub, simd::max, simd::min);
// keep its operand order, or a NaN plane decides differently from the scalar test.
// Why can one function serve chapter 12 and chapter 13? Write down what lane k holds in each.
template <int L>
STRAHL_ALWAYS_INLINE inline simd::vmask<L> lane_slab(const simd::vfloat<L> (&near)[3], const simd::vfloat<L> (&far)[3],
                                                     const simd::vfloat<L> (&inv)[3],
                                                       const simd::vfloat<L> (&org_near)[3],
                                                       const simd::vfloat<L> (&org_far)[3], simd::vfloat<L> t0,
                                                       simd::vfloat<L> t1, simd::vfloat<L>& entry) {
    STRAHL_TODO("14.1 one slab test for both kinds of lanes");
}

// 14.2 (first half): whether the active lanes (p.active[0]) point into one octant, and the spread of their
// directions (hybrid_walk.hpp, accel.hpp's coherence).
// Hint: a shadow ray's direction is as long as the way to the light: compare directions of unit length.
// Why the active lanes only? Think of a packet at the image's edge.
template <int K>
coherence packet_coherence(const ch12::ray_packet<K, 1>& p) {
    STRAHL_TODO("14.2 the packet's coherence");
}

// 14.2 (second half): the threshold for a packet of this coherence (hybrid_walk.hpp states the rule).
// Why not let an incoherent packet's rays go alone at once, at the root? (Try: race ch14-hybrid16-16.)
int packet_threshold(const coherence& c, int lanes, const threshold_rule& rule) {
    STRAHL_TODO("14.2 the threshold");
}

// 14.3: each ray of `lanes` out of the packet, traced by alone(k, lone), its answer back into its lane
// (hybrid_walk.hpp states what goes out and what comes back).
// Hint: the packet goes on after the hand-off, testing boxes against [t0, t1]: what must t1 become?
// Why does a closest-hit ray stay active in the packet after it went alone, and an any-hit ray not always?
template <bool Any, int K, class Alone>
STRAHL_ALWAYS_INLINE inline void hand_off(ch12::ray_packet<K, 1>& p, unsigned lanes, Alone&& alone) {
    STRAHL_TODO("14.3 the hand-off");
}

}  // namespace strahl::ch14

// The hybrid tracers compiled here, with the functions above inlined into them.
#include "strahl/ch14/hybrid_accel_impl.hpp"
