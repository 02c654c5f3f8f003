#include "strahl/camera.hpp"
#include "strahl/scene.hpp"
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>
#include <string>

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

camera scene_camera(const scene& s, int width, int height) {
    try {
        return camera(s.camera, width, height);
    } catch (const std::invalid_argument& e) {
        std::string message = "scene '" + s.name + "': " + e.what();
        const aabb box = s.bounds();
        const vec3 extent = box.extent(), centre = box.centroid();
        char cause[400] = "";
        if (!box.is_empty() && !std::isfinite(glm::length(extent)))
            // frame_camera fits the box's bounding sphere, of radius |extent| / 2, which overflows to +inf;
            // its fallback radius of 1 is then lost against coordinates this large: eye and target coincide.
            std::snprintf(cause, sizeof cause,
                          "; the cause: the scene's extent (%.3g x %.3g x %.3g) overflows float arithmetic in the "
                          "camera framing (the length of its diagonal exceeds float's largest value, 3.4e38): "
                          "scale the mesh down",
                          double(extent.x), double(extent.y), double(extent.z));
        else if (!box.is_empty() && s.camera.eye == s.camera.target)
            std::snprintf(cause, sizeof cause,
                          "; the cause: the scene (extent %.3g x %.3g x %.3g) lies too far from the origin for its "
                          "size (its centre at %.3g, %.3g, %.3g): the camera's distance from it is below float's "
                          "resolution there; move the mesh towards the origin",
                          double(extent.x), double(extent.y), double(extent.z), double(centre.x), double(centre.y),
                          double(centre.z));
        throw std::invalid_argument(message + cause);
    }
}

mat4 camera::view_matrix() const { return glm::lookAt(desc_.eye, desc_.target, desc_.up); }

mat4 camera::projection_matrix(float znear, float zfar) const {
    return glm::perspective(glm::radians(desc_.vfov_degrees), aspect_, znear, zfar);
}

}  // namespace strahl
