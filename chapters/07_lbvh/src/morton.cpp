// The codes phase: which primitives fit in the tree, the box around their centroids, and one Morton code
// per primitive over that box (Lauterbach et al. 2009, section 4.1).
#include "strahl/ch07/morton.hpp"
#include "strahl/ch04/bvh.hpp"
#include "strahl/parallel.hpp"
#include <stdexcept>

namespace strahl::ch07 {

namespace {

template <bool Wide, bool Pdep>
std::uint64_t code(const quantizer& q, const vec3& c) {
    const std::uint32_t x = q(c.x, 0), y = q(c.y, 1), z = q(c.z, 2);
    if constexpr (Wide && Pdep) return expand_bits21_pdep(x) << 2 | expand_bits21_pdep(y) << 1 | expand_bits21_pdep(z);
    if constexpr (Wide && !Pdep) return morton63(x, y, z);
    if constexpr (!Wide && Pdep) return expand_bits10_pdep(x) << 2 | expand_bits10_pdep(y) << 1 | expand_bits10_pdep(z);
    if constexpr (!Wide && !Pdep) return morton30(x, y, z);
}

template <bool Wide, bool Pdep>
void fill(morton_codes& out, std::span<const vec3> centroids, const quantizer& q) {
    parallel_for_chunks(out.ids.size(), 4096, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) out.keys[k] = code<Wide, Pdep>(q, centroids[out.ids[k]]);
    });
}

}  // namespace

morton_codes compute_morton_codes(std::span<const aabb> boxes, std::span<const vec3> centroids, int bits_per_axis,
                                  bool use_pdep) {
    if (boxes.size() != centroids.size()) throw std::invalid_argument("compute_morton_codes: one centroid per box");
    if (bits_per_axis != 10 && bits_per_axis != 21)
        throw std::invalid_argument("compute_morton_codes: 10 or 21 bits per axis");
    morton_codes out;
    // 1. The primitives a tree can hold (the others are loose, as in chapter 04), and their centroids' box.
    out.ids.reserve(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        if (ch04::fits_in_tree(boxes[i], centroids[i])) {
            out.ids.push_back(std::uint32_t(i));
            out.centroid_box.grow(centroids[i]);
        } else {
            out.loose.push_back(std::uint32_t(i));
        }
    }
    // 2. One code per primitive, in parallel.
    out.keys.resize(out.ids.size());
    const quantizer q(out.centroid_box, bits_per_axis);
    const bool wide = bits_per_axis == 21, pdep = use_pdep && have_pdep;
    if (wide)
        pdep ? fill<true, true>(out, centroids, q) : fill<true, false>(out, centroids, q);
    else
        pdep ? fill<false, true>(out, centroids, q) : fill<false, false>(out, centroids, q);
    return out;
}

}  // namespace strahl::ch07
