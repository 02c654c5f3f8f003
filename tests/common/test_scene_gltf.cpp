// Unit tests of the scene loader on glTF and GLB files (common/src/scene_gltf.cpp checks them before assimp
// reads them): out-of-range indices, node trees too deep or cyclic, JSON too deep or malformed, small node
// transforms, GLB lengths beyond the file.
// (Among them, hostile files of issue #20: each was loaded silently wrong, crashed or ran away before.)
#include <catch2/catch.hpp>
#include "strahl/scene.hpp"
#include "scene_test_files.hpp"
#include "test_support.hpp"
#include <chrono>

using namespace strahl;
using namespace strahl::test;
using Catch::Matchers::Contains;

TEST_CASE("scene loader: a glTF face with an out-of-range vertex index is refused, not dropped", "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_gltf_index");
    CHECK(load_mesh(write_file(dir, "good.gltf", gltf_text(unit_quad, {0, 1, 2, 0, 2, 3}))).triangle_count() == 2);
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "bad_index.gltf", gltf_text(unit_quad, {0, 1, 2, 0, 2, 7}))),
                        Contains("bad_index.gltf") && Contains("out of range"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "bad_index.glb", glb(unit_quad, {0, 1, 2, 0, 2, 7}))),
                        Contains("bad_index.glb") && Contains("out of range"));
}

TEST_CASE("scene loader: deeply nested and cyclic glTF node trees are refused before assimp reads them",
          "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_gltf_depth");
    const auto chain = [](int depth) {
        std::string nodes = "[";
        for (int i = 0; i < depth - 1; ++i) nodes += R"({"children":[)" + std::to_string(i + 1) + "]},";
        return nodes + R"({"mesh":0}])";
    };
    CHECK(load_mesh(write_file(dir, "nested_100.gltf", gltf_text(unit_quad, {0, 1, 2, 0, 2, 3}, chain(100))))
              .triangle_count() == 2);
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "nested.gltf", gltf_text(unit_quad, {0, 1, 2, 0, 2, 3}, chain(20000)))),
                        Contains("nested.gltf") && Contains("20,000 levels"));
    REQUIRE_THROWS_WITH(
        load_mesh(write_file(dir, "cycle.gltf", gltf_text(unit_quad, {0, 1, 2}, R"([{"children":[1]},{"children":[0],"mesh":0}])"))),
        Contains("cycle.gltf") && Contains("cycle"));
    // JSON nested far deeper than any glTF needs: the check's own JSON reader stops at 1,000 levels.
    const std::string deep_json = gltf_text(unit_quad, {0, 1, 2}).insert(1, R"("extras":)" + std::string(100000, '[') +
                                                                            std::string(100000, ']') + ",");
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "deep_json.gltf", deep_json)),
                        Contains("deep_json.gltf") && Contains("nested"));
}

TEST_CASE("scene loader: a small node translation is applied, not taken for the identity", "[common][scene]") {
    // aiMatrix4x4::IsIdentity allows entries 0.01 off: a translation of 0.005 used to be dropped.
    const auto dir = test::scratch_dir("scene_loader_small_transform");
    const triangle_mesh m = load_mesh(write_file(dir, "nudged.gltf",
        gltf_text(unit_quad, {0, 1, 2, 0, 2, 3}, R"([{"mesh":0,"translation":[0,0,0.005]}])")));
    CHECK(m.bounds().min == vec3(0, 0, 0.005f));
    CHECK(m.bounds().max == vec3(1, 1, 0.005f));
}

TEST_CASE("scene loader: a GLB whose lengths exceed the file is refused at once", "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_glb");
    const std::string good = glb(unit_quad, {0, 1, 2, 0, 2, 3});
    CHECK(load_mesh(write_file(dir, "good.glb", good)).triangle_count() == 2);
    std::string huge_chunk = good;
    huge_chunk.replace(12, 4, std::string(4, '\xFF'));  // the JSON chunk's length: 0xFFFFFFFF
    const auto start = std::chrono::steady_clock::now();
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "huge_chunk.glb", huge_chunk)),
                        Contains("huge_chunk.glb") && Contains("JSON chunk"));
    CHECK(seconds_since(start) < 1.0);
    std::string long_header = good;
    long_header.replace(8, 4, std::string(4, '\x7F'));  // the header's total length
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "long_header.glb", long_header)), Contains("bytes"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "short.glb", good.substr(0, 10))), Contains("short.glb"));
}

TEST_CASE("scene loader: glTF JSON is read to 1,000 levels, malformed JSON is refused naming the byte",
          "[common][scene]") {
    // The checks read the JSON with nlohmann-json's SAX parser, which stops at 1,000 levels of nesting (the
    // root at level 0): an "extras" of 1,000 nested arrays loads, one of 1,001 is refused.
    const auto dir = test::scratch_dir("scene_loader_gltf_json");
    const auto nested = [](std::size_t levels) {
        return gltf_text(unit_quad, {0, 1, 2}).insert(1, R"("extras":)" + std::string(levels, '[') +
                                                             std::string(levels, ']') + ",");
    };
    CHECK(load_mesh(write_file(dir, "levels_1000.gltf", nested(1000))).triangle_count() == 1);
    CHECK_THROWS_WITH(load_mesh(write_file(dir, "levels_1001.gltf", nested(1001))),
                      Contains("levels_1001.gltf: its JSON is nested more than 1,000 levels deep"));
    // Malformed JSON: the byte where reading stopped (counted from 1), its line and column, and what is wrong.
    CHECK_THROWS_WITH(load_mesh(write_file(dir, "comma.gltf", "{\"asset\":1,\n}")),
                      Contains("comma.gltf: malformed glTF JSON at byte 13, line 2, column 1: ") &&
                          Contains("expected string literal"));
    CHECK_THROWS_WITH(load_mesh(write_file(dir, "after.gltf", gltf_text(unit_quad, {0, 1, 2}) + " x")),
                      Contains("after.gltf: malformed glTF JSON at byte ") && Contains("expected end of input"));
    CHECK_THROWS_WITH(load_mesh(write_file(dir, "bom.gltf", "\xEF\xBB\xBF" + gltf_text(unit_quad, {0, 1, 2}))),
                      Contains("bom.gltf: malformed glTF JSON at byte 1") && Contains("byte order mark"));
    // A name in Latin-1 (not UTF-8) is no reason to refuse a file assimp reads.
    const std::string latin1 = gltf_text(unit_quad, {0, 1, 2}, "[{\"mesh\":0,\"name\":\"caf\xE9\"}]");
    CHECK(load_mesh(write_file(dir, "latin1.gltf", latin1)).triangle_count() == 1);
}
