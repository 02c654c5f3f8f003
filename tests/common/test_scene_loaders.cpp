// Unit tests of the scene loader (common/src/scene.cpp): the shared meshes with their known counts, small
// valid OBJ/PLY/glTF files written at test time, and every kind of bad file, each of which must throw a
// load_error naming the file and the problem (never crash, never return a smaller scene).
#include <catch2/catch.hpp>
#include "strahl/procedural.hpp"
#include "strahl/scene.hpp"
#include "test_support.hpp"
#include <chrono>
#include <fstream>
#include <sstream>

using namespace strahl;
using Catch::Matchers::Contains;

namespace {

std::filesystem::path write_file(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
    const std::filesystem::path p = dir / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
}

const std::string ply_header_3v1f =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

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

TEST_CASE("scene loader: the shared meshes load with their known triangle and vertex counts", "[common][scene]") {
    struct expected { const char* name; std::size_t triangles; const char* line; };
    const expected meshes[] = {
        {"cornell_box.obj", 32, "cornell_box.obj: 32 triangles, 66 vertices"},
        {"teapot.obj", 6320, "teapot.obj: 6,320 triangles, 3,241 vertices"},
        {"bunny.ply", 69451, "bunny.ply: 69,451 triangles, 34,834 vertices"},
        {"armadillo.obj", 86482, "armadillo.obj: 86,482 triangles, 43,243 vertices"},
        {"ogre.obj", 124008, "ogre.obj: 124,008 triangles, 62,185 vertices"},
        {"sponza.obj", 262205, "sponza.obj: 262,205 triangles, 145,185 vertices"},
    };
    for (const expected& e : meshes) {
        const auto path = test::shared_scene(e.name);
        if (path.empty()) { WARN("skipped: ../shared/scenes/" << e.name << " is absent"); continue; }
        std::ostringstream log;
        const auto start = std::chrono::steady_clock::now();
        const triangle_mesh m = load_mesh(path, &log);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        INFO(e.name << " loaded in " << ms << " ms");
        CHECK(m.triangle_count() == e.triangles);
        CHECK(log.str() == std::string(e.line) + "\n");
        CHECK_FALSE(m.bounds().is_empty());
        bool in_range = true, finite = true;
        for (const uvec3& t : m.indices) in_range = in_range && glm::all(glm::lessThan(t, uvec3(m.positions.size())));
        for (const vec3& p : m.positions) finite = finite && is_finite(p);
        CHECK(in_range);
        CHECK(finite);
    }
}

TEST_CASE("scene loader: triangles of a multi-object OBJ come in file order", "[common][scene]") {
    const auto path = test::shared_scene("cornell_box.obj");
    if (path.empty()) { WARN("skipped: ../shared/scenes/cornell_box.obj is absent"); return; }
    // Read the 'v' and 'f' lines (triangles only in this file) and compare face by face.
    std::ifstream in(path);
    std::vector<vec3> v;
    std::vector<std::array<int, 3>> f;
    for (std::string line; std::getline(in, line);) {
        std::istringstream ls(line);
        std::string tag;
        ls >> tag;
        if (tag == "v") { vec3 p; ls >> p.x >> p.y >> p.z; v.push_back(p); }
        if (tag == "f") {
            std::array<int, 3> t{};
            for (int& i : t) { std::string corner; ls >> corner; i = std::stoi(corner) - 1; }
            f.push_back(t);
        }
    }
    const triangle_mesh m = load_mesh(path);
    REQUIRE(m.triangle_count() == f.size());
    for (std::size_t i = 0; i < f.size(); ++i) {
        const auto tri = m.triangle(i);
        for (int k = 0; k < 3; ++k) CHECK(tri[std::size_t(k)] == v[std::size_t(f[i][std::size_t(k)])]);
    }
}

TEST_CASE("scene loader: an OBJ quad becomes two triangles (a b c), (a c d), objects in file order", "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_valid_obj");
    const auto path = write_file(dir, "quad.obj",
                                 "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 5 5 5\n"
                                 "o first\nf 1 2 3 4\no second\nf 5 1 2\n");
    std::ostringstream log;
    const triangle_mesh m = load_mesh(path, &log);
    REQUIRE(m.triangle_count() == 3);
    using tri = std::array<vec3, 3>;
    CHECK(m.triangle(0) == tri{vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0)});
    CHECK(m.triangle(1) == tri{vec3(0, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)});
    CHECK(m.triangle(2) == tri{vec3(5, 5, 5), vec3(0, 0, 0), vec3(1, 0, 0)});
    CHECK(log.str() == "quad.obj: 3 triangles, 7 vertices\n");  // welded within a mesh, not across meshes
}

TEST_CASE("scene loader: a valid ASCII PLY and a glTF with an embedded buffer and a node transform", "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_valid_ply_gltf");
    const auto ply = write_file(dir, "square.ply",
                                "ply\nformat ascii 1.0\ncomment two triangles\nelement vertex 4\nproperty float x\n"
                                "property float y\nproperty float z\nelement face 2\nproperty list uchar int "
                                "vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n");
    const triangle_mesh m = load_mesh(ply);
    REQUIRE(m.triangle_count() == 2);
    CHECK(m.triangle(1) == std::array<vec3, 3>{vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)});

    // A unit quad (4 float positions, 6 ushort indices) in a base64 buffer, translated by (0, 0, 5).
    const auto gltf = write_file(dir, "quad.gltf", R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
"nodes":[{"mesh":0,"translation":[0,0,5]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
"buffers":[{"byteLength":60,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAACAPwAAgD8AAAAAAAAAAAAAgD8AAAAAAAABAAIAAAACAAMA"}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":12}],
"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
{"bufferView":1,"componentType":5123,"count":6,"type":"SCALAR"}]})");
    const triangle_mesh g = load_mesh(gltf);
    REQUIRE(g.triangle_count() == 2);
    CHECK(g.bounds().min == vec3(0, 0, 5));
    CHECK(g.bounds().max == vec3(1, 1, 5));
}

