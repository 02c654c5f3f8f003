// Exercise 03.2 classify a triangle against a plane (5 points). Read: I. Wald and V. Havran, "On building
// fast kd-trees for ray tracing, and on doing that in O(N log N)", 2006 (section 4.3, planar triangles).
#include "strahl/ch03/sah.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch03 {

// Where does a triangle with box b go when its node is split at pos on axis?
//   planar (b.min[axis] == b.max[axis] == pos): to the side planar_left says;
//   b.max[axis] <= pos: left (touching the plane from below is still left);
//   b.min[axis] >= pos: right;
//   otherwise it straddles the plane: both (one more reference).
side classify(const aabb& b, int axis, float pos, bool planar_left) {
    STRAHL_TODO("03.2 classify");
}

}  // namespace strahl::ch03
