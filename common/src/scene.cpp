// Scenes: mesh and scene helpers, the assimp loader with its checks, camera and light framing.
//
// Loading a file (load_mesh) runs these steps:
//   1. file-system checks: missing, a directory, not a regular file, empty;
//   2. PLY only: walk the body against the header (ply_body_check), because assimp 5.2 reads past the end
//      of a truncated binary PLY (a crash) and repeats the last face of a short ASCII PLY;
//   3. assimp reads the file with no post-processing (Assimp::Importer::ReadFile);
//   4. every face index is checked against its mesh's vertex count and every referenced vertex for NaN/Inf,
//      before any post-process touches them (assimp passes PLY indices and non-finite values through);
//   5. assimp triangulates (aiProcess_Triangulate) and welds identical vertices
//      (aiProcess_JoinIdenticalVertices, which renumbers vertices but keeps the faces in file order);
//   6. meshes are concatenated in node order: depth first from the root, a node's own meshes in its
//      mMeshes order before its children, each with the node's accumulated transform; a mesh referenced by
//      two nodes appears twice. Points and lines are skipped; unreferenced vertices are dropped.
// Reference: assimp 5.2 documentation, https://assimp-docs.readthedocs.io (Importer, aiScene, aiNode).
#include "strahl/scene.hpp"
#include "strahl/procedural.hpp"
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <algorithm>
#include <cctype>
#include <fstream>
#include <ostream>
#include <sstream>

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

namespace {

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

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
    throw load_error(file.string() + ": " + what);
}

// ---- Step 2: the PLY body against its header (format: Greg Turk, "The PLY Polygon File Format", 1994).

struct ply_property {
    bool is_list = false;
    int count_size = 0;  // bytes of a list's count
    int value_size = 0;  // bytes of a scalar, or of each list item
    std::string name;
};
struct ply_element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<ply_property> properties;
};

int ply_type_size(const std::string& t) {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32") return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
}

// A list count of `size` bytes at p; counts are unsigned in practice, a negative signed one reads huge.
std::uint64_t read_count(const unsigned char* p, int size, bool big_endian) {
    std::uint64_t v = 0;
    for (int i = 0; i < size; ++i) v |= std::uint64_t(p[big_endian ? size - 1 - i : i]) << (8 * i);
    return v;
}

void ply_body_check(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Header: "ply", "format ...", elements with their properties, "end_header".
    std::size_t pos = 0;
    std::string format;
    std::vector<ply_element> elements;
    bool ended = false, first = true;
    while (!ended && pos < data.size()) {
        std::size_t eol = data.find('\n', pos);
        if (eol == std::string::npos) eol = data.size();
        std::istringstream line(data.substr(pos, eol - pos));
        pos = eol + 1;
        std::string word;
        line >> word;
        if (first) {
            if (word != "ply") fail(file, "not a PLY file (it does not start with 'ply')");
            first = false;
        } else if (word == "format") {
            line >> format;
        } else if (word == "element") {
            ply_element e;
            if (!(line >> e.name >> e.count)) fail(file, "malformed PLY header line 'element'");
            elements.push_back(e);
        } else if (word == "property") {
            ply_property p;
            std::string type;
            line >> type;
            if (type == "list") {
                std::string count_type, value_type;
                line >> count_type >> value_type;
                p.is_list = true;
                p.count_size = ply_type_size(count_type);
                p.value_size = ply_type_size(value_type);
                if (p.count_size == 0) type = count_type;
            } else {
                p.value_size = ply_type_size(type);
            }
            line >> p.name;
            if (p.value_size == 0 || (p.is_list && p.count_size == 0)) fail(file, "unknown PLY type '" + type + "'");
            if (elements.empty()) fail(file, "PLY property '" + p.name + "' before any element");
            elements.back().properties.push_back(p);
        } else if (word == "end_header") {
            ended = true;
        }
    }
    if (!ended) fail(file, "PLY header has no end_header (truncated or not a PLY file)");
    const auto missing = [&](const ply_element& e, std::uint64_t i) {
        fail(file, "truncated: the header declares " + with_thousands(e.count) + " " + e.name +
                       " elements, the data ends at " + e.name + " " + with_thousands(i));
    };
    if (format == "ascii") {
        // One element per line: first the number of data lines against the declared counts, then each
        // line's number of values against its element's properties and list counts.
        std::uint64_t declared = 0, lines = 0;
        std::string counts;
        for (const ply_element& e : elements) {
            declared += e.count;
            counts += (counts.empty() ? "" : ", ") + with_thousands(e.count) + " " + e.name;
        }
        for (std::size_t p = pos; p < data.size();) {
            std::size_t eol = data.find('\n', p);
            if (eol == std::string::npos) eol = data.size();
            if (data.find_first_not_of(" \t\r", p) < eol) ++lines;
            p = eol + 1;
        }
        if (lines < declared)
            fail(file, "truncated: the header declares " + counts + " elements, but the data holds only " +
                           with_thousands(lines) + " of the " + with_thousands(declared) + " lines");
        for (const ply_element& e : elements) {
            for (std::uint64_t i = 0; i < e.count; ++i) {
                std::string text;
                while (text.find_first_not_of(" \t\r") == std::string::npos) {
                    if (pos >= data.size()) missing(e, i);
                    std::size_t eol = data.find('\n', pos);
                    if (eol == std::string::npos) eol = data.size();
                    text = data.substr(pos, eol - pos);
                    pos = eol + 1;
                }
                std::istringstream line(text);
                std::vector<std::string> values;
                for (std::string v; line >> v;) values.push_back(v);
                std::size_t need = 0;
                for (const ply_property& p : e.properties) {
                    if (!p.is_list) { ++need; continue; }
                    long long n = -1;
                    if (need < values.size()) n = std::atoll(values[need].c_str());
                    if (n < 0) break;
                    need += 1 + std::size_t(n);
                }
                if (values.size() != need || need == 0)
                    fail(file, e.name + " " + with_thousands(i) + " has " + std::to_string(values.size()) +
                                   " values, its properties need " + std::to_string(need));
            }
        }
    } else if (format == "binary_little_endian" || format == "binary_big_endian") {
        const bool big = format == "binary_big_endian";
        const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
        const std::uint64_t size = data.size();
        std::uint64_t at = std::min<std::uint64_t>(pos, size);
        for (const ply_element& e : elements) {
            const bool fixed = std::none_of(e.properties.begin(), e.properties.end(),
                                            [](const ply_property& p) { return p.is_list; });
            if (fixed) {  // fixed-size records: one multiplication, no walk
                std::uint64_t stride = 0;
                for (const ply_property& p : e.properties) stride += std::uint64_t(p.value_size);
                if (stride > 0 && e.count > (size - at) / stride) missing(e, (size - at) / stride);
                at += e.count * stride;
                continue;
            }
            for (std::uint64_t i = 0; i < e.count; ++i) {
                for (const ply_property& p : e.properties) {
                    std::uint64_t n = 1;
                    if (p.is_list) {
                        if (std::uint64_t(p.count_size) > size - at) missing(e, i);
                        n = read_count(bytes + at, p.count_size, big);
                        at += std::uint64_t(p.count_size);
                    }
                    if (n > (size - at) / std::uint64_t(p.value_size)) missing(e, i);
                    at += n * std::uint64_t(p.value_size);
                }
            }
        }
    } else {
        fail(file, "unknown PLY format '" + format + "'");
    }
}

