// Exercises 13.2 the node test (3 points) and 13.3 the ordered push (5 points). Read: I. Wald, C. Benthin and
// S. Boulos, "Getting rid of packets", IEEE RT 2008, section 4; chapter 05's slab_test.hpp (the fast test
// this one widens to N boxes).
#include "strahl/inlining.hpp"
#include "strahl/ch13/wide_traverse.hpp"

namespace strahl::ch13 {

// 13.2: per axis, the near and the far plane of all N boxes (one row each, s.row(n, s.near_row[a])), their t
// by s.plane_t, and the running maximum of the entries and minimum of the exits, as the scalar test does.
template <int N, bool Fused>
STRAHL_ALWAYS_INLINE inline simd::vfloat<N> node_entry(const wide_node<N>& n, const wide_fast_slab<N, Fused>& s,
                                                float t0, float t1, simd::vmask<N>& hit) {
    using vf = simd::vfloat<N>;
    vf lo(t0), hi(t1);
    for (int a = 0; a < 3; ++a) {
        const vf near = s.plane_t(vf::load(s.row(n, s.near_row[a])), s.inv[a], s.org_near[a]);
        const vf far = s.plane_t(vf::load(s.row(n, s.far_row[a])), s.inv[a], s.org_far[a]);
        lo = simd::max(near, lo);  // near > lo ? near : lo
        hi = simd::min(far, hi);   // far < hi ? far : hi
    }
    hit = lo <= hi;
    return lo;
}

// 13.3: the hit children sorted by entry distance, farthest first (an insertion sort: two to N entries),
// pushed but for the last, the nearest, whose reference is returned.
template <int N>
STRAHL_ALWAYS_INLINE inline std::uint32_t push_ordered(unsigned bits, const float* t, const std::uint32_t* child,
                                                stack_entry* stack, int& top) {
    stack_entry hits[N];
    int count = 0;
    for (; bits != 0; bits &= bits - 1) {
        const int k = std::countr_zero(bits);
        const stack_entry e{child[k], t[k]};
        int j = count++;
        for (; j > 0 && hits[j - 1].t <= e.t; --j) hits[j] = hits[j - 1];  // (<=: a later equal one goes before)
        hits[j] = e;
    }
    for (int j = 0; j + 1 < count; ++j) stack[top++] = hits[j];
    return hits[count - 1].ref;
}

}  // namespace strahl::ch13

// The traversal compiled here, with the two functions above inlined into it.
#include "strahl/ch13/wide_accel_impl.hpp"
