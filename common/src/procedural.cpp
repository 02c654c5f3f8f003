// Procedural scenes: Cornell box, Utah teapot (Newell's Bezier patches), teapot in a stadium (Haines),
// UV sphere, random and clustered triangle soups. Every generator is deterministic; the emitted triangle
// order is documented at each function (it is the primitive id).
#include "strahl/procedural.hpp"
#include "strahl/instancing.hpp"
#include "strahl/rng.hpp"
#include <array>
#include <cmath>
#include <stdexcept>

namespace strahl {

namespace teapot_data {  // defined in teapot_data.cpp
inline constexpr std::size_t patch_count = 32;
inline constexpr std::size_t vertex_count = 306;
extern const std::array<std::array<std::uint16_t, 16>, patch_count> patches;
extern const std::array<std::array<float, 3>, vertex_count> vertices;
}  // namespace teapot_data

namespace {

// Appends the quad a b c d as triangles (a b c) and (a c d), reversing the corner order first where needed
// so that the geometric normal (b - a) x (c - a) points along `facing`.
void add_quad(triangle_mesh& m, vec3 a, vec3 b, vec3 c, vec3 d, const vec3& facing) {
    if (glm::dot(glm::cross(b - a, c - a), facing) < 0.0f) std::swap(b, d);
    const auto base = std::uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), {a, b, c, d});
    m.indices.emplace_back(base, base + 1, base + 2);
    m.indices.emplace_back(base, base + 2, base + 3);
}

// The camera of frame_camera, swung up about the target by `elevation_degrees` (same distance).
camera_desc elevated_camera(const aabb& box, float elevation_degrees) {
    camera_desc cam = frame_camera(box);
    const float d = glm::length(cam.eye - cam.target);
    const float e = glm::radians(elevation_degrees);
    cam.eye = cam.target + d * vec3(0.0f, std::sin(e), std::cos(e));
    return cam;
}

// Cubic Bernstein basis at t: (1-t)^3, 3t(1-t)^2, 3t^2(1-t), t^3.
std::array<double, 4> bernstein3(double t) {
    const double s = 1.0 - t;
    return {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
}

}  // namespace

scene cornell_box(bool with_spheres) {
    scene s;
    s.name = "cornell";
    s.materials = {
        {"white", material_kind::diffuse, color(0.73f), 0.0f},
        {"red", material_kind::diffuse, color(0.65f, 0.05f, 0.05f), 0.0f},
        {"green", material_kind::diffuse, color(0.12f, 0.45f, 0.15f), 0.0f},
        {"mirror", material_kind::mirror, color(0.9f), 0.0f},
        {"rough_mirror", material_kind::rough_mirror, color(0.9f), 0.2f},
    };
    // Walls in the documented order, each quad facing into the box: floor, ceiling, back, left, right.
    triangle_mesh& m = s.mesh;
    add_quad(m, {0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, {0, 1, 0});     // floor, y = 0
    add_quad(m, {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}, {0, -1, 0});    // ceiling, y = 1
    add_quad(m, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1});     // back wall, z = 0
    add_quad(m, {0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}, {1, 0, 0});     // left wall, x = 0
    add_quad(m, {1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}, {-1, 0, 0});    // right wall, x = 1
    s.triangle_materials = {0, 0, 0, 0, 0, 0, 1, 1, 2, 2};
    if (with_spheres) {
        s.spheres.push_back({vec3(0.3f, 0.18f, 0.35f), 0.18f, 3});  // mirror, back left
        s.spheres.push_back({vec3(0.7f, 0.18f, 0.6f), 0.18f, 4});   // rough mirror, front right
    }
    s.lights = {point_light{vec3(0.5f, 0.95f, 0.5f), color(2.0f)}};
    // The open front (z = 1) spans 0.5 / 1.6 = tan 17.4 degrees from the eye: inside the 20 degree half fov.
    s.camera = camera_desc{vec3(0.5f, 0.5f, 2.6f), vec3(0.5f, 0.5f, 0.5f), vec3(0, 1, 0), 40.0f};
    return s;
}

