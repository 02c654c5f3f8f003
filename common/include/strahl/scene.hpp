// Scenes: one triangle mesh, optional analytic spheres and planes (chapter 01 needs them), materials,
// point lights and a default camera. Loaded from files with assimp or made procedurally.
//
// Primitive ids: triangle i of scene.mesh has primitive id i. Every loader and generator documents the
// order in which it emits triangles, so a hit file written today names the same triangle tomorrow.
#pragma once
#include "strahl/aabb.hpp"
#include "strahl/camera.hpp"
#include <array>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace strahl {

struct triangle_mesh {
    std::vector<vec3> positions;
    std::vector<uvec3> indices;  // one index triple per triangle, into positions

    std::size_t triangle_count() const { return indices.size(); }
    std::array<vec3, 3> triangle(std::size_t i) const {
        const uvec3 t = indices[i];
        return {positions[t.x], positions[t.y], positions[t.z]};
    }
    aabb bounds() const;  // of the referenced vertices; empty for an empty mesh
    // Appends other's triangles after this mesh's (ids continue), re-basing its indices.
    void append(const triangle_mesh& other);
};

enum class material_kind { diffuse, mirror, rough_mirror };

struct material_desc {
    std::string name = "default";
    material_kind kind = material_kind::diffuse;
    color albedo{0.8f};     // diffuse reflectance, or the mirror's reflectance
    float roughness = 0.0f;  // rough mirror only: spread of the reflected lobe, 0 = perfect mirror
};

struct sphere_desc {
    vec3 center{0.0f};
    float radius = 1.0f;
    std::uint32_t material = 0;
};

// The plane of points p with dot(normal, p) == offset; normal is unit length.
struct plane_desc {
    vec3 normal{0.0f, 1.0f, 0.0f};
    float offset = 0.0f;
    std::uint32_t material = 0;
};

// Isotropic point light; intensity in W/sr per colour channel (irradiance falls off as 1/d^2).
struct point_light {
    vec3 position{0.0f};
    color intensity{1.0f};
};

struct instanced_meshes;  // instancing.hpp

struct scene {
    std::string name;
    triangle_mesh mesh;
    // An instanced scene's meshes and instances (instancing.hpp), whose flattened copy mesh holds; null for
    // a scene of one mesh. Chapter 10's two-level structures trace it instanced.
    std::shared_ptr<const instanced_meshes> instances;
    std::vector<std::uint32_t> triangle_materials;  // empty: every triangle uses material 0
    std::vector<sphere_desc> spheres;
    std::vector<plane_desc> planes;
    std::vector<material_desc> materials{material_desc{}};  // never empty
    std::vector<point_light> lights;
    camera_desc camera;

    std::uint32_t triangle_material(std::size_t i) const {
        return triangle_materials.empty() ? 0u : triangle_materials[i];
    }
    aabb bounds() const;  // triangles and spheres; planes are unbounded and left out
};

// A file that cannot be turned into a scene: missing, unreadable, malformed, truncated, empty, or holding
// non-finite coordinates. The message names the file and what is wrong with it.
class load_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Loads OBJ, PLY, glTF (and whatever else assimp reads) as one triangle mesh. PLY is read by the course's
// own reader, everything else by assimp. Polygons are triangulated; meshes are concatenated in node order,
// each mesh's faces in file order. Throws load_error. Where log is given, prints one line: file, triangles,
// vertices; and a warning line when the mesh is below float32 resolution at its distance from the origin
// (its largest side under 2^-20 of its largest coordinate: its corners have collapsed; loaded all the same).
//
// Triangle order (the primitive ids): the node tree is walked depth first from the root; a node's own
// meshes come in its mesh-list order before its children, each with the node's accumulated transform (a
// mesh used by two nodes appears twice). Within a mesh, faces come in file order; a polygon of n corners
// becomes n - 2 triangles in place (assimp's aiProcess_Triangulate: a quad a b c d gives a b c, a c d
// unless b, c or d is a concave corner, where the fan then starts). For OBJ every object/group (and
// material change) is one mesh, in file order under the root. A PLY is one mesh: its faces and triangle
// strips (element tristrips; -1 restarts a strip, every other triangle swaps its first two corners so that
// all face one way, triangles repeating a corner are kept as the strip says) in file order; its polygons of
// five or more corners become a fan from their first corner. Points and lines are skipped. Vertices: corners
// with equal positions (and, for files read by assimp, equal normals, texture coordinates and colours)
// within a mesh are welded, never corners that merely lie close; unreferenced ones are dropped; numbered in
// order of first use.
// Errors: missing file, a directory, an empty file, a truncated PLY (more vertices or faces declared than
// present), a PLY vertex without x, y or z, indices out of range (every format: OBJ zero, negative before
// any vertex, beyond the last vertex; a glTF face assimp would drop), NaN or Inf in a referenced vertex, an
// OBJ vertex line without three numbers or with a whole number of more than 64 bits, a polygon of more
// than 1,000 corners, a glTF whose nodes nest more than 1,000 deep or form a cycle, a GLB whose lengths
// exceed the file, a file assimp cannot read, a file with no triangles, a coordinate beyond max_coordinate,
// and an extent (the largest side of the mesh's bounding box) below min_extent, a mesh that is one point
// included.
triangle_mesh load_mesh(const std::filesystem::path& file, std::ostream* log = nullptr);

