// Morton codes: a point's position along the Z-order curve, its three quantised coordinates' bits
// interleaved (x2 y2 z2 x1 y1 z1 x0 y0 z0). Sorting primitives by the Morton code of their centroids lays
// them out along the curve, so that primitives near in the sorted order are near in space.
//   G. M. Morton, "A computer oriented geodetic data base and a new technique in file sequencing", IBM 1966;
//   C. Lauterbach, M. Garland, S. Sengupta, D. Luebke and D. Manocha, "Fast BVH construction on GPUs",
//   Eurographics 2009 (the linear BVH: codes over the centroid box, sorted, split at their bits).
#pragma once
#include "strahl/aabb.hpp"
#include <cstdint>
#include <span>
#include <vector>
#ifdef __BMI2__
#include <immintrin.h>
#endif

namespace strahl::ch07 {

// Exercise 07.1 "bit expansion": the low 10 bits of v spread out to every third bit: bit k of v goes to
// bit 3k of the result (bits 0, 3, ..., 27); every other bit of the result is 0. Higher bits of v are
// ignored. Shifts and masks, four steps (16, 8, 4, 2): no loop over the bits.
std::uint32_t expand_bits10(std::uint32_t v);

// The same for the low 21 bits into a 64-bit word (bits 0, 3, ..., 60): five steps (32, 16, 8, 4, 2).
inline std::uint64_t expand_bits21(std::uint64_t v) {
    v &= 0x1fffffu;
    v = (v | v << 32) & 0x001f00000000ffffull;
    v = (v | v << 16) & 0x001f0000ff0000ffull;
    v = (v | v << 8) & 0x100f00f00f00f00full;
    v = (v | v << 4) & 0x10c30c30c30c30c3ull;
    v = (v | v << 2) & 0x1249249249249249ull;
    return v;
}

// The same two expansions by BMI2's parallel bit deposit, one instruction each (where the compiler targets
// BMI2; the shift versions elsewhere). pdep writes the low bits of v into the mask's set bits, in order.
// (On AMD before Zen 3, pdep is microcoded and slower than the shifts.)
inline constexpr bool have_pdep =
#ifdef __BMI2__
    true;
#else
    false;
#endif
inline std::uint32_t expand_bits10_pdep(std::uint32_t v) {
#ifdef __BMI2__
    return _pdep_u32(v, 0x09249249u);
#else
    return expand_bits10(v);
#endif
}
inline std::uint64_t expand_bits21_pdep(std::uint64_t v) {
#ifdef __BMI2__
    return _pdep_u64(v, 0x1249249249249249ull);
#else
    return expand_bits21(v);
#endif
}

// A code from quantised coordinates (each below 2^10 or 2^21): x's bits highest, then y's, then z's.
inline std::uint32_t morton30(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    return expand_bits10(x) << 2 | expand_bits10(y) << 1 | expand_bits10(z);
}
inline std::uint64_t morton63(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    return expand_bits21(x) << 2 | expand_bits21(y) << 1 | expand_bits21(z);
}

// The axis a code's bit belongs to: bit 3k + 2 is x's, 3k + 1 y's, 3k z's.
inline int axis_of_bit(int bit) { return 2 - bit % 3; }

// Quantisation of centroids into the grid of 2^bits_per_axis cells per axis over the centroid box:
//   q = floor((c - lo) * 2^k / extent), clamped to [0, 2^k - 1]
// (c == hi lands in cell 2^k, one past the last: the clamp keeps it in the last cell). An axis of extent 0
// (all centroids in one plane) quantises to 0. Computed in double: a float product could overflow to inf
// for a box of extent near float's maximum, and double keeps (c - lo) exact for float inputs. A NaN
// quantises to 0 (the builders never pass one: a non-finite centroid is loose, ch04::fits_in_tree).
struct quantizer {
    double lo[3] = {0, 0, 0}, scale[3] = {0, 0, 0}, top = 0;

    quantizer(const aabb& centroid_box, int bits_per_axis) {
        top = double((1u << bits_per_axis) - 1);
        for (int a = 0; a < 3; ++a) {
            lo[a] = centroid_box.min[a];
            const double extent = double(centroid_box.max[a]) - double(centroid_box.min[a]);
            scale[a] = extent > 0.0 ? double(1u << bits_per_axis) / extent : 0.0;
        }
    }
    std::uint32_t operator()(float c, int axis) const {
        const double q = (double(c) - lo[axis]) * scale[axis];
        return std::uint32_t(q > 0.0 ? (q < top ? q : top) : 0.0);  // NaN: 0
    }
};

// The codes phase of the builders: for the primitives that fit in a tree (ch04::fits_in_tree), in id order,
// their ids and the Morton codes of their centroids over the box around those centroids, with
// bits_per_axis 10 (30-bit codes) or 21 (63-bit codes); the others' ids in loose. In parallel (TBB).
// use_pdep: the BMI2 expansions (where have_pdep), else the shift versions.
struct morton_codes {
    std::vector<std::uint64_t> keys;
    std::vector<std::uint32_t> ids;
    std::vector<std::uint32_t> loose;
    aabb centroid_box;
};
morton_codes compute_morton_codes(std::span<const aabb> boxes, std::span<const vec3> centroids, int bits_per_axis,
                                  bool use_pdep = false);

}  // namespace strahl::ch07