triangle_mesh teapot_mesh(int resolution) {
    if (resolution < 1) throw std::invalid_argument("teapot_mesh: resolution must be at least 1");
    const auto n = std::size_t(resolution);
    triangle_mesh m;
    m.positions.reserve(teapot_data::patch_count * (n + 1) * (n + 1));
    m.indices.reserve(teapot_data::patch_count * 2 * n * n);
    for (const auto& patch : teapot_data::patches) {
        // 1. Evaluate the patch on a (n+1) x (n+1) grid, row j at v = j/n, column i at u = i/n:
        //    P(u, v) = sum over r, c of B_r(v) B_c(u) P[r][c], control point P[r][c] = patch[4r + c].
        //    The data is z-up; (x, y, z) -> (x, z, -y) turns it y-up (a rotation about x).
        const auto base = std::uint32_t(m.positions.size());
        for (std::size_t j = 0; j <= n; ++j) {
            const auto bv = bernstein3(double(j) / double(n));
            for (std::size_t i = 0; i <= n; ++i) {
                const auto bu = bernstein3(double(i) / double(n));
                double p[3] = {0.0, 0.0, 0.0};
                for (int r = 0; r < 4; ++r)
                    for (int c = 0; c < 4; ++c) {
                        const auto& cp = teapot_data::vertices[patch[std::size_t(4 * r + c)]];
                        const double w = bv[std::size_t(r)] * bu[std::size_t(c)];
                        for (int k = 0; k < 3; ++k) p[k] += w * double(cp[std::size_t(k)]);
                    }
                m.positions.emplace_back(float(p[0]), float(p[2]), float(-p[1]));
            }
        }
        // 2. Quads row by row (v), column by column (u); quad (i, j) with corners a = (i, j), b = (i+1, j),
        //    c = (i+1, j+1), d = (i, j+1) gives (a, b, c) then (a, c, d): outward-facing on the body.
        const auto at = [&](std::size_t i, std::size_t j) { return base + std::uint32_t(j * (n + 1) + i); };
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t i = 0; i < n; ++i) {
                m.indices.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
                m.indices.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
            }
    }
    return m;
}

scene teapot_scene(int resolution) {
    scene s;
    s.name = "teapot";
    s.mesh = teapot_mesh(resolution);
    s.materials = {{"teapot", material_kind::diffuse, color(0.8f, 0.7f, 0.55f), 0.0f},
                   {"ground", material_kind::diffuse, color(0.6f), 0.0f}};
    s.planes = {plane_desc{vec3(0, 1, 0), 0.0f, 1}};  // the teapot stands on y = 0
    const aabb box = s.mesh.bounds();
    s.camera = elevated_camera(box, 20.0f);
    s.lights = {frame_light(box, s.camera)};
    return s;
}

