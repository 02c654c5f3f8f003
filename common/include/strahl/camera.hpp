// Pinhole camera with look-at placement and a vertical field of view.
//
// Image conventions (shared by the tracer and the OSMesa rasteriser, so that they agree pixel for pixel):
// pixel (i, j) covers the square [i, i+1) x [j, j+1) of image coordinates, its centre is (i + 0.5, j + 0.5),
// column 0 is at the left and row 0 at the TOP. Image coordinate (x, y) maps to normalised device
// coordinates ndc = (2x/W - 1, 1 - 2y/H), exactly as OpenGL's viewport transform does with rows flipped.
#pragma once
#include "strahl/ray.hpp"

namespace strahl {

// Where the camera is; independent of the image size.
struct camera_desc {
    vec3 eye{0.0f, 0.0f, 5.0f};
    vec3 target{0.0f};
    vec3 up{0.0f, 1.0f, 0.0f};
    float vfov_degrees = 45.0f;
};

class camera {
public:
    camera(const camera_desc& desc, int width, int height);

    // Primary ray through image coordinate (x, y); origin at the eye, direction normalised, t in [0, inf).
    ray generate(float x, float y) const;
    // Ray through pixel (px, py) at the given offset inside it; (0.5, 0.5) is the pixel centre.
    ray pixel_ray(int px, int py, vec2 offset = vec2(0.5f)) const {
        return generate(float(px) + offset.x, float(py) + offset.y);
    }

    // The same camera as OpenGL matrices (glm::lookAt and glm::perspective conventions).
    mat4 view_matrix() const;
    mat4 projection_matrix(float znear, float zfar) const;

    int width() const { return width_; }
    int height() const { return height_; }
    const camera_desc& desc() const { return desc_; }

    // The orthonormal basis: forward points at the target, right x up = -forward (right-handed, like GL).
    vec3 eye() const { return desc_.eye; }
    vec3 forward() const { return forward_; }
    vec3 right() const { return right_; }
    vec3 up() const { return up_; }
    float tan_half_fov() const { return tan_half_fov_; }  // tan(vfov / 2)
    float aspect() const { return aspect_; }              // width / height

private:
    camera_desc desc_;
    int width_, height_;
    vec3 forward_, right_, up_;
    float tan_half_fov_, aspect_;
};

struct scene;

// The camera of a scene, s.camera at width x height. Where the camera cannot be made, the
// std::invalid_argument names the scene and, where it can tell, the cause: a mesh whose extent overflows
// float arithmetic in the camera framing (frame_camera squares it: beyond about 1.8e19), or one that lies
// too far from the origin for its size (the camera's distance below float's resolution there).
camera scene_camera(const scene& s, int width, int height);

}  // namespace strahl
