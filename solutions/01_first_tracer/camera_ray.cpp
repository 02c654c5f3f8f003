// Exercise 01.1 camera ray: the primary ray of a pinhole camera through image coordinate (x, y).
#include "strahl/ch01/whitted.hpp"

namespace strahl::ch01 {

ray primary_ray(const camera& cam, float x, float y) {
    // Step 1, image to NDC: x in [0, W] maps to [-1, 1] left to right, y in [0, H] to [1, -1] (row 0 on top).
    const float ndc_x = 2.0f * x / float(cam.width()) - 1.0f;
    const float ndc_y = 1.0f - 2.0f * y / float(cam.height());
    // Step 2, NDC to the image plane at distance 1 in front of the eye: half-height tan(fov/2), half-width
    // aspect times that.
    const vec3 d = cam.forward() + (ndc_x * cam.tan_half_fov() * cam.aspect()) * cam.right() +
                   (ndc_y * cam.tan_half_fov()) * cam.up();
    // Step 3, the ray: from the eye, normalised direction, t in [0, inf).
    return ray{cam.eye(), glm::normalize(d), 0.0f, inf};
}

}  // namespace strahl::ch01