bool is_ply(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    std::string ext = file.extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".ply" || (in.gcount() == 4 && std::string(magic, 4) == "ply\n");
}

// ---- Step 4: indices in range and referenced vertices finite, before any post-process.
void check_raw_meshes(const std::filesystem::path& file, const aiScene& s) {
    for (unsigned m = 0; m < s.mNumMeshes; ++m) {
        const aiMesh& mesh = *s.mMeshes[m];
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices == 0)  // assimp 5.2's triangulation aborts on these
                fail(file, "face " + with_thousands(f) + " of mesh " + std::to_string(m) + " has no vertices");
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                const unsigned idx = face.mIndices[k];
                if (idx >= mesh.mNumVertices)
                    fail(file, "face " + with_thousands(f) + " of mesh " + std::to_string(m) + " refers to vertex " +
                                   std::to_string(idx) + ", but the mesh has " + with_thousands(mesh.mNumVertices) +
                                   " vertices (index out of range)");
                const aiVector3D& p = mesh.mVertices[idx];
                if (!is_finite(vec3(p.x, p.y, p.z)))
                    fail(file, "vertex " + with_thousands(idx) + " of mesh " + std::to_string(m) +
                                   " has a non-finite coordinate (NaN or Inf)");
            }
        }
    }
}

// ---- Step 6: meshes in node order with accumulated transforms.
struct gatherer {
    const aiScene& scene;
    triangle_mesh out;
    std::size_t skipped = 0;  // points and lines

    void visit(const aiNode& node, const aiMatrix4x4& parent) {
        const aiMatrix4x4 world = parent * node.mTransformation;
        const bool identity = world.IsIdentity();
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
            // Keep only referenced vertices, numbered in order of first use.
            std::vector<std::uint32_t> remap(mesh.mNumVertices, invalid_id);
            for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
                const aiFace& face = mesh.mFaces[f];
                if (face.mNumIndices != 3) { ++skipped; continue; }
                uvec3 tri;
                for (int k = 0; k < 3; ++k) {
                    std::uint32_t& r = remap[face.mIndices[k]];
                    if (r == invalid_id) {
                        const aiVector3D p = identity ? mesh.mVertices[face.mIndices[k]]
                                                      : world * mesh.mVertices[face.mIndices[k]];
                        r = std::uint32_t(out.positions.size());
                        out.positions.emplace_back(p.x, p.y, p.z);
                    }
                    tri[k] = r;
                }
                out.indices.push_back(tri);
            }
        }
        for (unsigned c = 0; c < node.mNumChildren; ++c) visit(*node.mChildren[c], world);
    }
};

}  // namespace

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

    // Step 2: PLY body against the header.
    if (is_ply(file)) ply_body_check(file);

    // Steps 3 to 5: read, check, post-process.
    Assimp::Importer importer;
    const aiScene* s = importer.ReadFile(file.string(), 0);
    if (!s) fail(file, std::string("cannot be read (assimp: ") + importer.GetErrorString() + ")");
    if ((s->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !s->mRootNode || s->mNumMeshes == 0)
        fail(file, "contains no triangles (no meshes found; malformed or not a mesh file)");
    check_raw_meshes(file, *s);
    s = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
    if (!s) fail(file, std::string("cannot be processed (assimp: ") + importer.GetErrorString() + ")");

    // Step 6: node order.
    gatherer g{*s, {}, 0};
    g.visit(*s->mRootNode, aiMatrix4x4());
    if (g.out.indices.empty()) fail(file, "contains no triangles");
    for (const vec3& p : g.out.positions)
        if (!is_finite(p)) fail(file, "a node transform makes a coordinate non-finite (NaN or Inf)");
    if (log) {
        *log << summary(file.filename().string(), g.out.triangle_count(), g.out.positions.size());
        if (g.skipped > 0) *log << " (" << with_thousands(g.skipped) << " points and lines skipped)";
        *log << '\n';
    }
    return std::move(g.out);
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
    return line;
}

}  // namespace strahl
