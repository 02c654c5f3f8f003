// Instanced scenes (instancing.hpp): transforms composed in order and inverted; flattened ids; the scene
// file read, and refused with the file, the line and the reason for each malformed line.
#include "strahl/instancing.hpp"
#include "strahl/procedural.hpp"
#include "test_support.hpp"
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace strahl;
namespace fs = std::filesystem;

namespace {
// ctest runs each test case as its own process, in parallel: one folder per process, so that two cases
// never write the same bad.scene at once.
struct process_dir {
    fs::path path = test::scratch_dir("instancing_" + std::to_string(::getpid()));
    ~process_dir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};
fs::path write_file(const std::string& name, const std::string& text) {
    static const process_dir scratch;
    const fs::path& dir = scratch.path;
    std::ofstream(dir / name) << text;
    return dir / name;
}
fs::path tiny_obj() {
    return write_file("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n");
}
std::string error_of(const std::string& text) {
    tiny_obj();
    try {
        load_instanced(write_file("bad.scene", text));
    } catch (const load_error& e) {
        return e.what();
    }
    return "no error";
}
}  // namespace

TEST_CASE("instancing: transforms compose right to left, and invert", "[common][instancing]") {
    const affine a = affine::translate({1, 2, 3}) * affine::scale(vec3(2.0f));
    CHECK(a.point(vec3(1, 1, 1)) == vec3(3, 4, 5));  // scaled first, then moved
    CHECK(a.vector(vec3(1, 1, 1)) == vec3(2, 2, 2));
    const affine r = affine::rotate(1, 90.0f);
    CHECK(r.point(vec3(0, 0, 1)).x == Approx(1.0f));  // about y: z turns to x
    const affine m = affine::translate({5, -1, 2}) * affine::rotate(0, 30.0f) * affine::scale({1, 3, 0.5f});
    const affine back = *inverse(m) * m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) CHECK(back.m[i][j] == Approx(affine{}.m[i][j]).margin(1e-6));
    CHECK_FALSE(inverse(affine::scale({1, 0, 1})));
    affine nan;
    nan.m[1][3] = std::numeric_limits<float>::quiet_NaN();
    CHECK_FALSE(inverse(nan));
    CHECK(affine{}.is_identity());
    CHECK_FALSE(a.is_identity());
}

TEST_CASE("instancing: flattened ids follow the instances in order", "[common][instancing]") {
    instanced_meshes inst = make_field(teapot_mesh(2), "teapot", 2, 3, 1.5f);
    REQUIRE(inst.instances.size() == 6);
    const std::size_t n = inst.meshes[0].triangle_count();
    CHECK(inst.triangle_count() == 6 * n);
    CHECK(inst.first_ids() == std::vector<std::uint32_t>{0, std::uint32_t(n), std::uint32_t(2 * n), std::uint32_t(3 * n),
                                                         std::uint32_t(4 * n), std::uint32_t(5 * n)});
    const triangle_mesh flat = inst.flatten();
    REQUIRE(flat.triangle_count() == 6 * n);
    const auto t = flat.triangle(4 * n + 7), o = inst.meshes[0].triangle(7);
    for (int k = 0; k < 3; ++k) CHECK(t[k] == inst.instances[4].to_world.point(o[k]));
    const aabb all = inst.bounds(), tight = flat.bounds();
    const float slack = 1e-5f * glm::length(all.extent());
    CHECK(glm::all(glm::lessThanEqual(all.min, tight.min + slack)));
    CHECK(glm::all(glm::greaterThanEqual(all.max, tight.max - slack)));
    CHECK(glm::length(all.extent() - tight.extent()) < 0.5f * glm::length(tight.extent()));
    CHECK(inst.flattened_bytes() > 5 * inst.memory_bytes());
}

