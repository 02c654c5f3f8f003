// Exercise 09.2 chopped binning (6 points). Read: chopped_bins.hpp; M. Stich, H. Friedrich and A. Dietrich,
// "Spatial splits in bounding volume hierarchies", HPG 2009, section 4.3.
#include "strahl/ch09/chopped_bins.hpp"
#include <cmath>

namespace strahl::ch09 {

// 09.2: entry and exit counts, and each spanned bin grown by the reference's part inside it.
void chopped_binning(std::span<const reference> refs, int axis, const ch05::bin_mapping& m,
                     std::span<chopped_bin> bins, slab_clipper clip) {
    for (chopped_bin& b : bins) b = chopped_bin{};
    for (const reference& r : refs) {
        // STEP 1, span: the first and the last bin.
        const int e = ch05::bin_index(m, r.box.min[axis]), x = ch05::bin_index(m, r.box.max[axis]);
        ++bins[std::size_t(e)].entry, ++bins[std::size_t(x)].exit;
        // STEP 2, chop: within one bin the whole box; else each bin's part, open-ended at both ends.
        if (e == x) {
            bins[std::size_t(e)].box.grow(r.box);
            continue;
        }
        for (int j = e; j <= x; ++j) {
            const float lo = j == e ? -INFINITY : bin_plane(m, j), hi = j == x ? INFINITY : bin_plane(m, j + 1);
            const aabb part = clip(r, lo, hi);
            if (!part.is_empty()) bins[std::size_t(j)].box.grow(part);
        }
    }
}

}  // namespace strahl::ch09
