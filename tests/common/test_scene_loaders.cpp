// Unit tests of the scene loader across formats (common/src/scene.cpp and the format files beside it): the
// shared meshes with their known counts, small valid OBJ/PLY/glTF files written at test time, and every kind
// of bad file that is no one format's, each of which must throw a load_error naming the file and the problem
// (never crash, never return a smaller scene). Each format's own tests: test_scene_ply.cpp,
// test_scene_obj.cpp, test_scene_gltf.cpp; load_scene and the framing: test_scene_framing.cpp.
#include <catch2/catch.hpp>
#include "strahl/scene.hpp"
#include "scene_test_files.hpp"
#include "test_support.hpp"
#include <array>
#include <chrono>
#include <sstream>

using namespace strahl;
using namespace strahl::test;
using Catch::Matchers::Contains;

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

TEST_CASE("scene loader: the course's smallest extent (min_extent): a mesh at it loads, one below is refused",
          "[common][scene]") {
    // Below min_extent the triangle tests' products of three lengths underflow float and hits are lost in
    // silence (chapter 15's scale.csv): refused, naming the extent and the range, as coordinates beyond
    // max_coordinate are. The extent is the largest side of the box: a flat mesh is fine.
    const auto dir = test::scratch_dir("scene_loader_min_extent");
    REQUIRE(min_extent == 1e-8f);
    const triangle_mesh at = load_mesh(write_file(dir, "at.obj", "v 0 0 0\nv 1e-8 0 0\nv 0 1e-8 0\nf 1 2 3\n"));
    CHECK(at.bounds().extent().x == min_extent);
    CHECK(load_mesh(write_file(dir, "flat.obj", "v 0 0 0\nv 1 0 1e-30\nv 0 1e-30 0\nf 1 2 3\n")).triangle_count() == 1);
    const std::string below = "v 0 0 0\nv 9.9e-9 0 0\nv 0 9.9e-9 0\nf 1 2 3\n";
    CHECK_THROWS_WITH(load_mesh(write_file(dir, "below.obj", below)),
                      Contains("below.obj: is 9.9e-09 across (the largest side of its bounding box)") &&
                          Contains("below 1e-8, the smallest extent the course accepts") &&
                          Contains("extents from 1e-8 to coordinates of +-1e12") && Contains("underflow") &&
                          Contains("scale the scene up"));
    CHECK_THROWS_WITH(load_mesh(write_file(dir, "tiny.ply",
                          "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                          "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n1e-30 0 0\n0 1e-30 0\n3 0 1 2\n")),
                      Contains("tiny.ply: is 1e-30 across") && Contains("below 1e-8"));
    CHECK_THROWS_WITH(load_mesh(write_file(dir, "tiny.gltf", gltf_text({vec3(0), vec3(1e-12f, 0, 0), vec3(0, 1e-12f, 0)},
                                                                       {0, 1, 2}))),
                      Contains("tiny.gltf: is 1e-12 across") && Contains("below 1e-8"));
    // A mesh that is one point: 0 across.
    CHECK_THROWS_WITH(load_mesh(write_file(dir, "point.obj", "v 1 2 3\nv 1 2 3\nv 1 2 3\nf 1 2 3\n")),
                      Contains("point.obj: is 0 across") && Contains("below 1e-8"));
    // load_scene refuses it too (strahl-trace and the race load through it).
    CHECK_THROWS_WITH(load_scene(dir / "below.obj"), Contains("below 1e-8"));
}

TEST_CASE("scene loader: distinct vertices are never merged, however close", "[common][scene]") {
    // A quad 1e-22 across beside a unit triangle (a mesh 1e-22 across is refused: below min_extent).
    const auto dir = test::scratch_dir("scene_loader_no_merge");
    const float s = 1e-22f;
    std::ostringstream log;
    const triangle_mesh obj = load_mesh(write_file(dir, "tiny.obj", "v 0 0 0\nv 1e-22 0 0\nv 1e-22 1e-22 0\nv 0 1e-22 0\n"
                                                                     "v 1 0 0\nv 0 1 0\nf 1 2 3 4\nf 1 5 6\n"), &log);
    CHECK(log.str() == "tiny.obj: 3 triangles, 6 vertices\n");
    REQUIRE(obj.triangle_count() == 3);
    CHECK(obj.triangle(0) == std::array<vec3, 3>{vec3(0, 0, 0), vec3(s, 0, 0), vec3(s, s, 0)});
    const triangle_mesh ply = load_mesh(write_file(dir, "tiny.ply",
        "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 3\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1e-22 0 0\n1e-22 1e-22 0\n0 1e-22 0\n1 1 1\n3 0 1 2\n3 0 2 3\n3 0 1 4\n"));
    CHECK(ply.positions.size() == 5);
    const triangle_mesh gltf = load_mesh(write_file(dir, "tiny.gltf",
        gltf_text({vec3(0), vec3(s, 0, 0), vec3(s, s, 0), vec3(0, s, 0), vec3(1)}, {0, 1, 2, 0, 2, 3, 0, 1, 4})));
    CHECK(gltf.positions.size() == 5);
    // Bit-identical corners are still welded: two faces sharing an edge give 4 vertices, not 6.
    CHECK(load_mesh(write_file(dir, "shared.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 1 0 0\nf 1 2 3\nf 1 3 4\n"))
              .positions.size() == 4);
}

TEST_CASE("scene loader: a mesh below float resolution at its distance from the origin is loaded with a warning",
          "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_float_resolution");
    // An octahedron of radius 0.6 centred at (1e7, 1e7, 1e7), where floats are 1 apart: its corners round to
    // the neighbouring floats, its shape is lost.
    const auto octahedron = [](const char* plus, const char* minus) {
        std::string text;
        for (int axis = 0; axis < 3; ++axis)
            for (const char* offset : {plus, minus}) {
                text += "v";
                for (int k = 0; k < 3; ++k) text += std::string(" ") + (k == axis ? offset : "10000000");
                text += "\n";
            }
        return text + "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";
    };
    std::ostringstream log;
    const scene s = load_scene(write_file(dir, "far.obj", octahedron("10000000.6", "9999999.4")), &log);
    CHECK(s.mesh.triangle_count() == 8);
    CHECK_THAT(log.str(), Contains("warning") && Contains("far.obj") && Contains("float"));
    // Of radius 1e-3 every corner rounds to one point: 0 across, below min_extent, refused, saying where.
    CHECK_THROWS_WITH(load_scene(write_file(dir, "point.obj", octahedron("10000000.001", "9999999.999"))),
                      Contains("point.obj: is 0 across") && Contains("below 1e-8") &&
                          Contains("lies 1e+07 from the origin") && Contains("move it nearer the origin"));
    // A mesh 2,000 across at the same distance is well within float resolution: no warning.
    std::ostringstream quiet;
    load_scene(write_file(dir, "near.obj", "v 10001000 0 0\nv 9999000 0 0\nv 10000000 1000 0\nv 10000000 0 1000\n"
                                           "f 1 3 4\nf 3 2 4\n"), &quiet);
    CHECK(quiet.str() == "near.obj: 2 triangles, 4 vertices\n");
}
