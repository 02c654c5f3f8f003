// Exercise 03.2 classify a triangle's box against a split plane. I. Wald and V. Havran, "On building fast
// kd-trees for ray tracing, and on doing that in O(N log N)", 2006 (section 4.3, planar triangles).
#include "strahl/ch03/sah.hpp"

namespace strahl::ch03 {

side classify(const aabb& b, int axis, float pos, bool planar_left) {
    // Planar: the box lies in the plane; it goes where the sweep found it cheaper.
    if (b.min[axis] == pos && b.max[axis] == pos) return planar_left ? side::left : side::right;
    // Wholly on one side (touching the plane counts as that side) ...
    if (b.max[axis] <= pos) return side::left;
    if (b.min[axis] >= pos) return side::right;
    // ... or straddling: a reference in both children.
    return side::both;
}

}  // namespace strahl::ch03