TEST_CASE("instancing: a scene file with meshes, instances, a field and a camera", "[common][instancing]") {
    tiny_obj();
    const fs::path f = write_file("ok.scene",
                                  "# two meshes\nmesh tri tri.obj\nmesh again tri.obj  # the same file\n"
                                  "instance tri\ninstance again translate 5 0 0 scale 2 rotate y 90\n"
                                  "field tri 3 2 4 4 7 scale 0.5 0.5 0.5\ncamera 0 5 20 0 0 0 35\n");
    const scene s = load_scene(f);
    REQUIRE(s.instances);
    CHECK(s.instances->meshes.size() == 2);
    CHECK(s.instances->instances.size() == 8);
    CHECK(s.mesh.triangle_count() == 16);
    CHECK(s.camera.vfov_degrees == 35.0f);
    CHECK(s.camera.eye == vec3(0, 5, 20));
    // "translate 5 0 0 scale 2 rotate y 90": moved first, then scaled, then turned.
    const vec3 p = s.instances->instances[1].to_world.point(vec3(0));
    CHECK(p.x == Approx(0.0f).margin(1e-5));
    CHECK(p.z == Approx(-10.0f));
    CHECK(describe(s).find("8 instances of 2 meshes") != std::string::npos);
}

TEST_CASE("instancing: malformed scene files name the line and what is wrong", "[common][instancing]") {
    CHECK_THAT(error_of("mesh tri tri.obj\nfrob tri\n"), Catch::Contains(":2: unknown keyword 'frob'"));
    CHECK_THAT(error_of("instance tri\n"), Catch::Contains("no mesh named 'tri'"));
    CHECK_THAT(error_of("mesh tri tri.obj\nmesh tri tri.obj\n"), Catch::Contains("named twice"));
    CHECK_THAT(error_of("mesh tri tri.obj\ninstance tri translate 1 x 3\n"), Catch::Contains("'x' is not a number"));
    CHECK_THAT(error_of("mesh tri tri.obj\ninstance tri translate 1 nan 3\n"), Catch::Contains("out of range"));
    CHECK_THAT(error_of("mesh tri tri.obj\ninstance tri translate 1 2\n"), Catch::Contains("needs"));
    CHECK_THAT(error_of("mesh tri tri.obj\ninstance tri scale 0\n"), Catch::Contains("singular"));
    CHECK_THAT(error_of("mesh tri tri.obj\ninstance tri rotate w 9\n"), Catch::Contains("axis must be x, y or z"));
    CHECK_THAT(error_of("mesh tri tri.obj\ninstance tri shear 2\n"), Catch::Contains("unknown transform 'shear'"));
    CHECK_THAT(error_of("mesh tri tri.obj\n"), Catch::Contains("no instances"));
    CHECK_THAT(error_of("mesh tri missing.obj\n"), Catch::Contains("missing.obj"));
    CHECK_THAT(error_of("mesh tri tri.obj\nfield tri 0 3 1 1\n"), Catch::Contains("NX must be a whole number"));
    CHECK_THAT(error_of("mesh tri tri.obj\nfield tri 2.5 3 1 1\n"), Catch::Contains("whole number"));
    CHECK_THAT(error_of("mesh tri tri.obj\ninstance tri\ncamera 0 0 1 0 0 0 200\n"), Catch::Contains("field of view"));
    CHECK_THAT(error_of("mesh tri tri.obj\ninstance tri\ncamera 1 2 3 1 2 3\n"), Catch::Contains("straight up or down"));
    CHECK_THAT(error_of("mesh tri tri.obj\ninstance tri\ncamera 0 9 0 0 0 0\n"), Catch::Contains("straight up or down"));
    CHECK_THAT(error_of("mesh tri tri.obj\ninstance tri translate 1e11 0 0 scale 100\n"), Catch::Contains("beyond"));
    // Counts refused before the instances are made: 2^20 + 1 instances; 2^32 triangles.
    CHECK_THAT(error_of("mesh tri tri.obj\ninstance tri\nfield tri 1024 1024 1 1\n"),
               Catch::Contains(":3: more than 1048576 instances"));
    std::string strip = "v 0 0 0\nv 0 1 0\n";  // 4,097 triangles: 2^20 instances of them pass 2^32
    for (int k = 1; k <= 2049; ++k) strip += "v " + std::to_string(k) + " 0 0\nv " + std::to_string(k) + " 1 0\n";
    for (int k = 0; k < 4097; ++k) strip += "f " + std::to_string(k + 1) + " " + std::to_string(k + 2) + " " + std::to_string(k + 3) + "\n";
    write_file("strip.obj", strip);
    CHECK_THAT(error_of("mesh s strip.obj\nfield s 1024 1024 1 1\n"), Catch::Contains("more than 32-bit primitive ids"));
    CHECK_THAT(error_of("mesh tri tri.obj\nfield tri 1025 1 1 1\n"), Catch::Contains("NX must be a whole number in [1, 1024]"));
    CHECK_THROWS_AS(load_instanced("/nonexistent/x.scene"), load_error);
}

