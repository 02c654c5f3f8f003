// Exercise 05.3 prefix and suffix sweeps over bins (10 points). Read: I. Wald, "On fast construction of
// SAH-based bounding volume hierarchies", IEEE Symposium on Interactive Ray Tracing 2007, section 3.
#include "strahl/ch05/sah.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch05 {

// Goal: the boundary b (bins [0, b) left, [b, k) right) with the lowest SAH cost (exercise 05.1's formula),
// found in two linear sweeps; right_area is scratch space of k floats. Boundaries that leave a side empty do
// not count; the lowest index wins a tie; fewer than 2 bins or no boundary: bin_split{} (index 0, cost inf).
// Hint: sweep from the right first and store the area of bins b .. k-1 for every b; then one sweep from the
// left grows the left box and count and prices each boundary once.
// Why: why do two sweeps of k steps suffice where pricing each boundary from scratch takes k^2 box unions,
// and why does this step's cost depend on k and not on the number of triangles?
// Step by step: HINTS.md, 05.3.
bin_split best_boundary(std::span<const bin> bins, std::span<float> right_area, const sah_costs& c,
                        float area_parent) {
    STRAHL_TODO("05.3 prefix and suffix sweeps");
}

}  // namespace strahl::ch05
