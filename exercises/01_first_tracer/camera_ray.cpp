// Exercise 01.1 camera ray (4 points): the primary ray of a pinhole camera through image coordinate (x, y).
#include "strahl/ch01/whitted.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch01 {

// Goal: the primary ray through image coordinate (x, y): origin cam.eye(), normalised direction, tmin 0,
// tmax inf, equal to cam.generate(x, y). x in [0, W] runs left to right, y in [0, H] top to bottom (row 0 is
// on top). The camera gives eye(), forward(), right(), up(), tan_half_fov(), aspect(), width(), height().
// Hint: aim at the image plane one unit in front of the eye: its half-height is tan_half_fov(), its
// half-width aspect() times that.
// Why: why is the horizontal offset scaled by the aspect ratio and the vertical one not: which field of view
// does tan_half_fov() describe?
// Step by step: HINTS.md, 01.1.
ray primary_ray(const camera& cam, float x, float y) {
    STRAHL_TODO("01.1 camera ray");
}

}  // namespace strahl::ch01
