// The animated scene (animation.hpp).
#include "strahl/ch10/animation.hpp"
#include <cmath>

namespace strahl::ch10 {

animation make_animation(triangle_mesh rigid, std::string rigid_name, int nx, int nz, triangle_mesh deforming,
                         std::string deforming_name, int frames) {
    animation a;
    a.frames = frames;
    const aabb rb = rigid.bounds();
    const float size = std::max({rb.extent().x, rb.extent().y, rb.extent().z});
    a.start = make_field(std::move(rigid), std::move(rigid_name), nx, nz, 1.3f);
    // The deforming mesh: twice a field member's size, standing on y = 0 beside the field's middle row.
    const aabb db = deforming.bounds();
    const float dsize = std::max({db.extent().x, db.extent().y, db.extent().z});
    const float s = 2.0f * size / dsize;
    const vec3 c = db.centroid();
    const float step = 1.3f * size;
    const vec3 front(float(nx) * step + 0.5f * size, 0.0f, 0.5f * float(nz - 1) * step);
    a.deforming = std::uint32_t(a.start.meshes.size());
    a.start.meshes.push_back(std::move(deforming));
    a.start.names.push_back(std::move(deforming_name));
    a.start.instances.push_back({a.deforming, affine::translate(front) * affine::scale(vec3(s)) *
                                                  affine::translate({-c.x, -db.min.y, -c.z})});
    const aabb box = a.start.bounds();
    const vec3 mid = box.centroid();
    const float d = glm::length(box.extent());
    a.camera.eye = mid + vec3(0.0f, 0.3f * d, 0.8f * d);
    a.camera.target = mid;
    a.camera.vfov_degrees = 40.0f;
    return a;
}

std::vector<affine> animation::transforms(int frame) const {
    std::vector<affine> t;
    const float phase = 2.0f * 3.14159265f * float(frame) / float(std::max(frames, 1));
    for (std::size_t i = 0; i < start.instances.size(); ++i) {
        const instance& in = start.instances[i];
        if (in.mesh == deforming) {
            t.push_back(in.to_world);
            continue;
        }
        // Bob up and down by a third of the mesh's height, each with its own phase, and turn about its own
        // vertical axis, a full turn over the animation (every other one the other way).
        const aabb b = start.meshes[in.mesh].bounds();
        const vec3 c = b.centroid();
        const float bob = 0.33f * b.extent().y * std::sin(phase + 0.7f * float(i));
        const float turn = (i % 2 ? -360.0f : 360.0f) * float(frame) / float(std::max(frames, 1));
        t.push_back(affine::translate({0.0f, bob, 0.0f}) * in.to_world * affine::translate(c) *
                    affine::rotate(1, turn) * affine::translate(-c));
    }
    return t;
}

std::vector<vec3> animation::vertices(int frame) const {
    const triangle_mesh& m = start.meshes[deforming];
    const aabb b = m.bounds();
    const vec3 c = b.centroid();
    const float h = std::max(b.extent().y, 1e-20f);
    const float total = twist_degrees * 3.14159265f / 180.0f * float(frame) / float(std::max(frames - 1, 1));
    std::vector<vec3> p(m.positions.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        const vec3 q = m.positions[i] - c;
        const float a = total * (m.positions[i].y - b.min.y) / h;
        p[i] = c + vec3(std::cos(a) * q.x - std::sin(a) * q.z, q.y, std::sin(a) * q.x + std::cos(a) * q.z);
    }
    return p;
}

instanced_meshes animation::at(int frame) const {
    instanced_meshes s = start;
    const std::vector<affine> t = transforms(frame);
    for (std::size_t i = 0; i < t.size(); ++i) s.instances[i].to_world = t[i];
    s.meshes[deforming].positions = vertices(frame);
    return s;
}

}  // namespace strahl::ch10
