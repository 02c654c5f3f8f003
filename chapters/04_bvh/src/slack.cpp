// The ray's slack for the box tests (the same measure as chapter 03's): how far, in t units, a triangle
// test's computed t may stray from the exact t of the box around it.
#include "strahl/ch04/traverse.hpp"

namespace strahl::ch04 {

float ray_slack(const ray& r, const aabb& box) {
    // Relative 2^-16 of the farthest t inside the box, plus 1e-5 of the box's diagonal, in t units.
    const float len = glm::length(r.dir);
    const float diag = glm::length(box.extent());
    const float reach = glm::length(r.org - box.centroid()) + diag;
    return (reach * 0x1p-16f + 1e-5f * diag) / len;
}

}  // namespace strahl::ch04
