// Exercise 03.2 classify a triangle against a plane (5 points). Read: I. Wald and V. Havran, "On building
// fast kd-trees for ray tracing, and on doing that in O(N log N)", 2006 (section 4.3, planar triangles).
#include "strahl/ch03/sah.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch03 {

// Goal: where a triangle with box b goes when its node is split at pos on axis: left, right or both. A
// planar triangle (b.min[axis] == b.max[axis] == pos) goes to the side planar_left says; touching the plane
// from one side counts as that side; straddling it: both (one more reference).
// Hint: test the planar case first: a planar box passes both "max <= pos" and "min >= pos".
// Why: why must these decisions agree exactly with the counts N_L, N_R and N_P of the event sweep (03.1)?
// Step by step: HINTS.md, 03.2.
side classify(const aabb& b, int axis, float pos, bool planar_left) {
    STRAHL_TODO("03.2 classify");
}

}  // namespace strahl::ch03
