// The scene loader's internals: what its files share. Not part of the course's API (that is
// common/include/strahl/scene.hpp, unchanged); included only by common/src/scene*.cpp.
//
// The loader, one file per part (scene.cpp's top comment lists load_mesh's steps):
//   scene.cpp         load_mesh (steps 1, 7 and 8 itself), framing, load_scene, describe; the helpers below
//   scene_ply.cpp     step 2: PLY, read here
//   scene_obj.cpp     step 3: OBJ, checked line by line before assimp reads it
//   scene_gltf.cpp    step 3: glTF and GLB, checked before assimp reads them (JSON through nlohmann-json)
//   scene_assimp.cpp  steps 4 to 6: assimp reads the file, the faces are checked, triangulated, welded and
//                     gathered in node order
#pragma once
#include "strahl/scene.hpp"
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace strahl::scene_detail {

// ---- Helpers (scene.cpp).

// 1234567 as "1,234,567".
std::string with_thousands(std::size_t n);
// "bunny.ply: 69,451 triangles, 34,834 vertices".
std::string summary(const std::string& name, std::size_t triangles, std::size_t vertices);
// Throws load_error "FILE: WHAT": every refusal names the file.
[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what);
// The file's extension in lower case, with its dot: ".obj".
std::string lower_extension(const std::filesystem::path& file);

// ---- Welding: corners that are equal share one vertex, numbered in order of first use. Equal means equal
// values (+0 equals -0), not close: welding by distance (assimp's aiProcess_JoinIdenticalVertices merges
// corners closer than about 1e-21) would change the geometry of a small enough mesh. Besides the position,
// a corner's key holds what else the file gives it (for files read by assimp: its normal, texture
// coordinates and colours, as aiProcess_JoinIdenticalVertices compares them), so that vertex counts stay
// those of the files' own vertices.
class welder {
public:
    explicit welder(triangle_mesh& out) : out_(out) {}
    // Starts a corner's key with its position; add() appends what else it has; index() welds it.
    void begin(const vec3& p) {
        key_.clear();
        position_ = p;
        add(&p.x, 3);
    }
    void add(const float* values, int n) {
        for (int i = 0; i < n; ++i) {
            const float v = values[i] == 0.0f ? 0.0f : values[i];  // -0 as +0
            key_.append(reinterpret_cast<const char*>(&v), sizeof v);
        }
    }
    std::uint32_t index() {
        const auto [it, fresh] = seen_.try_emplace(key_, std::uint32_t(out_.positions.size()));
        if (fresh) out_.positions.push_back(position_);
        return it->second;
    }
    std::uint32_t index(const vec3& p) {
        begin(p);
        return index();
    }

private:
    triangle_mesh& out_;
    vec3 position_{0.0f};
    std::string key_;
    std::unordered_map<std::string, std::uint32_t> seen_;
};

// The most corners a polygon may have: assimp's triangulation (ear clipping) takes time growing with the
// square of the corners (about 0.1 s for 4,000 on the course machine, minutes for 100,000).
constexpr std::size_t max_polygon_corners = 1000;

// The refusal of a polygon of that many corners: "has 100,000 corners, more than the 1,000 ...".
std::string too_many_corners(std::size_t corners);

// ---- PLY (scene_ply.cpp): step 2.

// A .ply file, or a file that starts with "ply\n".
bool is_ply(const std::filesystem::path& file);
// The PLY file as one mesh, faces and strips triangulated in file order; skipped counts the faces of one
// or two corners (points and lines).
triangle_mesh ply_mesh(const std::filesystem::path& file, std::size_t& skipped);

// ---- OBJ (scene_obj.cpp): step 3, before assimp reads the file.

void obj_check(const std::filesystem::path& file);

// ---- glTF and GLB (scene_gltf.cpp): step 3, before assimp reads the file.

// What a glTF 2.0 file says its primitives hold: per primitive, in the order assimp makes them meshes
// (mesh by mesh, primitive by primitive), the number of faces its index accessor makes, or -1 where no
// face can be dropped (no indices) or the count is not known.
struct gltf_expectation {
    std::vector<long long> faces;
    std::vector<std::string> names;  // "mesh 2, primitive 0"
};

// A .gltf or .glb file, or a file that starts with "glTF".
bool is_gltf(const std::filesystem::path& file);
// Refuses a glTF or GLB that assimp would misread or choke on; returns what its primitives hold.
gltf_expectation gltf_check(const std::filesystem::path& file);

// ---- assimp (scene_assimp.cpp): steps 4 to 6 for every format but PLY. expect: gltf_check's answer for
// a glTF (empty otherwise); skipped counts the points and lines left out.
triangle_mesh assimp_mesh(const std::filesystem::path& file, const gltf_expectation& expect, std::size_t& skipped);

}  // namespace strahl::scene_detail
