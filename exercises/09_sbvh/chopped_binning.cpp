// Exercise 09.2 chopped binning (6 points). Read: chopped_bins.hpp; M. Stich, H. Friedrich and A. Dietrich,
// "Spatial splits in bounding volume hierarchies", HPG 2009, section 4.3.
#include "strahl/ch09/chopped_bins.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch09 {

// Goal: clear the m.k bins, then for each reference r: its first bin e (of r.box.min[axis]) and last bin x
// (of r.box.max[axis]) by ch05::bin_index; one more entry in bin e and one more exit in bin x; and the box
// of every bin j in e..x grown by r's part inside it: r.box itself when e == x, else clip(r, lo, hi) with
// lo = bin_plane(m, j) (or -inf for j == e) and hi = bin_plane(m, j + 1) (or +inf for j == x). An empty
// part grows nothing.
// Hint: aabb::grow with an empty box changes nothing, but test is_empty() anyway: it says what you mean.
// Why: why entries and exits, not one count per bin: at a boundary, which references belong to the left
// child, which to the right, and which to both?
// Step by step: HINTS.md, 09.2.
void chopped_binning(std::span<const reference> refs, int axis, const ch05::bin_mapping& m,
                     std::span<chopped_bin> bins, slab_clipper clip) {
    STRAHL_TODO("09.2 chopped binning");
}

}  // namespace strahl::ch09
