// Unit tests of the procedural scenes (common/src/procedural.cpp) and of the mesh and scene helpers:
// triangle counts, documented orders, determinism, bounds, orientation, the builtin names.
#include <catch2/catch.hpp>
#include "strahl/procedural.hpp"
#include "strahl/scene.hpp"
#include "test_support.hpp"
#include <set>

using namespace strahl;
using Catch::Matchers::Contains;

namespace {

vec3 normal_of(const std::array<vec3, 3>& t) { return glm::cross(t[1] - t[0], t[2] - t[0]); }
vec3 centroid_of(const std::array<vec3, 3>& t) { return (t[0] + t[1] + t[2]) / 3.0f; }

bool all_finite(const triangle_mesh& m) {
    for (const vec3& p : m.positions)
        if (!is_finite(p)) return false;
    return true;
}

bool indices_in_range(const triangle_mesh& m) {
    for (const uvec3& t : m.indices)
        if (!glm::all(glm::lessThan(t, uvec3(m.positions.size())))) return false;
    return true;
}

}  // namespace

TEST_CASE("procedural: mesh bounds, append re-bases indices, scene bounds include spheres", "[common][procedural]") {
    triangle_mesh empty;
    CHECK(empty.bounds().is_empty());
    triangle_mesh a;
    a.positions = {vec3(0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(100)};  // the last one is unreferenced
    a.indices = {uvec3(0, 1, 2)};
    CHECK(a.bounds().max == vec3(1, 1, 0));
    triangle_mesh b;
    b.positions = {vec3(5), vec3(6, 5, 5), vec3(5, 6, 5)};
    b.indices = {uvec3(2, 1, 0)};
    a.append(b);
    REQUIRE(a.triangle_count() == 2);
    CHECK(a.indices[1] == uvec3(6, 5, 4));
    CHECK(a.triangle(1) == std::array<vec3, 3>{vec3(5, 6, 5), vec3(6, 5, 5), vec3(5)});
    a.append(empty);
    CHECK(a.triangle_count() == 2);

    scene s;
    s.mesh = b;
    s.spheres.push_back({vec3(0), 2.0f, 0});
    s.planes.push_back({});
    CHECK(s.bounds().min == vec3(-2));
    CHECK(s.bounds().max == vec3(6, 6, 5));
    CHECK(scene{}.bounds().is_empty());
}

TEST_CASE("procedural: Cornell box walls, materials, spheres, light and camera", "[common][procedural]") {
    const scene s = cornell_box(true);
    CHECK(s.name == "cornell");
    REQUIRE(s.mesh.triangle_count() == 10);
    CHECK(s.mesh.bounds().min == vec3(0));
    CHECK(s.mesh.bounds().max == vec3(1));
    // Order floor, ceiling, back, left, right; every wall faces into the box.
    const vec3 inward[5] = {{0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {1, 0, 0}, {-1, 0, 0}};
    const char* names[5] = {"white", "white", "white", "red", "green"};
    for (std::size_t i = 0; i < 10; ++i) {
        const vec3 n = glm::normalize(normal_of(s.mesh.triangle(i)));
        CHECK(glm::dot(n, inward[i / 2]) == Approx(1.0f));
        CHECK(s.materials[s.triangle_material(i)].name == names[i / 2]);
    }
    REQUIRE(s.spheres.size() == 2);
    CHECK(s.materials[s.spheres[0].material].kind == material_kind::mirror);
    const material_desc& rough = s.materials[s.spheres[1].material];
    CHECK(rough.kind == material_kind::rough_mirror);
    CHECK(rough.roughness == Approx(0.2f));
    for (const sphere_desc& sp : s.spheres) {
        CHECK(sp.center.y == Approx(sp.radius));  // standing on the floor
        CHECK(aabb{vec3(0), vec3(1)}.contains(sp.center + vec3(sp.radius)));
        CHECK(aabb{vec3(0), vec3(1)}.contains(sp.center - vec3(sp.radius)));
    }
    REQUIRE(s.lights.size() == 1);
    CHECK(s.lights[0].position.y < 1.0f);
    CHECK(s.lights[0].position.y > 0.8f);
    CHECK(s.camera.eye.z > 1.0f);
    CHECK_NOTHROW(camera(s.camera, 64, 64));
    // Every corner of the box inside a square image: its projection within tan(vfov / 2) on both axes.
    const camera cam(s.camera, 64, 64);
    for (int c = 0; c < 8; ++c) {
        const vec3 d = vec3(float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1)) - cam.eye();
        const float depth = glm::dot(d, cam.forward());
        CHECK(depth > 0.0f);
        CHECK(std::abs(glm::dot(d, cam.right()) / depth) < cam.tan_half_fov());
        CHECK(std::abs(glm::dot(d, cam.up()) / depth) < cam.tan_half_fov());
    }
    CHECK(cornell_box(false).spheres.empty());
    CHECK(cornell_box(false).mesh.triangle_count() == 10);
}

TEST_CASE("procedural: the Utah teapot's triangle count, bounds, orientation and poles", "[common][procedural]") {
    for (const int res : {1, 2, 3, 4, 10}) {
        const triangle_mesh m = teapot_mesh(res);
        CHECK(m.triangle_count() == std::size_t(32 * 2 * res * res));
        CHECK(m.positions.size() == std::size_t(32 * (res + 1) * (res + 1)));
        CHECK(all_finite(m));
        CHECK(indices_in_range(m));
        // y-up, standing on y = 0, the lid's knob at y = 3.15 (a patch corner: exact at every resolution).
        CHECK(m.bounds().min.y == Approx(0.0f).margin(1e-6));
        CHECK(m.bounds().max.y == Approx(3.15f));
    }
    // The classic proportions at resolution 10: handle to spout -3 .. 3.434, body radius 2.
    const triangle_mesh m = teapot_mesh(10);
    const aabb b = m.bounds();
    CHECK(b.min.x == Approx(-3.0f).margin(1e-3));
    CHECK(b.max.x == Approx(3.434f).margin(1e-3));
    CHECK(b.min.z == Approx(-2.0f).margin(1e-3));
    CHECK(b.max.z == Approx(2.0f).margin(1e-3));
    // Body patches 4..7 (triangles 800..1599 at resolution 10) face away from the y axis.
    int outward = 0, inward = 0;
    for (std::size_t i = 4 * 200; i < 8 * 200; ++i) {
        const auto t = m.triangle(i);
        vec3 radial = centroid_of(t);
        radial.y = 0.0f;
        const vec3 n = normal_of(t);
        if (glm::length(n) > 0.0f) (glm::dot(n, radial) > 0.0f ? outward : inward)++;
    }
    CHECK(outward == 800);
    CHECK(inward == 0);
    // Degenerate triangles at the lid's and bottom's poles are kept.
    std::size_t degenerate = 0;
    for (std::size_t i = 0; i < m.triangle_count(); ++i) degenerate += glm::length(normal_of(m.triangle(i))) == 0.0f;
    CHECK(degenerate >= 8 * 10);
    CHECK(teapot_mesh(3).positions == teapot_mesh(3).positions);  // deterministic
    REQUIRE_THROWS_AS(teapot_mesh(0), std::invalid_argument);
}

TEST_CASE("procedural: teapot_mesh(10) matches the shared teapot.obj vertex for vertex", "[common][procedural]") {
    const auto path = test::shared_scene("teapot.obj");
    if (path.empty()) { WARN("skipped: ../shared/scenes/teapot.obj is absent"); return; }
    const triangle_mesh ref = load_mesh(path);
    const triangle_mesh m = teapot_mesh(10);
    // Every 7th vertex of the file lies on a vertex of ours (the file is Newell's data at 10 x 10 per patch).
    float worst = 0.0f;
    for (std::size_t i = 0; i < ref.positions.size(); i += 7) {
        float best = inf;
        for (const vec3& p : m.positions) best = std::min(best, glm::length(p - ref.positions[i]));
        worst = std::max(worst, best);
    }
    CHECK(worst < 1e-4f);
}

TEST_CASE("procedural: teapot scene and teapot in a stadium", "[common][procedural]") {
    const scene t = teapot_scene(4);
    CHECK(t.name == "teapot");
    CHECK(t.mesh.triangle_count() == 32 * 2 * 16);
    REQUIRE(t.planes.size() == 1);
    CHECK(t.planes[0].normal == vec3(0, 1, 0));
    CHECK(t.materials.at(t.planes[0].material).kind == material_kind::diffuse);
    CHECK(t.lights.size() == 1);
    CHECK_NOTHROW(camera(t.camera, 64, 64));

    const scene s = teapot_in_stadium(4, 32);
    const triangle_mesh teapot = teapot_mesh(4);
    REQUIRE(s.mesh.triangle_count() > teapot.triangle_count());
    for (std::size_t i = 0; i < teapot.triangle_count(); ++i) {  // the teapot comes first
        REQUIRE(s.mesh.triangle(i) == teapot.triangle(i));
        REQUIRE(s.triangle_material(i) == 0);
    }
    CHECK(s.triangle_material(s.mesh.triangle_count() - 1) == 1);
    CHECK(indices_in_range(s.mesh));
    const aabb stadium = s.mesh.bounds(), pot = teapot.bounds();
    CHECK(stadium.extent().x > 100.0f * pot.extent().x);
    CHECK(stadium.min.y == Approx(0.0f).margin(1e-6));
    // The camera looks at the teapot from close by.
    CHECK(pot.contains(s.camera.target));
    CHECK(glm::length(s.camera.eye - s.camera.target) < 4.0f * glm::length(pot.extent()));
    // More segments, more stadium triangles; the same arguments, the same scene.
    CHECK(teapot_in_stadium(4, 64).mesh.triangle_count() > s.mesh.triangle_count());
    CHECK(teapot_in_stadium(4, 32).mesh.positions == s.mesh.positions);
}

TEST_CASE("procedural: tessellated sphere counts, radius and outward winding", "[common][procedural]") {
    for (const auto& [stacks, slices] : {std::pair{2, 3}, std::pair{8, 16}, std::pair{32, 64}}) {
        const triangle_mesh m = tessellated_sphere(stacks, slices);
        CHECK(m.triangle_count() == std::size_t(2 * slices * (stacks - 1)));
        CHECK(indices_in_range(m));
        for (const vec3& p : m.positions) CHECK(glm::length(p) == Approx(1.0f).epsilon(1e-5));
        for (std::size_t i = 0; i < m.triangle_count(); ++i) {
            const auto t = m.triangle(i);
            REQUIRE(glm::dot(normal_of(t), centroid_of(t)) > 0.0f);
        }
    }
    REQUIRE_THROWS_AS(tessellated_sphere(1, 8), std::invalid_argument);
    REQUIRE_THROWS_AS(tessellated_sphere(8, 2), std::invalid_argument);
}

TEST_CASE("procedural: random and clustered soups are deterministic and stay in the unit cube", "[common][procedural]") {
    const aabb unit{vec3(0), vec3(1)};
    const triangle_mesh a = random_soup(1000, 42), b = random_soup(1000, 42), c = random_soup(1000, 43);
    CHECK(a.triangle_count() == 1000);
    CHECK(a.positions == b.positions);
    CHECK(a.indices == b.indices);
    CHECK(a.positions != c.positions);
    CHECK(unit.contains(a.bounds().min));
    CHECK(unit.contains(a.bounds().max));
    CHECK(a.bounds().extent().x > 0.9f);  // spread over the whole cube
    float longest = 0.0f;
    for (std::size_t i = 0; i < a.triangle_count(); ++i) {
        const auto t = a.triangle(i);
        longest = std::max({longest, glm::length(t[1] - t[0]), glm::length(t[2] - t[1]), glm::length(t[0] - t[2])});
    }
    CHECK(longest <= 0.05f * std::sqrt(3.0f) + 1e-6f);
    CHECK(random_soup(0, 1).triangle_count() == 0);

    const triangle_mesh k = clustered_soup(2000, 7, 4), l = clustered_soup(2000, 7, 4), o = clustered_soup(2000, 8, 4);
    CHECK(k.triangle_count() == 2000);
    CHECK(k.positions == l.positions);
    CHECK(k.positions != o.positions);
    CHECK(unit.contains(k.bounds().min));
    CHECK(unit.contains(k.bounds().max));
    // Clustered: the triangles' centres spread far less than uniform ones (standard deviation 0.29 per axis)
    // about their nearest neighbours; measured as the share of the unit cube's 10^3 cells that they touch.
    const auto cells_touched = [](const triangle_mesh& m) {
        std::set<int> cells;
        for (std::size_t i = 0; i < m.triangle_count(); ++i) {
            const glm::ivec3 c = glm::clamp(glm::ivec3(centroid_of(m.triangle(i)) * 10.0f), glm::ivec3(0), glm::ivec3(9));
            cells.insert(c.x + 10 * c.y + 100 * c.z);
        }
        return cells.size();
    };
    CHECK(cells_touched(k) < cells_touched(random_soup(2000, 7)) / 3);
    REQUIRE_THROWS_AS(clustered_soup(10, 1, 0), std::invalid_argument);
}

TEST_CASE("procedural: builtin scene names round-trip, unknown names list the valid ones", "[common][procedural]") {
    const auto names = builtin_scene_names();
    CHECK(names == std::vector<std::string>{"cornell", "teapot", "teapot_stadium", "sphere", "soup", "clustered_soup",
                                             "teapot_field"});
    for (const std::string& name : names) {
        const scene s = builtin_scene(name);
        CHECK(s.name == name);
        CHECK(s.mesh.triangle_count() > 0);
        CHECK(indices_in_range(s.mesh));
        CHECK_FALSE(s.materials.empty());
        CHECK_FALSE(s.lights.empty());
        CHECK_NOTHROW(camera(s.camera, 32, 32));
        for (std::size_t i = 0; i < s.triangle_materials.size(); ++i) REQUIRE(s.triangle_materials[i] < s.materials.size());
        CHECK(load_scene_spec("builtin:" + name).mesh.positions == s.mesh.positions);
    }
    REQUIRE_THROWS_WITH(builtin_scene("bunny"), Contains("bunny") && Contains("cornell") && Contains("clustered_soup"));
    const scene m = mesh_scene("ball", tessellated_sphere(4, 8));
    CHECK(m.name == "ball");
    CHECK(describe(m) == "ball: 48 triangles, 26 vertices");
}