scene teapot_in_stadium(int teapot_resolution, int stadium_segments) {
    if (stadium_segments < 3) throw std::invalid_argument("teapot_in_stadium: at least 3 segments");
    // Sizes: the teapot is about 6.5 wide and 3.15 high; the field's radius is 100 half-widths of it.
    constexpr float field_radius = 320.0f, tread = 16.0f, riser = 8.0f;
    constexpr int tiers = 12;
    scene s;
    s.name = "teapot_stadium";
    s.mesh = teapot_mesh(teapot_resolution);
    const aabb teapot_box = s.mesh.bounds();
    const std::size_t teapot_triangles = s.mesh.triangle_count();
    // Order after the teapot: the field (a fan of `segments` triangles around the origin at y = 0), then
    // tier by tier outwards, segment by segment: the riser (2 triangles, facing the centre), then the tread
    // (2 triangles, facing up).
    const auto ring = [&](float radius, float y, int k) {
        const float a = 2.0f * pi * float(k % stadium_segments) / float(stadium_segments);
        return vec3(radius * std::cos(a), y, -radius * std::sin(a));
    };
    triangle_mesh& m = s.mesh;
    const auto centre = std::uint32_t(m.positions.size());
    m.positions.emplace_back(0.0f);
    for (int k = 0; k < stadium_segments; ++k) m.positions.push_back(ring(field_radius, 0.0f, k));
    for (int k = 0; k < stadium_segments; ++k)  // counter-clockwise seen from above: facing up
        m.indices.emplace_back(centre, centre + 1 + std::uint32_t(k),
                               centre + 1 + std::uint32_t((k + 1) % stadium_segments));
    for (int t = 0; t < tiers; ++t) {
        const float r0 = field_radius + float(t) * tread, r1 = r0 + tread;
        const float y0 = float(t) * riser, y1 = y0 + riser;
        for (int k = 0; k < stadium_segments; ++k) {
            const vec3 inward = -glm::normalize(ring(1.0f, 0.0f, k) + ring(1.0f, 0.0f, k + 1));
            add_quad(m, ring(r0, y0, k), ring(r0, y0, k + 1), ring(r0, y1, k + 1), ring(r0, y1, k), inward);
            add_quad(m, ring(r0, y1, k), ring(r0, y1, k + 1), ring(r1, y1, k + 1), ring(r1, y1, k), {0, 1, 0});
        }
    }
    s.materials = {{"teapot", material_kind::diffuse, color(0.8f, 0.7f, 0.55f), 0.0f},
                   {"stadium", material_kind::diffuse, color(0.5f), 0.0f}};
    s.triangle_materials.assign(m.triangle_count(), 1u);
    std::fill_n(s.triangle_materials.begin(), teapot_triangles, 0u);
    s.camera = elevated_camera(teapot_box, 20.0f);
    s.lights = {frame_light(teapot_box, s.camera)};
    return s;
}

triangle_mesh tessellated_sphere(int stacks, int slices) {
    if (stacks < 2 || slices < 3) throw std::invalid_argument("tessellated_sphere: stacks >= 2, slices >= 3");
    // Vertices: north pole, rings 1 .. stacks-1 from north to south (slices each), south pole.
    // Triangles: the north cap fan (slices), then between rings k and k+1 for each k the quads (2 each, slice
    // by slice), then the south cap fan (slices): 2 * slices * (stacks - 1) in all, counter-clockwise
    // seen from outside.
    triangle_mesh m;
    const auto su = std::uint32_t(slices);
    m.positions.emplace_back(0.0f, 1.0f, 0.0f);
    for (int k = 1; k < stacks; ++k) {
        const float phi = pi * float(k) / float(stacks);
        for (int j = 0; j < slices; ++j) {
            const float theta = 2.0f * pi * float(j) / float(slices);
            m.positions.emplace_back(std::sin(phi) * std::cos(theta), std::cos(phi), -std::sin(phi) * std::sin(theta));
        }
    }
    m.positions.emplace_back(0.0f, -1.0f, 0.0f);
    const auto south = std::uint32_t(m.positions.size() - 1);
    const auto at = [&](int ring, std::uint32_t j) { return 1u + std::uint32_t(ring - 1) * su + j % su; };
    for (std::uint32_t j = 0; j < su; ++j) m.indices.emplace_back(0u, at(1, j), at(1, j + 1));
    for (int k = 1; k + 1 < stacks; ++k)
        for (std::uint32_t j = 0; j < su; ++j) {
            m.indices.emplace_back(at(k, j), at(k + 1, j), at(k + 1, j + 1));
            m.indices.emplace_back(at(k, j), at(k + 1, j + 1), at(k, j + 1));
        }
    for (std::uint32_t j = 0; j < su; ++j) m.indices.emplace_back(at(stacks - 1, j), south, at(stacks - 1, j + 1));
    return m;
}

namespace {

// A triangle of three vertices scattered by up to size/2 per axis around centre (in triangle order).
void add_soup_triangle(triangle_mesh& m, pcg32& rng, const vec3& centre, float size) {
    const auto base = std::uint32_t(m.positions.size());
    for (int k = 0; k < 3; ++k) {
        const vec3 offset(rng.next_float() - 0.5f, rng.next_float() - 0.5f, rng.next_float() - 0.5f);
        m.positions.push_back(centre + size * offset);
    }
    m.indices.emplace_back(base, base + 1, base + 2);
}

}  // namespace

