// Scenes: mesh and scene helpers, the loader (load_mesh: its steps 1, 7 and 8 here, each format's part in
// its own file, scene_detail.hpp lists them, with the helpers they share), camera and light framing.
//
// Loading a file (load_mesh) runs these steps:
//   1. file-system checks: missing, a directory, not a regular file, empty;
//   2. PLY: read here (scene_ply.cpp: read_ply, ply_mesh), not by assimp, because assimp 5.2 reads past
//      the end of a truncated binary PLY (a crash), repeats the last face of a short ASCII PLY, keeps one
//      triangle of each triangle strip and puts vertices without x, y or z at 0. Other formats go through
//      steps 3-6;
//   3. checks before assimp reads the file: OBJ line by line (scene_obj.cpp, obj_check: vertex lines,
//      numbers assimp misreads, indices, polygon size); glTF and GLB (scene_gltf.cpp, gltf_check: chunk
//      lengths against the file size, JSON and node nesting depth, node cycles, each primitive's face
//      count);
//   4. (steps 4 to 6: scene_assimp.cpp) assimp reads the file with no post-processing
//      (Assimp::Importer::ReadFile); then every face is checked (faces assimp dropped, indices, polygon
//      size, NaN/Inf in referenced vertices) before any post-process touches them (assimp passes
//      out-of-range indices and non-finite values through);
//   5. assimp triangulates (aiProcess_Triangulate); corners are welded here, where exactly equal (not
//      with aiProcess_JoinIdenticalVertices, which merges corners closer than about 1e-21);
//   6. meshes are concatenated in node order: depth first from the root, a node's own meshes in its
//      mMeshes order before its children, each with the node's accumulated transform; a mesh referenced by
//      two nodes appears twice. Points and lines are skipped; unreferenced vertices are dropped;
//   7. every coordinate within max_coordinate, the mesh's extent at least min_extent (scene.hpp says why);
//   8. with a log, a warning when the mesh is below float32 resolution at its distance from the origin.
// Reference: assimp 5.2 documentation, https://assimp-docs.readthedocs.io (Importer, aiScene, aiNode).
#include "strahl/scene.hpp"
#include "scene_detail.hpp"
#include "strahl/instancing.hpp"
#include "strahl/procedural.hpp"
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <ostream>
#include <sstream>
#include <utility>

