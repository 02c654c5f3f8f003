// Instanced scenes: a few meshes, each placed many times by an affine transform (chapter 10's two-level
// BVHs trace them as they are; every other structure traces their flattened copy).
//
// Primitive ids: the flattened scene lists the instances in order, each instance's triangles in its
// mesh's order, so triangle k of instance i has the flattened id first_id(i) + k. A two-level structure
// reports that id (and the instance in hit.inst), so its answers compare with the flattened scene's, and the
// course's tie rule (the lower id at equal t) orders instances first, then triangles within one.
#pragma once
#include "strahl/scene.hpp"
#include <array>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace strahl {

// p' = L p + t as three rows of four floats (L's row and t's component): m[r] = {L_r0, L_r1, L_r2, t_r}.
// point() and vector() evaluate in one fixed order ((a0 x + a1 y) + a2 z) + t, so that every structure
// transforming the same ray by the same matrix gets the same bits.
struct affine {
    std::array<std::array<float, 4>, 3> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};

    vec3 point(const vec3& p) const {
        return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
                m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
                m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
    }
    vec3 vector(const vec3& v) const {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    bool is_identity() const { return *this == affine{}; }
    bool operator==(const affine&) const = default;

    static affine translate(const vec3& t);
    static affine scale(const vec3& s);
    static affine rotate(int axis, float degrees);  // about x (0), y (1) or z (2), right-handed
};

// a * b: first b, then a. Computed in double, rounded once.
affine operator*(const affine& a, const affine& b);

// The inverse, computed in double and rounded once; nullopt where L is singular (|det| below 1e-30 times
// the product of its rows' lengths) or the result is not finite.
std::optional<affine> inverse(const affine& a);

// The box of a box's eight corners transformed.
aabb transformed(const aabb& box, const affine& a);

struct instance {
    std::uint32_t mesh = 0;  // index into instanced_meshes::meshes
    affine to_world;         // object space to world space
};

struct instanced_meshes {
    std::vector<triangle_mesh> meshes;
    std::vector<std::string> names;   // one per mesh, as the scene file names them
    std::vector<instance> instances;  // empty: the scene is not instanced

    bool empty() const { return instances.empty(); }
    // Triangles of the flattened scene, and flattened id of instance i's first triangle.
    std::uint64_t triangle_count() const;
    std::vector<std::uint32_t> first_ids() const;
    // The box of the instances' world boxes (each mesh's box, transformed): it holds every flattened vertex
    // (up to the rounding of the transform), and is what chapter 10's structures take as their ray frame.
    aabb bounds() const;
    // The flattened mesh: each instance's vertices transformed (affine::point), its triangles in order.
    triangle_mesh flatten() const;
    // Bytes the instanced description holds (meshes' vertices and indices, the instances) and the flattened
    // mesh would hold.
    std::size_t memory_bytes() const;
    std::size_t flattened_bytes() const;
};

// The largest flattened scene load_scene_spec makes (primitive ids are 32 bits; flattening costs memory):
// 64 million triangles. Larger instanced scenes are built and traced instanced only (chapter 10's program).
inline constexpr std::uint64_t max_flattened_triangles = 64u << 20;

// Reads a scene file (extension .scene): lines of words, '#' starts a comment.
//   mesh NAME PATH                  a mesh file (anything load_mesh reads), PATH relative to the scene file
//   instance NAME [TRANSFORM...]    one instance of mesh NAME
//   field NAME NX NZ DX DZ [SEED] [TRANSFORM...]
//                                   NX x NZ instances on a grid: instance (i, j) is the mesh turned about y by
//                                   a pseudo-random angle (from SEED, default 1), then TRANSFORM, then moved
//                                   by (i DX, 0, j DZ)
//   camera EX EY EZ LX LY LZ [FOV]  the camera's eye, the point it looks at, the vertical field of view in
//                                   degrees (default: frame_camera of the scene's box); up is +y, so the
//                                   eye may not lie straight above or below the point
// TRANSFORM: words applied in the order written, the first to the mesh:
//   translate X Y Z | scale S | scale X Y Z | rotate x|y|z DEGREES | matrix M00 M01 M02 M03 M10 ... M23
// Errors (load_error naming the file and line): an unknown keyword, a wrong count or a malformed,
// non-finite or out-of-range number (a field is at most 1,024 x 1,024), an unknown or repeated mesh name, a
// singular transform, a mesh that does not load, no instances, more than max_instances instances, more than
// 2^32 - 2 triangles in all (both refused before the line's instances are made), a transformed coordinate
// beyond max_coordinate, an instance whose extent where it is placed (the largest side of its mesh's box,
// transformed) is below min_extent (scene.hpp: the flattened copy would lose its hits).
inline constexpr std::size_t max_instances = std::size_t(1) << 20;
instanced_meshes load_instanced(const std::filesystem::path& file, std::ostream* log = nullptr,
                                std::optional<std::array<float, 7>>* camera = nullptr);

// A scene from an instanced description: the flattened mesh in scene.mesh (so every structure traces it),
// the description in scene.instances, the camera framing its box (or the one given). Throws load_error
// when the flattened scene would exceed max_flattened_triangles.
scene instanced_scene(instanced_meshes inst, std::string name,
                      const std::optional<std::array<float, 7>>& camera = std::nullopt);

// NX x NZ copies of mesh on a grid, as the scene file's field line makes them (spacing in units of the
// mesh's largest extent; SEED turns them).
instanced_meshes make_field(triangle_mesh mesh, std::string name, int nx, int nz, float spacing,
                            std::uint32_t seed = 1);

}  // namespace strahl
