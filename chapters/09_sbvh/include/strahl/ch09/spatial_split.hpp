// The spatial split of one node: the best plane by chopped binning on each axis, and the distribution of
// the references to the two sides, with reference unsplitting.
//   M. Stich, H. Friedrich and A. Dietrich, "Spatial splits in bounding volume hierarchies", HPG 2009,
//   sections 4.3 (the sweep over chopped bins) and 4.5 (reference unsplitting).
#pragma once
#include "strahl/ch09/chopped_bins.hpp"
#include "strahl/ch09/clip.hpp"
#include <limits>
#include <vector>

namespace strahl::ch09 {

// A spatial split: bins [0, boundary) of `mapping` on `axis` go left, [boundary, k) right, the plane
// between them at bin_plane(mapping, boundary). cost: chapter 05's SAH cost of the split, the straddling
// references counted on both sides; +inf: none found.
struct spatial_split {
    int axis = -1;
    int boundary = 0;
    float cost = std::numeric_limits<float>::infinity();
    ch05::bin_mapping mapping;
    aabb left, right;                   // the bins' boxes on each side
    std::uint32_t n_left = 0, n_right = 0;  // the entries left of the boundary, the exits right of it
    float plane() const { return bin_plane(mapping, boundary); }
};

// SWEEP: over chopped bins (one axis), the boundary of least cost
//   C_T + C_I (A(L) N_L + A(R) N_R) / area_parent,
// N_L the entries of the bins left of it, N_R the exits of the bins right of it; a boundary with an empty
// side is skipped; ties to the lower boundary, and to the earlier axis (best is only replaced by a lower
// cost). right_area: scratch of bins.size() floats.
void sweep_chopped_bins(int axis, const ch05::bin_mapping& m, std::span<const chopped_bin> bins,
                        std::span<float> right_area, const ch05::sah_costs& c, float area_parent, spatial_split& best);

// FIND: chopped binning (exercise 09.2, each part clipped by exercise 09.1) over node_box on each axis the
// box extends along, and the sweep. bins: k chopped bins of scratch (k = their number).
spatial_split find_spatial_split(std::span<const reference> refs, std::span<const triangle> tris,
                                 const aabb& node_box, float area_parent, const ch05::sah_costs& c,
                                 std::span<chopped_bin> bins);

// DISTRIBUTE: each reference wholly left (its last bin left of the boundary), wholly right (its first bin
// right of it), or straddling. A straddler is clipped at the plane into its two parts (exercise 09.1: the
// left part below the plane, the right part above it, each within the reference's box); where a part is
// empty it goes wholly to the other side. Otherwise, with `unsplit`, the paper's test: with B its box and
// L, R, N_L, N_R the sides' current boxes and counts,
//   split:       A(L) N_L + A(R) N_R
//   wholly left: A(L u B) N_L + A(R) (N_R - 1)       wholly right: A(L) (N_L - 1) + A(R u B) N_R,
// the least of the three (ties: split, then left); the sides' boxes and counts follow each decision. A
// split takes one reference from budget_left; with none left only the two wholly-one-side choices remain.
// Returns the references unsplit (put wholly on one side though they straddle).
std::size_t distribute(std::span<const reference> refs, std::span<const triangle> tris, const spatial_split& s,
                       bool unsplit, std::size_t& budget_left, std::vector<reference>& left,
                       std::vector<reference>& right);

}  // namespace strahl::ch09