// The largest coordinate (in magnitude) the course accepts, in a scene or a ray file's origins and
// directions. The triangle tests multiply three lengths (Moeller-Trumbore's t = e2 . (s x e1) / det):
// with edges and the origin's offset of about 7e12, that product passes float's largest value, 3.4e38,
// and every hit is lost. Within +-1e12 the largest product stays below 5e37.
inline constexpr float max_coordinate = 1e12f;

// The smallest extent the course accepts: the largest side of a mesh's bounding box, and of each instance of
// a scene file where it is placed. The triangle tests multiply three lengths the other way too: Moeller-
// Trumbore's t numerator e2 . ((org - v0) x e1) and the watertight test's T are about a^2 b for a triangle of
// edge a seen from a distance b. Below float's smallest normal number, 2^-126 (1.2e-38), such a product
// loses digits, becomes 0 where denormals are flushed (Embree's kernels run so), and below 2^-150 becomes 0
// in every test: t = 0, and the hit is lost. At 1e-8, a triangle as small as float resolves in the scene
// (edges of 2^-20 of its extent) seen from the scene's size keeps a^2 b near 1e-36, 77 times 2^-126. Chapter 15 measures the edges: the teapot (its triangles about 1e-2 of its extent) loses hits
// in Embree below an extent of about 6e-12 and in the course's float tests below about 5e-14.
inline constexpr float min_extent = 1e-8f;

// The refusal of an extent below min_extent, as load_mesh and load_instanced word it: "is 5e-12 across (the
// largest side of its bounding box), below 1e-8, ...: scale the scene up".
std::string below_min_extent(float extent);

// load_mesh plus what a render needs: one diffuse material, a camera framing the mesh from the front
// (+z looking at -z) and a point light near the camera. Meshes whose front view says little have a view
// of their own, chosen by file name (case ignored) and placed in fractions of the mesh's bounding box:
// sponza.obj is seen from inside, down its atrium from the +x end, lit from the middle of the atrium
// (from outside only 19% of primary rays would hit it).
scene load_scene(const std::filesystem::path& file, std::ostream* log = nullptr);

// "builtin:NAME" (see builtin_scene_names) or a file path.
scene load_scene_spec(const std::string& spec, std::ostream* log = nullptr);

// Camera and light framing a bounding box from the front, as load_scene places them.
// The camera sits on +z of the box centre, looks at it with up = +y, and fits the box's bounding sphere
// into the vertical field of view with a 10% margin (for images at least as wide as tall).
camera_desc frame_camera(const aabb& box, float vfov_degrees = 40.0f);

// A point light above and to the right of the camera's eye (by a quarter of the box diagonal), with an
// intensity of pi * d^2 for its distance d to the box centre: an irradiance of pi there, so a white
// diffuse surface at the centre facing the light has a radiance equal to its albedo.
point_light frame_light(const aabb& box, const camera_desc& camera);

// A one-line summary: "bunny.ply: 69,451 triangles, 34,834 vertices".
std::string describe(const scene& s);

}  // namespace strahl
