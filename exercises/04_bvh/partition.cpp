// Exercise 04.2 the split of BUILD-HIERARCHY (8 points). Read: J. Goldsmith and J. Salmon, "Automatic
// creation of object hierarchies for ray tracing", IEEE CG&A 1987; pbrt-v4, 2023, section 7.3.2.
#include "strahl/ch04/bvh.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch04 {

// See bvh.hpp. In short, for the node's range ids (2 or more primitive ids):
//   1. the box around the centroids of ids; axis = its largest_axis();
//   2. all centroids equal on that axis (max == min): mid = n / 2, nothing moved;
//   3. spatial median: std::partition ids by centroid[axis] < (min + max) / 2 of the centroid box;
//      mid = size of the first part; if that is 0 or n, fall through to the object median;
//   4. object median: mid = n / 2, std::nth_element over ids by (centroid[axis], id).
// Returns {axis, mid}. No copies: ids is reordered in place.
split_result partition_split(std::span<std::uint32_t> ids, std::span<const vec3> centroids, split_method m) {
    STRAHL_TODO("04.2 partition");
}

}  // namespace strahl::ch04
