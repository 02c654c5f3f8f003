// The spatial split of one node: the sweep over chopped bins, the search on three axes, and the
// distribution with reference unsplitting (Stich, Friedrich and Dietrich, HPG 2009, sections 4.3 and 4.5).
#include "strahl/ch09/spatial_split.hpp"
#include <cmath>

namespace strahl::ch09 {

void sweep_chopped_bins(int axis, const ch05::bin_mapping& m, std::span<const chopped_bin> bins,
                        std::span<float> right_area, const ch05::sah_costs& c, float area_parent, spatial_split& best) {
    const int k = int(bins.size());
    // The suffix sweep: the right side's box area per boundary (its count comes from the exits).
    aabb right;
    for (int b = k - 1; b > 0; --b) right.grow(bins[std::size_t(b)].box), right_area[std::size_t(b)] = right.surface_area();
    std::uint32_t n_right = 0;
    for (const chopped_bin& bin : bins) n_right += bin.exit;
    // The prefix sweep: entries to the left, exits to the right, and the cost at each boundary.
    aabb left;
    std::uint32_t n_left = 0;
    bool improved = false;
    for (int b = 1; b < k; ++b) {
        const chopped_bin& prev = bins[std::size_t(b - 1)];
        left.grow(prev.box);
        n_left += prev.entry, n_right -= prev.exit;
        if (n_left == 0 || n_right == 0) continue;
        const float cost = c.traversal + c.intersection *
                                             (left.surface_area() * float(n_left) + right_area[std::size_t(b)] * float(n_right)) /
                                             area_parent;
        if (cost < best.cost) {
            best.axis = axis, best.boundary = b, best.cost = cost, best.mapping = m;
            best.n_left = n_left, best.n_right = n_right;
            improved = true;
        }
    }
    // The winner's side boxes, once (not per boundary).
    if (improved) {
        best.left = best.right = aabb{};
        for (int b = 0; b < k; ++b) (b < best.boundary ? best.left : best.right).grow(bins[std::size_t(b)].box);
    }
}

spatial_split find_spatial_split(std::span<const reference> refs, std::span<const triangle> tris,
                                 const aabb& node_box, float area_parent, const ch05::sah_costs& c,
                                 std::span<chopped_bin> bins) {
    spatial_split best;
    const int k = int(bins.size());
    float right_area[256];
    for (int axis = 0; axis < 3; ++axis) {
        const float lo = node_box.min[axis], hi = node_box.max[axis];
        if (!(hi > lo)) continue;
        const ch05::bin_mapping m = ch05::make_bin_mapping(lo, hi, k);
        if (!std::isfinite(m.scale) || !(m.scale > 0.0f)) continue;  // an extent too small (or large) to bin
        // Each part clipped by exercise 09.1, within the reference's box.
        chopped_binning(refs, axis, m, bins, [&](const reference& r, float slab_lo, float slab_hi) {
            return clip_to_slab(tris[r.tri], axis, slab_lo, slab_hi, r.box);
        });
        sweep_chopped_bins(axis, m, bins, std::span<float>(right_area, std::size_t(k)), c, area_parent, best);
    }
    return best;
}

std::size_t distribute(std::span<const reference> refs, std::span<const triangle> tris, const spatial_split& s,
                       bool unsplit, std::size_t& budget_left, std::vector<reference>& left,
                       std::vector<reference>& right) {
    const int axis = s.axis;
    const float plane = s.plane();
    aabb lbox = s.left, rbox = s.right;
    float n_l = float(s.n_left), n_r = float(s.n_right);
    std::size_t unsplit_count = 0;
    for (const reference& r : refs) {
        const int e = ch05::bin_index(s.mapping, r.box.min[axis]), x = ch05::bin_index(s.mapping, r.box.max[axis]);
        if (x < s.boundary) { left.push_back(r); continue; }   // wholly left
        if (e >= s.boundary) { right.push_back(r); continue; }  // wholly right
        // A straddler: its two parts.
        const reference lpart{clip_to_slab(tris[r.tri], axis, -INFINITY, plane, r.box), r.tri};
        const reference rpart{clip_to_slab(tris[r.tri], axis, plane, INFINITY, r.box), r.tri};
        if (lpart.box.is_empty()) { right.push_back(r); continue; }
        if (rpart.box.is_empty()) { left.push_back(r); continue; }
        // Unsplitting: split, wholly left, or wholly right, whichever prices the children lowest.
        const float c_split = lbox.surface_area() * n_l + rbox.surface_area() * n_r;
        const float c_left = unite(lbox, r.box).surface_area() * n_l + rbox.surface_area() * (n_r - 1.0f);
        const float c_right = lbox.surface_area() * (n_l - 1.0f) + unite(rbox, r.box).surface_area() * n_r;
        const bool may_split = budget_left > 0;
        const bool split = may_split && (!unsplit || (c_split <= c_left && c_split <= c_right));
        if (split) {
            --budget_left;
            left.push_back(lpart), right.push_back(rpart);
        } else if (c_left <= c_right) {
            ++unsplit_count;
            left.push_back(r), lbox.grow(r.box), n_r -= 1.0f;
        } else {
            ++unsplit_count;
            right.push_back(r), rbox.grow(r.box), n_l -= 1.0f;
        }
    }
    return unsplit_count;
}

}  // namespace strahl::ch09
