// The codes phase: which primitives fit in the tree, the box around their centroids, and one Morton code
// per primitive over that box (Lauterbach et al. 2009, section 4.1).
#include "strahl/ch07/morton.hpp"
#include "strahl/ch04/bvh.hpp"
#include "strahl/parallel.hpp"
#include <algorithm>
#include <stdexcept>
#include <vector>

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
    // 1. The primitives a tree can hold (the others are loose, as in chapter 04), and their centroids' box:
    //    per fixed chunk in parallel (how many fit, their box), then each chunk's ids written from the
    //    prefix sum of those counts, so ids and loose keep input order on any number of threads.
    const std::size_t n = boxes.size(), chunk = 16384, chunks = (n + chunk - 1) / chunk;
    std::vector<std::size_t> fits(chunks + 1, 0);
    std::vector<aabb> chunk_box(chunks);
    parallel_for_chunks(chunks, 1, [&](std::size_t c0, std::size_t c1) {
        for (std::size_t c = c0; c < c1; ++c) {
            std::size_t count = 0;  // in registers, stored once (neighbouring chunks share cache lines)
            aabb box;
            for (std::size_t i = c * chunk; i < std::min(n, (c + 1) * chunk); ++i)
                if (ch04::fits_in_tree(boxes[i], centroids[i])) ++count, box.grow(centroids[i]);
            fits[c + 1] = count, chunk_box[c] = box;
        }
    });
    for (std::size_t c = 0; c < chunks; ++c) fits[c + 1] += fits[c], out.centroid_box.grow(chunk_box[c]);
    out.ids.resize(fits[chunks]);
    out.loose.resize(n - fits[chunks]);
    parallel_for_chunks(chunks, 1, [&](std::size_t c0, std::size_t c1) {
        for (std::size_t c = c0; c < c1; ++c) {
            if (fits[chunks] == n) {  // all fit (the usual case): ids are 0..n-1
                for (std::size_t i = c * chunk; i < std::min(n, (c + 1) * chunk); ++i) out.ids[i] = std::uint32_t(i);
                continue;
            }
            std::size_t in = fits[c], loose = c * chunk - fits[c];
            for (std::size_t i = c * chunk; i < std::min(n, (c + 1) * chunk); ++i)
                (ch04::fits_in_tree(boxes[i], centroids[i]) ? out.ids[in++] : out.loose[loose++]) = std::uint32_t(i);
        }
    });
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