triangle_mesh random_soup(std::size_t count, std::uint64_t seed, float size) {
    // Triangle i: a centre uniform in the cube [h, 1-h]^3 (h = size/2, so that every vertex lies in the
    // unit cube), then its three vertices; all drawn from one PCG32 stream in that order.
    pcg32 rng(seed);
    triangle_mesh m;
    m.positions.reserve(3 * count);
    m.indices.reserve(count);
    const float h = std::min(0.5f * size, 0.5f);
    for (std::size_t i = 0; i < count; ++i) {
        const vec3 u(rng.next_float(), rng.next_float(), rng.next_float());
        add_soup_triangle(m, rng, vec3(h) + (1.0f - 2.0f * h) * u, size);
    }
    return m;
}

triangle_mesh clustered_soup(std::size_t count, std::uint64_t seed, int clusters, float size) {
    // 1. Cluster centres uniform in [0.15, 0.85]^3. 2. Triangle i picks a cluster at random and a centre
    // about it with a Gaussian-like offset (Irwin-Hall: a sum of four uniforms, standard deviation 0.05 per
    // axis), clamped so that its vertices stay in the unit cube. 3. Its vertices as in random_soup.
    if (clusters < 1) throw std::invalid_argument("clustered_soup: clusters must be at least 1");
    pcg32 rng(seed);
    std::vector<vec3> centres(static_cast<std::size_t>(clusters));
    for (vec3& c : centres) c = vec3(0.15f) + 0.7f * vec3(rng.next_float(), rng.next_float(), rng.next_float());
    const auto gaussian = [&] {
        return (rng.next_float() + rng.next_float() + rng.next_float() + rng.next_float() - 2.0f) * std::sqrt(3.0f);
    };
    triangle_mesh m;
    m.positions.reserve(3 * count);
    m.indices.reserve(count);
    const float h = std::min(0.5f * size, 0.5f), sigma = 0.05f;
    for (std::size_t i = 0; i < count; ++i) {
        const vec3 c = centres[rng.next_bounded(std::uint32_t(clusters))];
        const float gx = gaussian(), gy = gaussian(), gz = gaussian();
        add_soup_triangle(m, rng, glm::clamp(c + sigma * vec3(gx, gy, gz), vec3(h), vec3(1.0f - h)), size);
    }
    return m;
}

scene mesh_scene(std::string name, triangle_mesh mesh) {
    scene s;
    s.name = std::move(name);
    s.mesh = std::move(mesh);
    s.materials = {material_desc{"diffuse", material_kind::diffuse, color(0.8f), 0.0f}};
    const aabb box = s.mesh.bounds();
    s.camera = frame_camera(box);
    s.lights = {frame_light(box, s.camera)};
    return s;
}

std::vector<std::string> builtin_scene_names() {
    return {"cornell", "teapot", "teapot_stadium", "sphere", "soup", "clustered_soup", "teapot_field"};
}

scene builtin_scene(const std::string& name) {
    // Each scene's name is its builtin name, so load_scene_spec("builtin:" + s.name) gives it back.
    if (name == "cornell") return cornell_box(true);
    if (name == "teapot") return teapot_scene(8);
    if (name == "teapot_stadium") return teapot_in_stadium(8, 64);
    if (name == "sphere") return mesh_scene(name, tessellated_sphere(32, 64));
    if (name == "soup") return mesh_scene(name, random_soup(10000, 1));
    if (name == "clustered_soup") return mesh_scene(name, clustered_soup(10000, 1));
    if (name == "teapot_field") {
        scene s = instanced_scene(make_field(teapot_mesh(4), "teapot", 5, 5, 1.5f), name);
        const aabb box = s.mesh.bounds();
        s.camera = elevated_camera(box, 35.0f);  // from above the front row: most rays meet a teapot
        s.lights = {frame_light(box, s.camera)};
        return s;
    }
    std::string valid;
    for (const std::string& n : builtin_scene_names()) valid += (valid.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown builtin scene '" + name + "'; valid names: " + valid);
}

}  // namespace strahl
