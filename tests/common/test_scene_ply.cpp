// Unit tests of the scene loader's PLY reader (common/src/scene_ply.cpp): truncated and short files, triangle
// strips, vertices without x, y or z. Each bad file must throw a load_error naming the file and the problem.
// (Among them, hostile files of issue #20: each was loaded silently wrong or crashed before.)
#include <catch2/catch.hpp>
#include "strahl/scene.hpp"
#include "scene_test_files.hpp"
#include "test_support.hpp"
#include <cstring>
#include <sstream>

using namespace strahl;
using namespace strahl::test;
using Catch::Matchers::Contains;

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

TEST_CASE("scene loader: PLY triangle strips are read, restarting at -1 with alternating winding", "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_tristrips");
    // Two strips in one list: 0 1 2 3 and, after the restart, 2 3 4 5. Every triangle faces -z.
    const std::string header = "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
                               "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
                               "end_header\n";
    const std::string points = "0 0 0\n0 1 0\n1 0 0\n1 1 0\n2 0 0\n2 1 0\n";
    std::ostringstream log;
    const triangle_mesh m = load_mesh(write_file(dir, "strips.ply", header + points + "9 0 1 2 3 -1 2 3 4 5\n"), &log);
    REQUIRE(m.triangle_count() == 4);
    const vec3 p[6] = {vec3(0, 0, 0), vec3(0, 1, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(2, 0, 0), vec3(2, 1, 0)};
    using tri = std::array<vec3, 3>;
    CHECK(m.triangle(0) == tri{p[0], p[1], p[2]});
    CHECK(m.triangle(1) == tri{p[2], p[1], p[3]});  // odd triangles swap their first two corners
    CHECK(m.triangle(2) == tri{p[2], p[3], p[4]});  // the restart begins a fresh strip: even again
    CHECK(m.triangle(3) == tri{p[4], p[3], p[5]});
    for (std::size_t i = 0; i < m.triangle_count(); ++i) {
        const tri t = m.triangle(i);
        CHECK(glm::cross(t[1] - t[0], t[2] - t[0]).z < 0.0f);
    }
    CHECK(log.str() == "strips.ply: 4 triangles, 6 vertices\n");

    // The same strips in a binary file, big endian, with a uchar-counted list.
    std::string binary = "ply\nformat binary_big_endian 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
                         "property float z\nelement tristrips 1\nproperty list uchar int vertex_indices\nend_header\n";
    const auto big_endian = [&](std::uint32_t bits) {
        for (int shift = 24; shift >= 0; shift -= 8) binary += char((bits >> shift) & 0xFF);
    };
    for (const vec3& q : p)
        for (int k = 0; k < 3; ++k) { std::uint32_t bits; std::memcpy(&bits, &q[k], 4); big_endian(bits); }
    binary += char(9);
    for (const int i : {0, 1, 2, 3, -1, 2, 3, 4, 5}) big_endian(std::uint32_t(i));
    const triangle_mesh b = load_mesh(write_file(dir, "strips_binary.ply", binary));
    REQUIRE(b.triangle_count() == 4);
    for (std::size_t i = 0; i < 4; ++i) CHECK(b.triangle(i) == m.triangle(i));

    // A strip index past the last vertex is refused like a face's.
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "strip_index.ply", header + points + "4 0 1 2 6\n")),
                        Contains("strip_index.ply") && Contains("out of range"));
}

TEST_CASE("scene loader: a PLY without x, y or z vertex properties is refused, naming the property", "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_ply_xyz");
    const std::string no_z = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                             "0 0\n1 0\n0 1\n3 0 1 2\n";
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "no_z.ply", no_z)), Contains("no_z.ply") && Contains("'z'"));
    const std::string no_x = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float y\nproperty float z\n"
                             "property float w\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                             "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "no_x.ply", no_x)), Contains("'x'"));
}
