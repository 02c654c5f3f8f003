// The flight's camera path and mirror floor (flight.hpp).
#include "strahl/ch14/flight.hpp"
#include <cmath>

namespace strahl::ch14 {

camera_desc flight_camera(const aabb& box, int f, int n) {
    const vec3 ext = box.extent();
    const int a = ext.x >= ext.z ? 0 : 2, b = 2 - a;
    const float s = n > 1 ? float(f) / float(n - 1) : 0.5f;
    camera_desc c;
    c.eye[a] = box.min[a] + (0.15f + 0.5f * s) * ext[a];
    c.eye[b] = box.min[b] + 0.5f * ext[b];
    c.eye.y = box.min.y + 0.25f * ext.y;
    vec3 ahead(0.0f, -0.15f, 0.0f);
    ahead[a] = 1.0f, ahead[b] = 0.21f * std::sin(2.0f * pi * s);  // tan(12 degrees) = 0.21
    c.target = c.eye + ahead * (0.25f * ext[a]);
    c.vfov_degrees = 60.0f;
    return c;
}

std::size_t make_floor_mirror(scene& s, const accel& built) {
    const aabb box = s.mesh.bounds();
    float floor_y = inf;
    for (int f = 0; f < 9; ++f) {
        const ray down{flight_camera(box, f, 9).eye, vec3(0.0f, -1.0f, 0.0f), 0.0f, inf};
        hit h;
        built.intersect(std::span<const ray>(&down, 1), std::span<hit>(&h, 1));
        if (h.found()) floor_y = std::min(floor_y, down.org.y - h.t);
    }
    if (floor_y == inf) floor_y = box.min.y;
    s.materials.push_back({"mirror floor", material_kind::mirror, color(0.8f), 0.0f});
    s.triangle_materials.resize(s.mesh.triangle_count(), 0u);  // (empty: every triangle material 0)
    std::size_t n = 0;
    for (std::size_t i = 0; i < s.mesh.triangle_count(); ++i) {
        const auto v = s.mesh.triangle(i);
        const vec3 c = glm::cross(v[1] - v[0], v[2] - v[0]);
        const float len = glm::length(c), y = (v[0].y + v[1].y + v[2].y) / 3.0f;
        if (len > 0.0f && std::fabs(c.y / len) > 0.9f && std::fabs(y - floor_y) <= 0.02f * box.extent().y)
            s.triangle_materials[i] = std::uint32_t(s.materials.size() - 1), ++n;
    }
    return n;
}

}  // namespace strahl::ch14
