// Exercise 04.2 the split of BUILD-HIERARCHY: object or spatial median, partitioning the index array in
// place. J. Goldsmith and J. Salmon, "Automatic creation of object hierarchies for ray tracing", IEEE CG&A
// 1987; M. Pharr, W. Jakob and G. Humphreys, pbrt-v4, 2023, section 7.3.2.
#include "strahl/ch04/bvh.hpp"
#include <algorithm>

namespace strahl::ch04 {

namespace {
// Object median: the n/2 entries with the smallest centroids (ties by id) first, in place.
std::size_t object_median(std::span<std::uint32_t> ids, std::span<const vec3> centroids, int axis) {
    const std::size_t mid = ids.size() / 2;
    std::nth_element(ids.begin(), ids.begin() + std::ptrdiff_t(mid), ids.end(),
                     [&](std::uint32_t a, std::uint32_t b) {
                         const float ca = centroids[a][axis], cb = centroids[b][axis];
                         return ca < cb || (ca == cb && a < b);
                     });
    return mid;
}
}  // namespace

split_result partition_split(std::span<std::uint32_t> ids, std::span<const vec3> centroids, split_method m) {
    // Step 1: the box around the centroids, and its longest axis.
    aabb cbox;
    for (const std::uint32_t id : ids) cbox.grow(centroids[id]);
    split_result s;
    s.axis = cbox.largest_axis();
    // Step 2, degenerate: all centroids in one point. No plane separates them: split the range in half.
    if (!(cbox.max[s.axis] > cbox.min[s.axis])) {
        s.mid = ids.size() / 2;
        return s;
    }
    // Step 3: the median.
    if (m == split_method::spatial_median) {
        const float pos = 0.5f * (cbox.min[s.axis] + cbox.max[s.axis]);
        const auto it = std::partition(ids.begin(), ids.end(),
                                       [&](std::uint32_t id) { return centroids[id][s.axis] < pos; });
        s.mid = std::size_t(it - ids.begin());
        if (s.mid > 0 && s.mid < ids.size()) return s;
    }
    s.mid = object_median(ids, centroids, s.axis);
    return s;
}

}  // namespace strahl::ch04