TEST_CASE("scene loader: missing, directory, empty and unreadable files throw load_error", "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_files");
    REQUIRE_THROWS_WITH(load_mesh(dir / "nothing_here.obj"), Contains("nothing_here.obj") && Contains("no such file"));
    std::filesystem::create_directory(dir / "folder.obj");
    REQUIRE_THROWS_WITH(load_mesh(dir / "folder.obj"), Contains("folder.obj") && Contains("directory"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "empty.obj", "")), Contains("empty.obj") && Contains("empty"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "empty.ply", "")), Contains("empty"));
    REQUIRE_THROWS_AS(load_mesh(write_file(dir, "junk.obj", "this is not a mesh\n\x01\x02")), load_error);
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "junk.ply", "not a ply at all\n")), Contains("not a PLY"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\np 3\n")),
                        Contains("no triangles"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "vertices_only.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n")),
                        Contains("no triangles"));
}

TEST_CASE("scene loader: truncated and short PLY files throw load_error", "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_ply");
    // Binary PLY, little endian: 3 vertices (3 floats each), 1 face (uchar count, 3 ints), cut short.
    std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                         "property float y\nproperty float z\nelement face 1\n"
                         "property list uchar int vertex_indices\nend_header\n";
    const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    binary.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
    const int face[3] = {0, 1, 2};
    binary += char(3);
    binary.append(reinterpret_cast<const char*>(face), sizeof face);
    CHECK(load_mesh(write_file(dir, "whole.ply", binary)).triangle_count() == 1);
    // Cut inside the face (assimp 5.2 alone reads past the end here), and inside the vertices.
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "cut_face.ply", binary.substr(0, binary.size() - 4))),
                        Contains("cut_face.ply") && Contains("truncated") && Contains("face"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "cut_vertex.ply", binary.substr(0, binary.size() - 30))),
                        Contains("truncated") && Contains("vertex"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "cut_header.ply", binary.substr(0, 40))), Contains("end_header"));
    // ASCII PLY declaring more vertices, or more faces, than it holds (assimp alone repeats the last face).
    const std::string more_vertices = "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
                                      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "more_vertices.ply", more_vertices)),
                        Contains("more_vertices.ply") && Contains("truncated") && Contains("5 vertex"));
    std::string more_faces = ply_header_3v1f + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    more_faces.replace(more_faces.find("face 1"), 6, "face 4");
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "more_faces.ply", more_faces)),
                        Contains("truncated") && Contains("4 face"));
    // A face with the wrong number of values, and one referring past the last vertex.
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "short_face.ply", ply_header_3v1f + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n")),
                        Contains("face 0"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "index.ply", ply_header_3v1f + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")),
                        Contains("index.ply") && Contains("out of range"));
    // A face with no vertices (assimp 5.2's triangulation aborts on it), and lines that are skipped.
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "no_corners.ply", ply_header_3v1f + "0 0 0\n1 0 0\n0 1 0\n0\n")),
                        Contains("no vertices"));
    std::string with_line = ply_header_3v1f + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n3 0 1 2\n";
    with_line.replace(with_line.find("face 1"), 6, "face 2");
    std::ostringstream log;
    CHECK(load_mesh(write_file(dir, "with_line.ply", with_line), &log).triangle_count() == 1);
    CHECK(log.str() == "with_line.ply: 1 triangles, 3 vertices (1 points and lines skipped)\n");
}

TEST_CASE("scene loader: bad OBJ indices throw load_error", "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_obj_indices");
    const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "zero.obj", v + "f 0 1 2\n")),
                        Contains("zero.obj") && Contains("index"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "negative_first.obj", "f -1 -2 -3\n" + v)),
                        Contains("negative_first.obj") && Contains("out of range"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "negative_far.obj", v + "f -1 -2 -4\n")), Contains("out of range"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "beyond.obj", v + "f 1 2 3\nf 1 2 4\n")),
                        Contains("beyond.obj") && Contains("out of range"));
    // Relative (negative) indices after their vertices are valid OBJ.
    CHECK(load_mesh(write_file(dir, "relative.obj", v + "f -3 -2 -1\n")).triangle_count() == 1);
}

TEST_CASE("scene loader: NaN and Inf coordinates throw load_error", "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_nonfinite");
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n")),
                        Contains("nan.obj") && Contains("NaN"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "inf.obj", "v 0 0 0\nv 0 inf 0\nv 0 1 0\nf 1 2 3\n")),
                        Contains("Inf"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "overflow.obj", "v 0 0 0\nv 0 0 1e39\nv 0 1 0\nf 1 2 3\n")),
                        Contains("non-finite"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "nan.ply", ply_header_3v1f + "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n")),
                        Contains("non-finite"));
    // An unreferenced non-finite vertex is not part of the mesh.
    CHECK(load_mesh(write_file(dir, "unused_nan.obj", "v nan 0 0\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 2 3 4\n"))
              .triangle_count() == 1);
}

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
