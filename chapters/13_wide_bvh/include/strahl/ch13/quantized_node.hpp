// Quantised wide nodes: a node keeps its children's boxes as bytes on a grid over its own box. Per axis, an
// origin (the node box's minimum corner) and a step that is a power of two; each child's plane is a whole
// number of steps from the origin, 0 to 255, rounded outward so that the decoded box holds the child's box.
// An 8-wide node's 192 bytes of planes become 48, and the node 128 bytes (two cache lines) instead of 256:
// a walk that waits on memory reads half as many lines per node, for a few more instructions to decode them.
//   H. Ylitie, T. Karras and S. Laine, "Efficient incoherent ray traversal on GPUs through compressed wide
//   BVHs", HPG 2017 (8-bit child boxes on a power-of-two grid per node);
//   C. Benthin, I. Wald, S. Woop and A. T. Afra, "Compressed-leaf bounding volume hierarchies", HPG 2018;
//   Embree's quantised BVH8 nodes (kernels/bvh/bvh_node_qaabb.h: an origin and a scale per axis, bytes).
//
// Decoding is exact arithmetic but for one rounding: plane = origin + q * step, where q * step is exact (q has
// 8 bits, step is a power of two no smaller than 2^-100), so a fused multiply-add and a multiply then an add
// give the same float, and the build checks each plane with the walk's own arithmetic. The decoded boxes are
// ordinary float boxes a little larger than the true ones: chapter 05's slab tests hold for them unchanged,
// with the tree's bounds grown to hold every decoded box. Only the hit set changes (more boxes entered);
// the leaves' triangle tests, and so every answer, stay the same.
#pragma once
#include "strahl/inlining.hpp"
#include "strahl/ch13/wide_bvh.hpp"
#include "strahl/simd.hpp"
#include <cstdint>

namespace strahl::ch13 {

// One node of N children. Rows q[a] (a = 0, 1, 2) hold the children's minimum corners on axis a, rows
// q[3 + a] their maximum corners. A slot without a child has its bit clear in used_bits (and bytes 255 / 0:
// an inverted box); the walk masks it out, not the slab test. Sizes: N = 8: 24 + 48 + 32 + 8 + 4 = 116
// bytes, padded to 128 (two lines); N = 16: 204, padded to 256; N = 4: 72, padded to 128 (no gain).
template <int N>
struct alignas(64) qnode {
    float origin[3];
    float step[3];  // powers of two, 2^-100 to 2^127
    std::uint8_t q[6][N];
    std::uint32_t child[N];
    std::uint8_t order[N];  // as wide_node::order
    std::uint32_t used_bits = 0;

    bool used(int k) const { return (used_bits >> k) & 1u; }
    // Plane row r (0-2: minima, 3-5: maxima) of every child, decoded.
    STRAHL_ALWAYS_INLINE simd::vfloat<N> row(int r) const {
        const int a = r % 3;
        return simd::bytes_to_float<N>(q[r]) * simd::vfloat<N>(step[a]) + simd::vfloat<N>(origin[a]);
    }
    // The same for one child, with the same rounding (the product is exact).
    float plane(int r, int k) const { return float(q[r][k]) * step[r % 3] + origin[r % 3]; }
    aabb box(int k) const {
        return {vec3(plane(0, k), plane(1, k), plane(2, k)), vec3(plane(3, k), plane(4, k), plane(5, k))};
    }
    // The planes of all N children into a float node's rows (its children and order are not written).
    STRAHL_ALWAYS_INLINE void decode(wide_node<N>& out) const {
        for (int a = 0; a < 3; ++a) row(a).store(out.lo[a]), row(3 + a).store(out.hi[a]);
    }
};

// The walks read a node's planes as a float node's rows: a float node as it is, a quantised one decoded into
// `scratch` (the slab tests are written once, for float rows).
template <int N>
STRAHL_ALWAYS_INLINE inline const wide_node<N>& planes_of(const wide_node<N>& n, wide_node<N>&) { return n; }
template <int N>
STRAHL_ALWAYS_INLINE inline const wide_node<N>& planes_of(const qnode<N>& n, wide_node<N>& scratch) {
    n.decode(scratch);
    return scratch;
}
// The slots that hold children: all of a float node's (an empty slot's box is empty), a quantised node's bits.
template <int N>
STRAHL_ALWAYS_INLINE inline unsigned used_slots(const wide_node<N>&) { return (1u << N) - 1; }
template <int N>
STRAHL_ALWAYS_INLINE inline unsigned used_slots(const qnode<N>& n) { return n.used_bits; }

// The tree with its nodes quantised: the same references, blocks and loose triangles; bounds grown to hold
// every decoded box (and centre and diagonal from them). Throws std::logic_error if a decoded plane would
// not hold its box (it cannot, for finite boxes: the check guards the arithmetic above).
template <int N, int M>
wide_bvh<N, M, qnode<N>> quantize(const wide_bvh<N, M>& tree);

}  // namespace strahl::ch13
