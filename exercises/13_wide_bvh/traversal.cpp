// Exercises 13.2 the node test (3 points) and 13.3 the ordered push (5 points). Read: I. Wald, C. Benthin and
// S. Boulos, "Getting rid of packets", IEEE RT 2008, section 4; chapter 05's slab_test.hpp (the fast test
// this one widens to N boxes).
#include "strahl/ch13/wide_traverse.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch13 {

// 13.2: the entry distances of node n's N child boxes for t in [t0, t1], and in `hit` the boxes the ray
// enters; lane k must equal ch05::fast_slab::entry on child k's box, bit for bit.
// Hint: s.row(n, s.near_row[a]) is the row of N near planes on axis a; s.plane_t turns a row into t values;
// simd::max and simd::min are the scalar test's "near > t0 ? near : t0" and "far < t1 ? far : t1".
// Why does an unused child slot (box from +inf to -inf) never count as hit?
template <int N, bool Fused>
simd::vfloat<N> node_entry(const wide_node<N>& n, const wide_fast_slab<N, Fused>& s,
                                                  float t0, float t1, simd::vmask<N>& hit) {
    STRAHL_TODO("13.2 the node test");
}

// 13.3: the children whose bits are set (two or more), entry distances t[k], references child[k]: push all
// but the nearest onto stack[top++], farthest first; return the nearest one's reference. Equal distances:
// the lower index counts as nearer.
// Hint: collect the hits, sort them (at most N: an insertion sort will do), then push.
// Why push the farthest first?
template <int N>
std::uint32_t push_ordered(unsigned bits, const float* t, const std::uint32_t* child,
                                                  stack_entry* stack, int& top) {
    STRAHL_TODO("13.3 the ordered push");
}

}  // namespace strahl::ch13

// The traversal compiled here, with the two functions above inlined into it. (Leave this line.)
#include "strahl/ch13/wide_accel_impl.hpp"
