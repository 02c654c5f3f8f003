// Exercises 12.1 the packet's box test (3 points), 12.2 the frustum test (4 points) and 12.3 the active-ray
// partition (4 points). Read: I. Wald, S. Boulos and P. Shirley, "Ray tracing deformable scenes using
// dynamic bounding volume hierarchies", ACM TOG 26(1), 2007, section 4 (the interval-arithmetic frustum);
// R. Overbeck, R. Ramamoorthi and W. R. Mark, "Large ray packets for real-time Whitted ray tracing", IEEE RT
// 2008, section 3 (the partition); chapter 05's slab_test.hpp (fast_slab, the test 12.1 puts on lanes).
#include "strahl/inlining.hpp"
#include "strahl/ch05/slab_test.hpp"
#include "strahl/ch12/packet.hpp"
#include "strahl/ch12/partition_walk.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch12 {

// 12.1: one box against K rays. Lane j must compute what ch05::fast_slab::entry computes for ray j, bit for
// bit: the lanes entering the box within [r.t0, r.t1] (returned) and their entry distances (in entry).
// Goal: K rays answered by one pass of twelve SIMD operations instead of K scalar tests.
// Hint: a coherent packet's near plane on axis a is bmax[a] where bit a of octant is set, else bmin[a];
// otherwise choose per lane with simd::select(r.negative[a], ...). A plane's t is plane * r.inv[a] - the
// origin term (r.org_near or r.org_far), fused (simd::fmsub) exactly where ch05::fused_plane_default is true.
// Why: why may a lane whose ray misses the box still be computed, and what keeps its answer from counting?
template <bool Coherent, int K>
STRAHL_ALWAYS_INLINE inline simd::vmask<K> packet_box(const lane_rays<K>& r, const float* bmin, const float* bmax,
                                                      int octant, simd::vfloat<K>& entry) {
    STRAHL_TODO("12.1 the packet's box test");
}

// 12.2: true only where no active lane of the coherent packet p can enter the box [bmin, bmax].
// Goal: one scalar test that culls a node for every ray of a large packet at once.
// Hint: per axis, a lane's entry is (near plane - o) * (1 / d) with o in [p.org_lo[a], p.org_hi[a]] and 1 / d
// in [p.inv_lo[a], p.inv_hi[a]]: bound it from below by the smallest of the four products of the ends, less
// p.margin[a]; the exit from above by the largest (far plane), plus the margin; start from p.t0_lo, p.t1_hi.
// Why: what would go wrong without the margin, given how packet_box computes a lane's entry?
template <int K, int V>
bool frustum_misses(const ray_packet<K, V>& p, const float* bmin, const float* bmax) {
    STRAHL_TODO("12.2 the frustum test");
}

// 12.3: ids[0 .. count-1] lists rays; enters(at) gives, as lane bits, which of ids[at .. at+K-1] enter the
// node (call it once for at = 0, K, 2K, ...; bits past count mean nothing). Move the rays that enter to the
// front, keep every id within [0, count), return how many enter.
// Goal: the node's subtree then sees only its own rays, however scattered they are in the packet.
// Hint: one pass, a swap per entering ray into the next place of the front part.
// Why: why must the rays that miss stay in the list rather than be dropped?
template <int K, class Enters>
STRAHL_ALWAYS_INLINE inline int partition_active(std::uint16_t* ids, int count, Enters&& enters) {
    STRAHL_TODO("12.3 the active-ray partition");
}

}  // namespace strahl::ch12

// The packet tracers compiled here, with the three functions above inlined into them. (Leave this line.)
#include "strahl/ch12/packet_accel_impl.hpp"
