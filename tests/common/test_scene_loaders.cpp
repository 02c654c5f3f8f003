// Unit tests of the scene loader (common/src/scene.cpp): the shared meshes with their known counts, small
// valid OBJ/PLY/glTF files written at test time, and every kind of bad file, each of which must throw a
// load_error naming the file and the problem (never crash, never return a smaller scene).
#include <catch2/catch.hpp>
#include "strahl/procedural.hpp"
#include "strahl/scene.hpp"
#include "test_support.hpp"
#include <chrono>
#include <cmath>
#include <cstring>
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

// ---- Hostile files (issue #20): each case below was loaded silently wrong, crashed or ran away before.

namespace {

std::string base64(const std::string& bytes) {
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t n = std::uint32_t(static_cast<unsigned char>(bytes[i])) << 16;
        if (i + 1 < bytes.size()) n |= std::uint32_t(static_cast<unsigned char>(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) n |= std::uint32_t(static_cast<unsigned char>(bytes[i + 2]));
        out += digits[(n >> 18) & 63];
        out += digits[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[n & 63] : '=';
    }
    return out;
}

template <class T> void append_raw(std::string& out, const T& value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// The binary buffer of a glTF mesh: float positions, then unsigned short indices.
std::string gltf_buffer(const std::vector<vec3>& positions, const std::vector<std::uint16_t>& indices) {
    std::string bin;
    for (const vec3& p : positions) { append_raw(bin, p.x); append_raw(bin, p.y); append_raw(bin, p.z); }
    for (const std::uint16_t i : indices) append_raw(bin, i);
    while (bin.size() % 4 != 0) bin += '\0';
    return bin;
}

// The JSON of a one-mesh glTF whose buffer (positions, then indices) is `uri` (empty: a GLB's own chunk),
// with the given "nodes" array and scene roots.
std::string gltf_json(std::size_t vertices, std::size_t indices, std::size_t buffer_bytes, const std::string& uri,
                      const std::string& nodes = R"([{"mesh":0}])", const std::string& roots = "[0]") {
    const std::size_t position_bytes = 12 * vertices;
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":)" + roots + R"(}],"nodes":)" + nodes +
           R"(,"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],"buffers":[{"byteLength":)" +
           std::to_string(buffer_bytes) + (uri.empty() ? "" : R"(,"uri":")" + uri + "\"") +
           R"(}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" + std::to_string(position_bytes) +
           R"(},{"buffer":0,"byteOffset":)" + std::to_string(position_bytes) + R"(,"byteLength":)" +
           std::to_string(2 * indices) + R"(}],"accessors":[{"bufferView":0,"componentType":5126,"count":)" +
           std::to_string(vertices) + R"(,"type":"VEC3","min":[-1e9,-1e9,-1e9],"max":[1e9,1e9,1e9]},)" +
           R"({"bufferView":1,"componentType":5123,"count":)" + std::to_string(indices) + R"(,"type":"SCALAR"}]})";
}

std::string gltf_text(const std::vector<vec3>& positions, const std::vector<std::uint16_t>& indices,
                      const std::string& nodes = R"([{"mesh":0}])") {
    const std::string bin = gltf_buffer(positions, indices);
    return gltf_json(positions.size(), indices.size(), bin.size(),
                     "data:application/octet-stream;base64," + base64(bin), nodes);
}

// A binary glTF: 12-byte header, a JSON chunk padded with spaces, a BIN chunk padded with zeros.
std::string glb(const std::vector<vec3>& positions, const std::vector<std::uint16_t>& indices) {
    const std::string bin = gltf_buffer(positions, indices);
    std::string json = gltf_json(positions.size(), indices.size(), bin.size(), "");
    while (json.size() % 4 != 0) json += ' ';
    std::string out = "glTF";
    append_raw(out, std::uint32_t(2));
    append_raw(out, std::uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    append_raw(out, std::uint32_t(json.size()));
    append_raw(out, std::uint32_t(0x4E4F534A));  // "JSON"
    out += json;
    append_raw(out, std::uint32_t(bin.size()));
    append_raw(out, std::uint32_t(0x004E4942));  // "BIN\0"
    out += bin;
    return out;
}

const std::vector<vec3> unit_quad = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)};

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

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

TEST_CASE("scene loader: a glTF face with an out-of-range vertex index is refused, not dropped", "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_gltf_index");
    CHECK(load_mesh(write_file(dir, "good.gltf", gltf_text(unit_quad, {0, 1, 2, 0, 2, 3}))).triangle_count() == 2);
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "bad_index.gltf", gltf_text(unit_quad, {0, 1, 2, 0, 2, 7}))),
                        Contains("bad_index.gltf") && Contains("out of range"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "bad_index.glb", glb(unit_quad, {0, 1, 2, 0, 2, 7}))),
                        Contains("bad_index.glb") && Contains("out of range"));
}

