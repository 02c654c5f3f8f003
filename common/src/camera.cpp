#include "strahl/camera.hpp"
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

namespace strahl {

camera::camera(const camera_desc& desc, int width, int height) : desc_(desc), width_(width), height_(height) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("camera: image size must be positive");
    if (!(desc.vfov_degrees > 0.0f && desc.vfov_degrees < 180.0f))
        throw std::invalid_argument("camera: vertical field of view must lie in (0, 180) degrees");
    if (!is_finite(desc.eye) || !is_finite(desc.target) || !is_finite(desc.up))
        throw std::invalid_argument("camera: eye, target and up must be finite");
    const vec3 view = desc.target - desc.eye;
    if (glm::length(glm::cross(view, desc.up)) == 0.0f)
        throw std::invalid_argument("camera: eye equals target, or up is parallel to the view direction");
    // The same basis glm::lookAt builds.
    forward_ = glm::normalize(view);
    right_ = glm::normalize(glm::cross(forward_, desc.up));
    up_ = glm::cross(right_, forward_);
    tan_half_fov_ = std::tan(glm::radians(desc.vfov_degrees) * 0.5f);
    aspect_ = float(width) / float(height);
}

ray camera::generate(float x, float y) const {
    const float ndc_x = 2.0f * x / float(width_) - 1.0f;
    const float ndc_y = 1.0f - 2.0f * y / float(height_);
    const vec3 d = forward_ + (ndc_x * tan_half_fov_ * aspect_) * right_ + (ndc_y * tan_half_fov_) * up_;
    return ray{desc_.eye, glm::normalize(d), 0.0f, inf};
}

mat4 camera::view_matrix() const { return glm::lookAt(desc_.eye, desc_.target, desc_.up); }

mat4 camera::projection_matrix(float znear, float zfar) const {
    return glm::perspective(glm::radians(desc_.vfov_degrees), aspect_, znear, zfar);
}

}  // namespace strahl
