// Chopped binning: the bins of a spatial split. A spatial split cuts the node's box, not its primitives'
// list: a reference that crosses the plane goes to both children, each with the box of its own part. To
// price every candidate plane at once, bin the references over the node's box (not over the centroids)
// and "chop" each one at the bin boundaries it crosses: every bin it spans receives the box of the
// triangle's part inside that bin; the bin it starts in counts an entry, the bin it ends in an exit. A
// sweep over the bins then knows, at each boundary, the left child's box and count (bins and entries to
// its left) and the right child's (bins and exits to its right): the references that straddle the
// boundary are counted on both sides.
//   M. Stich, H. Friedrich and A. Dietrich, "Spatial splits in bounding volume hierarchies", HPG 2009,
//   section 4.3 (chopped binning: entry and exit counters, the clipped boxes per bin).
#pragma once
#include "strahl/ch05/sah.hpp"
#include "strahl/function_ref.hpp"
#include <cstdint>
#include <span>

namespace strahl::ch09 {

// A reference: a triangle, or a part of one after spatial splits (box: the part's box), in a leaf by id.
struct reference {
    aabb box;
    std::uint32_t tri = 0;
};

// One bin of a spatial split: the box around the parts of references inside the bin, the number of
// references whose part starts in it (entry) and ends in it (exit).
struct chopped_bin {
    aabb box;
    std::uint32_t entry = 0, exit = 0;
};

// The boundary between bins j - 1 and j on a bin mapping (chapter 05's: bin j covers
// [lo + j / scale, lo + (j + 1) / scale)), the plane a spatial split at boundary j cuts at.
inline float bin_plane(const ch05::bin_mapping& m, int j) { return m.lo + float(j) / m.scale; }

// The box of reference r's part within [lo, hi] on the binning's axis (the builder passes clip_to_slab on
// r's triangle; tests pass their own).
using slab_clipper = function_ref<aabb(const reference& r, float lo, float hi)>;

// Exercise 09.2 "chopped binning": fills bins (m.k of them, bins.size() == m.k; cleared first) with
// refs on `axis`:
//   STEP 1, span: the reference's first bin e = ch05::bin_index(m, r.box.min[axis]) and last bin
//     x = ch05::bin_index(m, r.box.max[axis]); bins[e].entry += 1, bins[x].exit += 1;
//   STEP 2, chop: a reference within one bin (e == x) grows that bin's box by its own box, unclipped. One
//     that spans bins e..x grows each bin j of them by clip(r, lo_j, hi_j): its part between
//     lo_j = bin_plane(m, j) and hi_j = bin_plane(m, j + 1), except that the first bin's part reaches
//     down to -inf (lo_e = -inf) and the last bin's up to +inf (hi_x = +inf), so that the bins' parts
//     cover the whole reference whatever the rounding of bin_index and bin_plane. An empty part grows
//     nothing.
// The entries left of a boundary and the exits right of it are the children's counts (spatial_split.hpp).
void chopped_binning(std::span<const reference> refs, int axis, const ch05::bin_mapping& m,
                     std::span<chopped_bin> bins, slab_clipper clip);

}  // namespace strahl::ch09
