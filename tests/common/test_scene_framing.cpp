// Unit tests of load_scene, load_scene_spec and the framing of a loaded mesh (common/src/scene.cpp): the
// camera sees the whole box, the light gives an irradiance of pi at its centre, Sponza gets its inside view.
#include <catch2/catch.hpp>
#include "strahl/procedural.hpp"
#include "strahl/scene.hpp"
#include "scene_test_files.hpp"
#include "test_support.hpp"
#include <algorithm>
#include <cmath>

using namespace strahl;
using namespace strahl::test;
using Catch::Matchers::Contains;

namespace {

// The largest angle (degrees) between the camera's view direction and a box corner.
float widest_corner_angle(const camera_desc& cam, const aabb& box) {
    const vec3 forward = glm::normalize(cam.target - cam.eye);
    float widest = 0.0f;
    for (int c = 0; c < 8; ++c) {
        const vec3 corner((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                          (c & 4) ? box.max.z : box.min.z);
        const float cosine = glm::dot(forward, glm::normalize(corner - cam.eye));
        widest = std::max(widest, glm::degrees(std::acos(std::min(1.0f, cosine))));
    }
    return widest;
}

}  // namespace

TEST_CASE("scene loader: load_scene frames the mesh, load_scene_spec reads builtin: names", "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_scene");
    const auto path = write_file(dir, "tri.obj", "v 0 0 0\nv 4 0 0\nv 0 2 -1\nf 1 2 3\n");
    std::ostringstream log;
    const scene s = load_scene(path, &log);
    CHECK(s.name == "tri.obj");
    CHECK(describe(s) == "tri.obj: 1 triangles, 3 vertices");
    CHECK(log.str() == describe(s) + "\n");
    REQUIRE(s.materials.size() == 1);
    CHECK(s.materials[0].kind == material_kind::diffuse);
    REQUIRE(s.lights.size() == 1);
    const aabb box = s.bounds();
    CHECK(s.camera.eye.z > box.max.z);
    CHECK(s.camera.vfov_degrees == 40.0f);
    CHECK(widest_corner_angle(s.camera, box) < 0.95f * 20.0f);
    // The light: near the camera, irradiance about pi at the box centre.
    const point_light& l = s.lights[0];
    CHECK(glm::length(l.position - s.camera.eye) < glm::length(s.camera.eye - box.centroid()));
    const vec3 to_centre = l.position - box.centroid();
    CHECK(l.intensity.x / glm::dot(to_centre, to_centre) == Approx(pi).epsilon(1e-4));

    CHECK(load_scene_spec(path.string()).mesh.triangle_count() == 1);
    CHECK(load_scene_spec("builtin:cornell").name == "cornell");
    REQUIRE_THROWS_AS(load_scene_spec("builtin:no_such_scene"), std::invalid_argument);
    REQUIRE_THROWS_AS(load_scene_spec((dir / "absent.ply").string()), load_error);
}

TEST_CASE("scene loader: a mesh named sponza.obj gets its inside view, placed in its bounding box", "[common][scene]") {
    // Two tetrahedra' worth of box: [0, 10] x [0, 5] x [0, 2]. The same file under another name gets the front view.
    const auto dir = test::scratch_dir("scene_loader_view");
    const std::string text = "v 0 0 0\nv 10 0 0\nv 0 5 0\nv 0 0 2\nf 1 2 3\nf 1 2 4\n";
    const scene front = load_scene(write_file(dir, "box.obj", text));
    const scene inside = load_scene(write_file(dir, "Sponza.OBJ", text));
    const aabb box = inside.bounds();
    CHECK(front.camera.eye.z > box.max.z);
    CHECK(box.contains(inside.camera.eye));
    CHECK(inside.camera.eye.x == Approx(7.5f));  // three quarters along x, looking towards -x
    CHECK(inside.camera.target.x < inside.camera.eye.x);
    CHECK(inside.camera.vfov_degrees == 70.0f);
    REQUIRE(inside.lights.size() == 1);
    CHECK(box.contains(inside.lights[0].position));
    const vec3 to_centre = inside.lights[0].position - box.centroid();
    CHECK(inside.lights[0].intensity.x / glm::dot(to_centre, to_centre) == Approx(pi).epsilon(1e-4));
    CHECK(inside.mesh.triangle_count() == front.mesh.triangle_count());
}

TEST_CASE("scene loader: frame_camera sees every corner of flat, long and empty boxes", "[common][scene]") {
    const aabb boxes[] = {aabb{vec3(-1), vec3(1)}, aabb{vec3(0, 0, 0), vec3(100, 0.01f, 0.01f)},
                          aabb{vec3(-5, -5, 0), vec3(5, 5, 0)}, aabb{vec3(3, 4, 5), vec3(3, 4, 5)}};
    for (const aabb& box : boxes) {
        for (const float fov : {20.0f, 40.0f, 90.0f}) {
            const camera_desc cam = frame_camera(box, fov);
            CHECK(cam.vfov_degrees == fov);
            CHECK(cam.target == box.centroid());
            CHECK(cam.eye.z > box.max.z);
            CHECK(widest_corner_angle(cam, box) < 0.5f * fov);
            CHECK_NOTHROW(camera(cam, 64, 48));
        }
    }
    const camera_desc empty = frame_camera(aabb::empty());
    CHECK(is_finite(empty.eye));
    CHECK_NOTHROW(camera(empty, 64, 64));
}
