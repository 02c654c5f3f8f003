// Exercise 05.3 prefix and suffix sweeps over bins. I. Wald, "On fast construction of SAH-based bounding
// volume hierarchies", IEEE Symposium on Interactive Ray Tracing 2007, section 3; the same two sweeps
// serve the full sweep over sorted primitives (one per "bin").
#include "strahl/ch05/sah.hpp"

namespace strahl::ch05 {

bin_split best_boundary(std::span<const bin> bins, std::span<float> right_area, const sah_costs& c,
                        float area_parent) {
    const std::size_t k = bins.size();
    bin_split best;
    if (k < 2) return best;
    // The suffix sweep, right to left: right_area[b] = A(bins b .. k-1).
    aabb right;
    for (std::size_t b = k - 1; b > 0; --b) {
        right.grow(bins[b].box);
        right_area[b] = right.surface_area();
    }
    std::uint64_t n_right = 0;
    for (const bin& b : bins) n_right += b.count;
    // The prefix sweep, left to right: bins 0 .. b-1 on the left; each boundary evaluated once.
    aabb left;
    std::uint64_t n_left = 0;
    for (std::size_t b = 1; b < k; ++b) {
        left.grow(bins[b - 1].box);
        n_left += bins[b - 1].count;
        n_right -= bins[b - 1].count;
        if (n_left == 0 || n_right == 0) continue;
        const float cost = c.traversal + c.intersection * (left.surface_area() * float(n_left) +
                                                           right_area[b] * float(n_right)) / area_parent;
        if (cost < best.cost) best = {int(b), cost};
    }
    return best;
}

}  // namespace strahl::ch05