TEST_CASE("scene loader: whole numbers of 20 or more digits in OBJ are read right or refused, never read as 0",
          "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_obj_digits");
    const std::string rest = "v 0 1 0\nv 0 0 1\nf 1 2 3\n";
    // Up to 19 digits and exponents are fine.
    CHECK(load_mesh(write_file(dir, "e11.obj", "v 1e11 0 0\n" + rest)).bounds().max.x == 1e11f);
    CHECK(load_mesh(write_file(dir, "digits12.obj", "v 100000000000 0 0\n" + rest)).bounds().max.x == 1e11f);
    // Beyond the course's range (max_coordinate, 1e12) the triangle tests overflow: refused, saying so.
    CHECK_THROWS_WITH(load_mesh(write_file(dir, "e20.obj", "v 1e20 0 0\n" + rest)),
                      Contains("e20.obj") && Contains("beyond +-1e12") && Contains("overflow"));
    CHECK_THROWS_WITH(load_mesh(write_file(dir, "digits19.obj", "v 1000000000000000000 0 0\n" + rest)),
                      Contains("beyond +-1e12"));
    // assimp's reader gives 0 for some (its integer overflows), a wrapped value for others (3e19 as 1.16e19).
    const std::pair<const char*, float> numbers[] = {
        {"100000000000000000000", 1e20f}, {"-30000000000000000000", -3e19f}, {"100000000000000000000.5", 1e20f}};
    for (const auto& [number, value] : numbers) {
        INFO(number);
        try {
            const triangle_mesh m = load_mesh(write_file(dir, "digits.obj", "v " + std::string(number) + " 0 0\n" + rest));
            CHECK((m.bounds().min.x == value || m.bounds().max.x == value));  // read right
        } catch (const load_error& e) {
            CHECK_THAT(e.what(), Contains("digits.obj") && Contains("line 1"));  // or refused, naming the line
        }
    }
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

TEST_CASE("scene loader: a 100,000-corner OBJ polygon is handled or refused within a second", "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_obj_polygon");
    const auto polygon = [](int n) {
        std::ostringstream text;
        for (int k = 0; k < n; ++k) text << "v " << std::cos(2 * pi * k / n) << ' ' << std::sin(2 * pi * k / n) << " 0\n";
        text << 'f';
        for (int k = 1; k <= n; ++k) text << ' ' << k;
        text << '\n';
        return text.str();
    };
    CHECK(load_mesh(write_file(dir, "polygon_1000.obj", polygon(1000))).triangle_count() == 998);
    const auto path = write_file(dir, "polygon.obj", polygon(100000));
    const auto start = std::chrono::steady_clock::now();
    std::size_t triangles = 0;
    std::string error;
    try {
        triangles = load_mesh(path).triangle_count();
    } catch (const load_error& e) {
        error = e.what();
    }
    CHECK(seconds_since(start) < 1.0);
    if (error.empty()) CHECK(triangles == 99998);  // handled
    else CHECK_THAT(error, Contains("polygon.obj") && Contains("100,000 corners"));  // or refused
}

TEST_CASE("scene loader: malformed OBJ vertex lines say what is wrong, naming the line", "[common][scene]") {
    const auto dir = test::scratch_dir("scene_loader_obj_vertex_lines");
    const std::string rest = "v 0 1 0\nv 0 0 1\nf 1 2 3\n";
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "two.obj", "v 0 0\n" + rest)),
                        Contains("two.obj") && Contains("line 1") && Contains("three numbers"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "letters.obj", rest + "v a b c\n")),
                        Contains("letters.obj") && Contains("line 4") && Contains("'a' is not a number"));
    REQUIRE_THROWS_WITH(load_mesh(write_file(dir, "five.obj", "v 1 2 3 4 5\n" + rest)), Contains("line 1"));
    // Valid forms: x y z, x y z w, x y z r g b, a comment after the numbers.
    CHECK(load_mesh(write_file(dir, "forms.obj", "v 0 0 0 1\nv 1 0 0 0.5 0.5 0.5\nv 0 1 0 # corner\nf 1 2 3\n"))
              .triangle_count() == 1);
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