namespace strahl {

aabb triangle_mesh::bounds() const {
    aabb box;
    for (const uvec3& t : indices) box.grow(positions[t.x]).grow(positions[t.y]).grow(positions[t.z]);
    return box;
}

void triangle_mesh::append(const triangle_mesh& other) {
    const auto base = std::uint32_t(positions.size());
    positions.insert(positions.end(), other.positions.begin(), other.positions.end());
    indices.reserve(indices.size() + other.indices.size());
    for (const uvec3& t : other.indices) indices.push_back(t + uvec3(base));
}

aabb scene::bounds() const {
    aabb box = mesh.bounds();
    for (const sphere_desc& s : spheres) box.grow(aabb{s.center - vec3(s.radius), s.center + vec3(s.radius)});
    return box;
}

// The helpers the loader's files share (scene_detail.hpp).
namespace scene_detail {

std::string with_thousands(std::size_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

std::string summary(const std::string& name, std::size_t triangles, std::size_t vertices) {
    return name + ": " + with_thousands(triangles) + " triangles, " + with_thousands(vertices) + " vertices";
}

void fail(const std::filesystem::path& file, const std::string& what) {
    throw load_error(file.string() + ": " + what);
}

std::string lower_extension(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

std::string too_many_corners(std::size_t corners) {
    return "has " + with_thousands(corners) + " corners, more than the " + with_thousands(max_polygon_corners) +
           " a polygon may have here (triangulating it takes time growing with the square of its corners); "
           "split it into smaller polygons";
}

}  // namespace scene_detail

using namespace scene_detail;

std::string below_min_extent(float extent) {
    static_assert(min_extent == 1e-8f && max_coordinate == 1e12f, "the message names both");
    std::ostringstream what;
    what << "is " << extent << " across (the largest side of its bounding box), below 1e-8, the smallest extent "
            "the course accepts (its range: extents from 1e-8 to coordinates of +-1e12; below it the float "
            "triangle tests' products of three lengths underflow and hits are lost): scale the scene up (by a "
            "power of two, which is exact)";
    return what.str();
}

triangle_mesh load_mesh(const std::filesystem::path& file, std::ostream* log) {
    // Step 1: the file system.
    std::error_code ec;
    const auto status = std::filesystem::status(file, ec);
    if (!std::filesystem::exists(status)) fail(file, "no such file");
    if (std::filesystem::is_directory(status)) fail(file, "is a directory, not a mesh file");
    if (!std::filesystem::is_regular_file(status)) fail(file, "is not a regular file");
    const auto bytes = std::filesystem::file_size(file, ec);
    if (ec) fail(file, "cannot be read (" + ec.message() + ")");
    if (bytes == 0) fail(file, "is empty (0 bytes)");
    if (!std::ifstream(file, std::ios::binary)) fail(file, "cannot be opened for reading");

    triangle_mesh mesh;
    std::size_t skipped = 0;
    if (is_ply(file)) {
        // Step 2: PLY, read here.
        mesh = ply_mesh(file, skipped);
    } else {
        // Step 3: checks before assimp (OBJ and glTF); steps 4 to 6 (scene_assimp.cpp): read, check,
        // triangulate, gather.
        gltf_expectation expect;
        if (lower_extension(file) == ".obj") obj_check(file);
        if (is_gltf(file)) expect = gltf_check(file);
        mesh = assimp_mesh(file, expect, skipped);
    }
    if (mesh.indices.empty()) fail(file, "contains no triangles");
    // Step 7: the course's range. Beyond it the triangle tests' products overflow float.
    for (const vec3& p : mesh.positions)
        if (std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > max_coordinate) {
            std::ostringstream what;
            what << "has a vertex at (" << p.x << ", " << p.y << ", " << p.z << "), beyond +-1e12, the largest "
                    "coordinate the course accepts (its float triangle tests multiply three lengths, which "
                    "overflow above about 7e12): scale the scene down";
            fail(file, what.str());
        }
    // Step 7, the other end: below min_extent the tests' products of three lengths underflow.
    {
        const aabb box = mesh.bounds();
        const vec3 e = box.extent(), far = glm::max(glm::abs(box.min), glm::abs(box.max));
        const float span = std::max({e.x, e.y, e.z}), reach = std::max({far.x, far.y, far.z});
        if (!(span >= min_extent)) {
            std::string what = below_min_extent(span);
            // A mesh whose corners float rounded together where it lies (step 8's case, taken to 0 or nearly).
            if (span <= std::ldexp(reach, -20)) {
                std::ostringstream where;
                where << "; it lies " << reach << " from the origin, where float holds nothing that small (about 7 "
                         "significant digits): move it nearer the origin";
                what += where.str();
            }
            fail(file, what);
        }
    }
    if (log) {
        *log << summary(file.filename().string(), mesh.triangle_count(), mesh.positions.size());
        if (skipped > 0) *log << " (" << with_thousands(skipped) << " points and lines skipped)";
        *log << '\n';
        // Step 8: a mesh that float32 cannot hold where it is: its size is below float resolution at its
        // distance from the origin (floats carry 24 bits: 2^-20 of the distance is 8 steps of the last bit),
        // so its corners have collapsed onto a few values. Loaded all the same; the user is told.
        const aabb box = mesh.bounds();
        const vec3 extent = box.extent();
        const float span = std::max({extent.x, extent.y, extent.z});
        const vec3 far = glm::max(glm::abs(box.min), glm::abs(box.max));
        const float reach = std::max({far.x, far.y, far.z});
        if (reach > 0.0f && span <= std::ldexp(reach, -20)) {
            std::size_t degenerate = 0;
            for (const uvec3& t : mesh.indices) degenerate += t.x == t.y || t.y == t.z || t.x == t.z;
            *log << "warning: " << file.filename().string() << ": the mesh is " << span << " across but " << reach
                 << " from the origin, below float32 resolution there (about 7 significant digits): its shape is "
                    "lost, " << with_thousands(degenerate) << " of its " << with_thousands(mesh.triangle_count())
                 << " triangles have collapsed corners; move it nearer the origin or scale it up\n";
        }
    }
    return mesh;
}

camera_desc frame_camera(const aabb& box, float vfov_degrees) {
    // The box's bounding sphere fits the vertical field of view with a 10% margin, seen from +z.
    const vec3 centre = box.is_empty() ? vec3(0.0f) : box.centroid();
    float radius = 0.5f * glm::length(box.extent());
    if (!(radius > 0.0f) || !std::isfinite(radius)) radius = 1.0f;
    const float half = glm::radians(vfov_degrees) * 0.5f;
    const float distance = 1.1f * radius / std::sin(half);
    camera_desc cam;
    cam.eye = centre + vec3(0.0f, 0.0f, distance);
    cam.target = centre;
    cam.up = vec3(0.0f, 1.0f, 0.0f);
    cam.vfov_degrees = vfov_degrees;
    return cam;
}

point_light frame_light(const aabb& box, const camera_desc& camera) {
    // Above and to the right of the eye by a quarter of the box diagonal; intensity pi * d^2 gives an
    // irradiance of pi at the box centre, so a white diffuse surface there facing the light has radiance
    // equal to its albedo.
    float radius = 0.5f * glm::length(box.extent());
    if (!(radius > 0.0f) || !std::isfinite(radius)) radius = 1.0f;
    const vec3 centre = box.is_empty() ? camera.target : box.centroid();
    point_light light;
    light.position = camera.eye + vec3(0.5f * radius, 0.5f * radius, 0.0f);
    const float d = glm::length(light.position - centre);
    light.intensity = color(pi * d * d);
    return light;
}

namespace {

// A view given in fractions of a mesh's bounding box (0 at its min, 1 at its max, per axis), so that a moved
// or rescaled copy of the mesh gets the same view.
struct box_view {
    std::string file;  // the file name it belongs to, lower case
    vec3 eye, target, light;
    float vfov_degrees;
};

// The meshes of ../shared/scenes whose front view says little about them. Sponza is a building: from
// outside only 19% of primary rays hit it. Its view looks down the atrium from the +x end (98% of primary
// rays hit, the sky shows through the open roof) and its light hangs in the middle of the atrium.
const box_view known_views[] = {
    {"sponza.obj", vec3(0.75f, 0.2f, 0.5f), vec3(0.0f, 0.35f, 0.5f), vec3(0.5f, 0.6f, 0.5f), 70.0f},
};

const box_view* known_view(const std::string& file_name) {
    std::string lower = file_name;
    for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    for (const box_view& v : known_views)
        if (v.file == lower) return &v;
    return nullptr;
}

}  // namespace

scene load_scene(const std::filesystem::path& file, std::ostream* log) {
    if (file.extension() == ".scene") {
        // An instanced scene (instancing.hpp): its meshes and instances, and their flattened copy.
        std::optional<std::array<float, 7>> camera;
        instanced_meshes inst = load_instanced(file, log, &camera);
        scene s = instanced_scene(std::move(inst), file.filename().string(), camera);
        if (log) *log << describe(s) << '\n';
        return s;
    }
    scene s;
    s.name = file.filename().string();
    s.mesh = load_mesh(file, log);
    s.materials = {material_desc{"diffuse", material_kind::diffuse, color(0.8f), 0.0f}};
    const aabb box = s.mesh.bounds();
    s.camera = frame_camera(box);
    s.lights = {frame_light(box, s.camera)};
    if (const box_view* v = known_view(s.name)) {
        // The mesh's own view; the light keeps frame_light's rule (an irradiance of pi at the box centre).
        const auto at = [&](vec3 fraction) { return box.min + fraction * box.extent(); };
        s.camera.eye = at(v->eye);
        s.camera.target = at(v->target);
        s.camera.vfov_degrees = v->vfov_degrees;
        s.lights[0].position = at(v->light);
        const float d = glm::length(s.lights[0].position - box.centroid());
        s.lights[0].intensity = color(pi * d * d);
    }
    return s;
}

scene load_scene_spec(const std::string& spec, std::ostream* log) {
    const std::string prefix = "builtin:";
    if (spec.rfind(prefix, 0) == 0) {
        scene s = builtin_scene(spec.substr(prefix.size()));
        if (log) *log << describe(s) << '\n';
        return s;
    }
    return load_scene(spec, log);
}

std::string describe(const scene& s) {
    std::string line = summary(s.name, s.mesh.triangle_count(), s.mesh.positions.size());
    if (!s.spheres.empty()) line += ", " + with_thousands(s.spheres.size()) + (s.spheres.size() == 1 ? " sphere" : " spheres");
    if (!s.planes.empty()) line += ", " + with_thousands(s.planes.size()) + (s.planes.size() == 1 ? " plane" : " planes");
    if (s.instances)
        line += " (" + with_thousands(s.instances->instances.size()) + " instances of " +
                with_thousands(s.instances->meshes.size()) + (s.instances->meshes.size() == 1 ? " mesh)" : " meshes)");
    return line;
}

}  // namespace strahl
