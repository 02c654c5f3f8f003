// The chapter's animated scene: a field of instances that bob and turn (rigid motion: only the top level
// changes) and one mesh that twists about its vertical axis (deformation: its own tree must follow). Frame f
// of `frames` is a pure function of f, so every update method sees the same scene at every frame.
#pragma once
#include "strahl/camera.hpp"
#include "strahl/instancing.hpp"
#include <string>
#include <vector>

namespace strahl::ch10 {

struct animation {
    instanced_meshes start;          // frame 0's meshes and instances (the deforming mesh untwisted)
    std::uint32_t deforming = 0;     // the mesh that twists (one instance of it)
    int frames = 24;
    float twist_degrees = 270.0f;    // the twist at the last frame, bottom to top
    camera_desc camera;

    std::vector<affine> transforms(int frame) const;  // every instance's to_world at frame
    std::vector<vec3> vertices(int frame) const;      // the deforming mesh's vertices at frame
    instanced_meshes at(int frame) const;             // the whole scene at frame
};

// rigid: a field of nx x nz copies of `rigid`; deforming: beside the field, twice the size of one of them.
// The camera looks down at them from the front.
animation make_animation(triangle_mesh rigid, std::string rigid_name, int nx, int nz, triangle_mesh deforming,
                         std::string deforming_name, int frames);

}  // namespace strahl::ch10
