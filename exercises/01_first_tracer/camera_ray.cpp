// Exercise 01.1 camera ray (4 points): the primary ray of a pinhole camera through image coordinate (x, y).
#include "strahl/ch01/whitted.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch01 {

// Build the ray from the camera's eye and basis (cam.eye(), cam.forward(), cam.right(), cam.up()), its
// cam.tan_half_fov(), cam.aspect(), cam.width() and cam.height(); it must equal cam.generate(x, y).
//   Step 1, image to NDC: x in [0, W] maps to [-1, 1] left to right, y in [0, H] to [1, -1]: row 0 is on top.
//   Step 2, NDC to the image plane one unit in front of the eye: half-height tan(fov/2), half-width aspect
//           times that; the direction is forward + (ndc_x ...) right + (ndc_y ...) up.
//   Step 3, the ray: origin at the eye, normalised direction, tmin 0, tmax inf.
ray primary_ray(const camera& cam, float x, float y) {
    STRAHL_TODO("01.1 camera ray");
}

}  // namespace strahl::ch01