TEST_CASE("instancing: an instance placed below the course's smallest extent is refused, naming it", "[common][instancing]") {
    // tri.obj is 1 across. As a mesh file below min_extent is refused (scene.hpp), so is an instance that a
    // scale makes smaller: the flattened copy, which every structure but chapter 10's traces, would lose its
    // hits. At min_extent it loads; the largest side counts (a flattened instance is fine).
    REQUIRE(min_extent == 1e-8f);
    CHECK(error_of("mesh tri tri.obj\ninstance tri scale 1e-8\n") == "no error");
    CHECK(error_of("mesh tri tri.obj\ninstance tri scale 1 1 1e-30\n") == "no error");
    CHECK(error_of("mesh tri tri.obj\ninstance tri translate 3 0 0 scale 1e-8 rotate y 45\n") == "no error");
    CHECK_THAT(error_of("mesh tri tri.obj\ninstance tri\ninstance tri scale 1e-30\n"),
               Catch::Contains("bad.scene:3: mesh 'tri' as this line places it is 1e-30 across (the largest side of its "
                               "bounding box), below 1e-8, the smallest extent the course accepts") &&
                   Catch::Contains("extents from 1e-8 to coordinates of +-1e12") && Catch::Contains("scale the scene up"));
    CHECK_THAT(error_of("mesh tri tri.obj\ninstance tri scale 9e-9\n"), Catch::Contains(":2: mesh 'tri'") &&
                                                                          Catch::Contains("is 9e-09 across"));
    CHECK_THAT(error_of("mesh tri tri.obj\nfield tri 2 2 1 1 scale 1e-12\n"), Catch::Contains(":2: mesh 'tri'") &&
                                                                                Catch::Contains("below 1e-8"));
    // A translation does not make an instance larger: every instance is checked, not the world box.
    CHECK_THAT(error_of("mesh tri tri.obj\ninstance tri\ninstance tri translate 5 0 0 scale 1e-20\n"),
               Catch::Contains(":3: mesh 'tri'") && Catch::Contains("below 1e-8"));
    // load_scene (strahl-trace, the race, chapter 10's program) refuses it the same way.
    CHECK_THROWS_WITH(load_scene(write_file("tiny.scene", "mesh tri tri.obj\ninstance tri scale 1e-30\n")),
                      Catch::Contains("tiny.scene:2:") && Catch::Contains("below 1e-8"));
}

TEST_CASE("instancing: a scene too large to flatten is refused with its size", "[common][instancing]") {
    instanced_meshes inst = make_field(teapot_mesh(8), "teapot", 128, 129, 1.5f);  // 67.6 million triangles
    REQUIRE(inst.triangle_count() > max_flattened_triangles);
    CHECK_THROWS_WITH(instanced_scene(std::move(inst), "big"), Catch::Contains("limited to"));
}
