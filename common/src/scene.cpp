// Scenes: mesh and scene helpers, the assimp loader with its checks, camera and light framing.
//
// Loading a file (load_mesh) runs these steps:
//   1. file-system checks: missing, a directory, not a regular file, empty;
//   2. PLY: read here (read_ply, ply_mesh), not by assimp, because assimp 5.2 reads past the end of a
//      truncated binary PLY (a crash), repeats the last face of a short ASCII PLY, keeps one triangle of
//      each triangle strip and puts vertices without x, y or z at 0. Other formats go through steps 3-6;
//   3. checks before assimp reads the file: OBJ line by line (obj_check: vertex lines, numbers assimp
//      misreads, indices, polygon size); glTF and GLB (gltf_check: chunk lengths against the file size,
//      JSON and node nesting depth, node cycles, each primitive's face count);
//   4. assimp reads the file with no post-processing (Assimp::Importer::ReadFile); then every face is
//      checked (faces assimp dropped, indices, polygon size, NaN/Inf in referenced vertices) before any
//      post-process touches them (assimp passes out-of-range indices and non-finite values through);
//   5. assimp triangulates (aiProcess_Triangulate); corners are welded here, where exactly equal (not
//      with aiProcess_JoinIdenticalVertices, which merges corners closer than about 1e-21);
//   6. meshes are concatenated in node order: depth first from the root, a node's own meshes in its
//      mMeshes order before its children, each with the node's accumulated transform; a mesh referenced by
//      two nodes appears twice. Points and lines are skipped; unreferenced vertices are dropped;
//   7. every coordinate within max_coordinate, the mesh's extent at least min_extent (scene.hpp says why);
//   8. with a log, a warning when the mesh is below float32 resolution at its distance from the origin.
// Reference: assimp 5.2 documentation, https://assimp-docs.readthedocs.io (Importer, aiScene, aiNode).
#include "strahl/scene.hpp"
#include "strahl/instancing.hpp"
#include "strahl/procedural.hpp"
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <ostream>
#include <sstream>
#include <string_view>
#include <unordered_map>
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

std::string lower_extension(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

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

std::string too_many_corners(std::size_t corners) {
    return "has " + with_thousands(corners) + " corners, more than the " + with_thousands(max_polygon_corners) +
           " a polygon may have here (triangulating it takes time growing with the square of its corners); "
           "split it into smaller polygons";
}

// ---- PLY: our own reader (format: Greg Turk, "The PLY Polygon File Format", 1994). assimp 5.2 reads past
// the end of a truncated binary PLY (a crash), repeats the last face of a short ASCII PLY, keeps one
// triangle of each triangle strip and puts vertices without x, y or z at 0; this reader refuses or reads
// each of these right.

enum class ply_type { int8, uint8, int16, uint16, int32, uint32, float32, float64, unknown };

ply_type ply_type_of(const std::string& t) {
    if (t == "char" || t == "int8") return ply_type::int8;
    if (t == "uchar" || t == "uint8") return ply_type::uint8;
    if (t == "short" || t == "int16") return ply_type::int16;
    if (t == "ushort" || t == "uint16") return ply_type::uint16;
    if (t == "int" || t == "int32") return ply_type::int32;
    if (t == "uint" || t == "uint32") return ply_type::uint32;
    if (t == "float" || t == "float32") return ply_type::float32;
    if (t == "double" || t == "float64") return ply_type::float64;
    return ply_type::unknown;
}

int ply_type_size(ply_type t) {
    switch (t) {
        case ply_type::int8: case ply_type::uint8: return 1;
        case ply_type::int16: case ply_type::uint16: return 2;
        case ply_type::int32: case ply_type::uint32: case ply_type::float32: return 4;
        case ply_type::float64: return 8;
        case ply_type::unknown: break;
    }
    return 0;
}

struct ply_property {
    bool is_list = false;
    ply_type count_type = ply_type::unknown;  // a list's count
    ply_type value_type = ply_type::unknown;  // a scalar, or each list item
    std::string name;
};
struct ply_element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<ply_property> properties;
    int find(const std::string& property) const {
        for (std::size_t k = 0; k < properties.size(); ++k)
            if (properties[k].name == property) return int(k);
        return -1;
    }
};

// One record of an element: property k's values are values[begin[k]], ... (one for a scalar, the items
// of a list), every value as a double (exact for every PLY type).
struct ply_record {
    std::vector<double> values;
    std::vector<std::size_t> begin, count;
};

// A binary value of type t at p (the caller has checked that its bytes are there).
double read_binary(const unsigned char* p, ply_type t, bool big_endian) {
    const int size = ply_type_size(t);
    std::uint64_t bits = 0;
    for (int i = 0; i < size; ++i) bits |= std::uint64_t(p[big_endian ? size - 1 - i : i]) << (8 * i);
    switch (t) {
        case ply_type::int8: return double(std::int8_t(std::uint8_t(bits)));
        case ply_type::int16: return double(std::int16_t(std::uint16_t(bits)));
        case ply_type::int32: return double(std::int32_t(std::uint32_t(bits)));
        case ply_type::float32: { float f; const auto b = std::uint32_t(bits); std::memcpy(&f, &b, 4); return double(f); }
        case ply_type::float64: { double d; std::memcpy(&d, &bits, 8); return d; }
        default: return double(bits);  // the unsigned types
    }
}

// An ASCII value: a number in C syntax (nan and inf included), read as a float for float properties (one
// rounding, as a binary file would hold it) and as a double otherwise.
bool read_ascii(const std::string& text, ply_type t, double& value) {
    const char* first = text.data() + (!text.empty() && text[0] == '+' ? 1 : 0);
    const char* last = text.data() + text.size();
    if (t == ply_type::float32) {
        float f = 0.0f;
        const auto r = std::from_chars(first, last, f);
        value = f;
        return r.ec == std::errc() && r.ptr == last;
    }
    const auto r = std::from_chars(first, last, value);
    return r.ec == std::errc() && r.ptr == last;
}

// A PLY file read into its vertex positions (in file order) and its faces and strips (corner lists into
// them), every index checked against the vertex count.
struct ply_contents {
    std::vector<vec3> positions;
    std::vector<std::uint32_t> corners;  // the faces' corners, one face after another
    std::vector<std::uint32_t> sizes;    // each face's number of corners
    std::vector<std::uint32_t> strips;   // the strips' indices, invalid_id where a strip restarts
    std::vector<std::size_t> strip_begin, strip_size;  // each tristrips record's indices in strips
    std::vector<std::pair<bool, std::size_t>> order;   // (a strip?, which one): faces and strips in file order
};

ply_contents read_ply(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
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
                p.count_type = ply_type_of(count_type);
                p.value_type = ply_type_of(value_type);
                type = p.count_type == ply_type::unknown ? count_type : value_type;
            } else {
                p.value_type = ply_type_of(type);
            }
            line >> p.name;
            if (p.value_type == ply_type::unknown || (p.is_list && p.count_type == ply_type::unknown))
                fail(file, "unknown PLY type '" + type + "'");
            if (elements.empty()) fail(file, "PLY property '" + p.name + "' before any element");
            elements.back().properties.push_back(p);
        } else if (word == "end_header") {
            ended = true;
        }
    }
    if (!ended) fail(file, "PLY header has no end_header (truncated or not a PLY file)");
    const bool ascii = format == "ascii";
    const bool big = format == "binary_big_endian";
    if (!ascii && !big && format != "binary_little_endian") fail(file, "unknown PLY format '" + format + "'");

    // What is read: the vertex element's x, y, z; the face element's vertex_indices (or vertex_index) and
    // the tristrips element's vertex_indices. Other elements and properties are walked over.
    std::uint64_t vertex_count = 0;
    const ply_element* vertex = nullptr;
    for (const ply_element& e : elements)
        if (e.name == "vertex" && !vertex) { vertex = &e; vertex_count = e.count; }
    if (!vertex) fail(file, "has no 'element vertex' in its PLY header");
    int xyz[3];
    for (int a = 0; a < 3; ++a) {
        const std::string name(1, char('x' + a));
        xyz[a] = vertex->find(name);
        if (xyz[a] < 0) fail(file, "the PLY vertex element has no '" + name + "' property (vertices need x, y and z)");
        if (vertex->properties[std::size_t(xyz[a])].is_list) fail(file, "the PLY vertex property '" + name + "' is a list");
    }
    if (vertex_count > std::uint64_t(invalid_id)) fail(file, "declares more vertices than 32-bit indices can number");
    const auto index_list = [&](const ply_element& e) {
        int k = e.find("vertex_indices");
        if (k < 0) k = e.find("vertex_index");
        if (k < 0 || !e.properties[std::size_t(k)].is_list)
            fail(file, "the PLY " + e.name + " element has no 'vertex_indices' list");
        return k;
    };

    const auto missing = [&](const ply_element& e, std::uint64_t i) {
        fail(file, "truncated: the header declares " + with_thousands(e.count) + " " + e.name +
                       " elements, the data ends at " + e.name + " " + with_thousands(i));
    };
    if (ascii) {
        // One element per line: first the number of data lines against the declared counts (a file that
        // declares billions of faces is refused before anything is allocated).
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
    } else {
        // Binary: elements of fixed-size records are checked against the file size before anything is read.
        std::uint64_t at = std::min<std::uint64_t>(pos, data.size());
        for (const ply_element& e : elements) {
            if (std::any_of(e.properties.begin(), e.properties.end(), [](const ply_property& p) { return p.is_list; }))
                break;  // its size is known only by walking it
            std::uint64_t stride = 0;
            for (const ply_property& p : e.properties) stride += std::uint64_t(ply_type_size(p.value_type));
            if (stride > 0 && e.count > (data.size() - at) / stride) missing(e, (data.size() - at) / stride);
            at += e.count * stride;
        }
    }

    const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
    const std::uint64_t size = data.size();
    std::uint64_t at = std::min<std::uint64_t>(pos, size);
    ply_record r;
    std::vector<std::string> tokens;
    std::vector<std::size_t> list_counts;  // ASCII: the record's list lengths
    // Reads record i of element e into r, or fails naming what is wrong with it.
    const auto read_record = [&](const ply_element& e, std::uint64_t i) {
        r.values.clear();
        r.begin.clear();
        r.count.clear();
        if (ascii) {
            std::string text;
            while (text.find_first_not_of(" \t\r") == std::string::npos) {
                if (pos >= data.size()) missing(e, i);
                std::size_t eol = data.find('\n', pos);
                if (eol == std::string::npos) eol = data.size();
                text = data.substr(pos, eol - pos);
                pos = eol + 1;
            }
            std::istringstream line(text);
            tokens.clear();
            for (std::string v; line >> v;) tokens.push_back(v);
            std::size_t need = 0;
            bool counted = true;
            list_counts.clear();
            for (const ply_property& p : e.properties) {
                if (!p.is_list) { ++need; continue; }
                long long n = -1;
                if (need < tokens.size()) n = std::atoll(tokens[need].c_str());
                if (n < 0 || std::uint64_t(n) > tokens.size()) { counted = false; break; }
                list_counts.push_back(std::size_t(n));
                need += 1 + std::size_t(n);
            }
            if (!counted || tokens.size() != need || need == 0)
                fail(file, e.name + " " + with_thousands(i) + " has " + std::to_string(tokens.size()) +
                               " values, its properties need " + std::to_string(need));
            std::size_t t = 0;
            const auto value = [&](ply_type type) {
                double v = 0.0;
                if (!read_ascii(tokens[t], type, v))
                    fail(file, e.name + " " + with_thousands(i) + ": '" + tokens[t] + "' is not a number");
                ++t;
                return v;
            };
            std::size_t list = 0;
            for (const ply_property& p : e.properties) {
                if (p.is_list) value(p.count_type);  // a number, checked; its value is the one counted above
                const std::size_t n = p.is_list ? list_counts[list++] : 1;
                r.begin.push_back(r.values.size());
                r.count.push_back(n);
                for (std::size_t k = 0; k < n; ++k) r.values.push_back(value(p.value_type));
            }
        } else {
            for (const ply_property& p : e.properties) {
                std::uint64_t n = 1;
                if (p.is_list) {
                    const auto count_size = std::uint64_t(ply_type_size(p.count_type));
                    if (count_size > size - at) missing(e, i);
                    const double c = read_binary(bytes + at, p.count_type, big);
                    at += count_size;
                    // A negative signed count reads as a huge one here and is reported as truncation.
                    n = c >= 0.0 && c < 1e18 ? std::uint64_t(c) : std::numeric_limits<std::uint64_t>::max();
                }
                const auto value_size = std::uint64_t(ply_type_size(p.value_type));
                if (n > (size - at) / value_size) missing(e, i);
                r.begin.push_back(r.values.size());
                r.count.push_back(std::size_t(n));
                for (std::uint64_t k = 0; k < n; ++k, at += value_size) r.values.push_back(read_binary(bytes + at, p.value_type, big));
            }
        }
    };
    // A corner index of element e's record i: a whole number naming one of the vertices.
    const auto vertex_index = [&](const ply_element& e, std::uint64_t i, double v) {
        if (!(v >= 0.0 && v < double(vertex_count)) || v != std::floor(v))
            fail(file, e.name + " " + with_thousands(i) + " refers to vertex " +
                           (v == std::floor(v) && std::abs(v) < 1e18 ? std::to_string(std::int64_t(v)) : std::to_string(v)) +
                           ", but the file has " + with_thousands(vertex_count) + " vertices (index out of range)");
        return std::uint32_t(v);
    };

    ply_contents out;
    out.positions.reserve(std::size_t(std::min<std::uint64_t>(vertex_count, size)));
    for (const ply_element& e : elements) {
        const bool is_vertex = &e == vertex, is_face = e.name == "face", is_strip = e.name == "tristrips";
        const int list = is_face || is_strip ? index_list(e) : -1;
        for (std::uint64_t i = 0; i < e.count; ++i) {
            read_record(e, i);
            if (is_vertex) {
                out.positions.emplace_back(float(r.values[r.begin[std::size_t(xyz[0])]]),
                                           float(r.values[r.begin[std::size_t(xyz[1])]]),
                                           float(r.values[r.begin[std::size_t(xyz[2])]]));
            } else if (is_face) {
                const std::size_t b = r.begin[std::size_t(list)], n = r.count[std::size_t(list)];
                if (n == 0) fail(file, "face " + with_thousands(i) + " has no vertices");
                for (std::size_t k = 0; k < n; ++k) out.corners.push_back(vertex_index(e, i, r.values[b + k]));
                out.order.emplace_back(false, out.sizes.size());
                out.sizes.push_back(std::uint32_t(n));
            } else if (is_strip) {
                // -1 restarts the strip; any other negative index is out of range.
                const std::size_t b = r.begin[std::size_t(list)], n = r.count[std::size_t(list)];
                out.order.emplace_back(true, out.strip_begin.size());
                out.strip_begin.push_back(out.strips.size());
                out.strip_size.push_back(n);
                for (std::size_t k = 0; k < n; ++k)
                    out.strips.push_back(r.values[b + k] == -1.0 ? invalid_id : vertex_index(e, i, r.values[b + k]));
            }
        }
    }
    return out;
}

// A PLY file as one mesh: faces and strips in file order, each face's polygon triangulated in place (a
// triangle as it is; a quad as assimp's aiProcess_Triangulate splits it, a b c and a c d unless a corner
// other than a is concave, in which case the fan starts there; a polygon of five or more corners as a fan
// from its first corner, a b c, a c d, a d e, ..., right for the convex polygons PLY files hold). A strip
// a b c d e ... gives a b c, c b d, c d e, e d f, ...: every other triangle swaps its first two corners so
// that all face one way; -1 restarts the strip, and the next triangle is again an even one. Triangles that
// repeat a corner (which strips use to join strips) are kept as the strip says, though they have no area.
// Faces of one or two corners are skipped (counted as points and lines).
triangle_mesh ply_mesh(const std::filesystem::path& file, std::size_t& skipped) {
    const ply_contents ply = read_ply(file);
    triangle_mesh out;
    welder weld(out);
    const auto corner = [&](std::uint32_t raw) {
        const vec3& p = ply.positions[raw];
        if (!is_finite(p)) fail(file, "vertex " + with_thousands(raw) + " has a non-finite coordinate (NaN or Inf)");
        return weld.index(p);
    };
    const auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        uvec3 t;  // one corner after another: vertices are numbered in order of first use
        t.x = corner(a);
        t.y = corner(b);
        t.z = corner(c);
        out.indices.push_back(t);
    };
    std::vector<std::size_t> face_begin(ply.sizes.size());
    for (std::size_t f = 1; f < ply.sizes.size(); ++f) face_begin[f] = face_begin[f - 1] + ply.sizes[f - 1];
    for (const auto& [is_strip, which] : ply.order) {
        if (is_strip) {
            const std::uint32_t* s = ply.strips.data() + ply.strip_begin[which];
            std::size_t run = 0;  // corners since the last restart
            for (std::size_t k = 0; k < ply.strip_size[which]; ++k) {
                if (s[k] == invalid_id) { run = 0; continue; }
                if (++run < 3) continue;
                if (run % 2 == 1) emit(s[k - 2], s[k - 1], s[k]);  // the strip's 1st, 3rd, ... triangle
                else emit(s[k - 1], s[k - 2], s[k]);
            }
            continue;
        }
        const std::uint32_t* c = ply.corners.data() + face_begin[which];
        const std::uint32_t n = ply.sizes[which];
        if (n < 3) { ++skipped; continue; }
        std::uint32_t start = 0;
        if (n == 4) {
            // assimp's rule, with assimp's own vector type so that it decides alike.
            for (std::uint32_t i = 0; i < 4; ++i) {
                const auto at = [&](std::uint32_t k) { const vec3& p = ply.positions[c[k % 4]]; return aiVector3D(p.x, p.y, p.z); };
                aiVector3D left = at(i + 3) - at(i), diag = at(i + 2) - at(i), right = at(i + 1) - at(i);
                left.Normalize();
                diag.Normalize();
                right.Normalize();
                if (std::acos(left * diag) + std::acos(right * diag) > AI_MATH_PI_F) { start = i; break; }
            }
        }
        for (std::uint32_t k = 1; k + 1 < n; ++k) emit(c[start], c[(start + k) % n], c[(start + k + 1) % n]);
    }
    return out;
}

bool is_ply(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    return lower_extension(file) == ".ply" || (in.gcount() == 4 && std::string(magic, 4) == "ply\n");
}

// ---- OBJ: a line-by-line check before assimp reads the file. assimp 5.2 skips a vertex line without three
// numbers (so later indices point at the wrong vertices or past the end), reads a whole number it cannot
// hold in 64 bits as 0 or as a wrapped value, and takes minutes to triangulate a polygon of 100,000
// corners. Each is refused here, naming the line; so are bad indices (assimp refuses those too, without
// the line).

// A number as assimp's OBJ reader takes it: an optional sign, then nan, inf or infinity (any case), or
// digits with an optional fraction after '.' or ',' and an optional exponent. Its whole part and its
// exponent must fit in 64 bits (assimp reads them as 64-bit integers).
enum class obj_number { ok, malformed, too_long };
obj_number check_obj_number(std::string_view t) {
    if (!t.empty() && (t[0] == '+' || t[0] == '-')) t.remove_prefix(1);
    std::string lower(t);
    for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (lower == "nan" || lower == "inf" || lower == "infinity") return obj_number::ok;
    // A run of digits that assimp's 64-bit reader takes right: at most 2^64 - 1 once leading zeros go.
    const auto fits = [](std::string_view digits) {
        digits.remove_prefix(std::min(digits.find_first_not_of('0'), digits.size()));
        return digits.size() < 20 || (digits.size() == 20 && digits <= "18446744073709551615");
    };
    std::size_t i = 0;
    const auto digits = [&] {
        const std::size_t from = i;
        while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) ++i;
        return t.substr(from, i - from);
    };
    const std::string_view whole = digits();
    std::string_view fraction;
    if (i < t.size() && (t[i] == '.' || t[i] == ',')) { ++i; fraction = digits(); }
    if (whole.empty() && fraction.empty()) return obj_number::malformed;
    if (!fits(whole)) return obj_number::too_long;
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
        ++i;
        if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
        const std::string_view exponent = digits();
        if (exponent.empty()) return obj_number::malformed;
        if (!fits(exponent)) return obj_number::too_long;
    }
    return i == t.size() ? obj_number::ok : obj_number::malformed;
}

void obj_check(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::uint64_t vertices = 0;           // 'v' lines so far
    std::uint64_t last_line = 0, highest = 0;  // the highest absolute vertex index, and its line
    std::string line, text;
    std::vector<std::string_view> tokens;
    for (std::uint64_t number = 1, next = 1; std::getline(in, text); number = next) {
        // A line ending in a backslash continues on the next one.
        line = text;
        ++next;
        while (!line.empty() && (line.back() == '\r' || line.back() == '\\')) {
            const bool continued = line.back() == '\\';
            line.pop_back();
            if (continued && std::getline(in, text)) { line += ' '; line += text; ++next; }
        }
        if (const std::size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        tokens.clear();
        for (std::size_t p = line.find_first_not_of(" \t"); p != std::string::npos;) {
            const std::size_t end = std::min(line.find_first_of(" \t", p), line.size());
            tokens.emplace_back(line.data() + p, end - p);
            p = line.find_first_not_of(" \t", end);
        }
        if (tokens.empty()) continue;
        const std::string where = "line " + with_thousands(number) + ": ";
        if (tokens[0] == "v") {
            for (std::size_t k = 1; k < tokens.size(); ++k) {
                const obj_number n = check_obj_number(tokens[k]);
                if (n == obj_number::malformed) fail(file, where + "'" + std::string(tokens[k]) + "' is not a number");
                if (n == obj_number::too_long)
                    fail(file, where + "the number '" + std::string(tokens[k]) + "' has more digits before its point "
                                       "(or in its exponent) than the OBJ reader (assimp) reads right, which would "
                                       "give 0 or a wrapped value; write it with an exponent, as in 1e20");
            }
            const std::size_t n = tokens.size() - 1;
            if (n != 3 && n != 4 && n != 6)
                fail(file, where + "a vertex line needs three numbers (x y z), optionally followed by w or by r g b; "
                                   "this one has " + std::to_string(n));
            ++vertices;
        } else if (tokens[0] == "f" || tokens[0] == "l" || tokens[0] == "p") {
            if (tokens[0] == "f" && tokens.size() - 1 > max_polygon_corners)
                fail(file, where + "the polygon " + too_many_corners(tokens.size() - 1));
            for (std::size_t k = 1; k < tokens.size(); ++k) {
                // The vertex index is the corner's first field: v, v/vt, v//vn or v/vt/vn.
                std::string_view index = tokens[k].substr(0, tokens[k].find('/'));
                const bool negative = !index.empty() && index[0] == '-';
                if (negative || (!index.empty() && index[0] == '+')) index.remove_prefix(1);
                std::uint64_t value = 0;
                const auto r = std::from_chars(index.data(), index.data() + index.size(), value);
                if (index.empty() || r.ptr != index.data() + index.size())
                    fail(file, where + "'" + std::string(tokens[k]) + "' is not a vertex index");
                if (r.ec == std::errc::result_out_of_range) value = std::numeric_limits<std::uint64_t>::max();
                if (value == 0) fail(file, where + "vertex index 0 (OBJ numbers vertices from 1, or from -1 backwards)");
                if (negative && value > vertices)
                    fail(file, where + "vertex index -" + std::to_string(value) + " is out of range: only " +
                                   with_thousands(vertices) + " vertices come before it");
                if (!negative && value > highest) { highest = value; last_line = number; }
            }
        }
    }
    // Absolute indices may name vertices defined later in the file (assimp accepts that).
    if (highest > vertices)
        fail(file, "line " + with_thousands(last_line) + ": vertex index " + std::to_string(highest) +
                       " is out of range: the file has " + with_thousands(vertices) + " vertices");
}

// ---- glTF and GLB: checks before assimp reads the file. assimp 5.2 allocates whatever a GLB's chunk
// length says (4 GB for 0xFFFFFFFF), recurses once per level of node nesting and of JSON nesting (20,000
// nested nodes overflow the stack), and drops faces with an out-of-range index without a word. The header
// and chunk lengths are checked against the file size, the JSON is read here with bounded nesting, the
// node tree is walked for its depth and for cycles, and each primitive's face count is kept so that a
// face assimp dropped is noticed after it reads the file.

// A small JSON reader, enough for a glTF's structure: strings keep their escapes as written (glTF keys
// and the few strings read here have none).
struct json {
    enum kind_t { null, boolean, number, string, array, object } kind = null;
    double value = 0.0;
    std::string text;
    std::vector<json> items;                         // array items, or object values
    std::vector<std::string> keys;                   // object keys, one per item
    const json* get(const std::string& key) const {
        if (kind != object) return nullptr;
        for (std::size_t i = 0; i < keys.size(); ++i)
            if (keys[i] == key) return &items[i];
        return nullptr;
    }
};

// The deepest JSON nesting accepted (the reader above recurses once per level) and the deepest node tree
// (assimp's glTF importer and post-processing recurse once per level; 20,000 overflow the stack): far more
// than any real file needs.
constexpr int max_json_depth = 1000;
constexpr std::size_t max_node_depth = 1000;

class json_reader {
public:
    json_reader(const std::filesystem::path& file, std::string_view text) : file_(file), s_(text) {}
    json document() {
        json j = value(0);
        skip_space();
        if (at_ < s_.size()) error("text after the JSON document");
        return j;
    }

private:
    [[noreturn]] void error(const std::string& what) {
        fail(file_, "malformed glTF JSON at byte " + with_thousands(at_) + ": " + what);
    }
    void skip_space() {
        while (at_ < s_.size() && (s_[at_] == ' ' || s_[at_] == '\t' || s_[at_] == '\n' || s_[at_] == '\r')) ++at_;
    }
    void expect(char c) {
        skip_space();
        if (at_ >= s_.size() || s_[at_] != c) error(std::string("expected '") + c + "'");
        ++at_;
    }
    std::string string_body() {
        expect('"');
        const std::size_t from = at_;
        while (at_ < s_.size() && s_[at_] != '"') at_ += s_[at_] == '\\' ? 2 : 1;
        if (at_ >= s_.size()) error("unterminated string");
        return std::string(s_.substr(from, at_++ - from));
    }
    json value(int depth) {
        if (depth > max_json_depth)
            fail(file_, "its JSON is nested more than " + with_thousands(max_json_depth) +
                            " levels deep (no glTF needs that; this check's reader recurses once per level)");
        skip_space();
        if (at_ >= s_.size()) error("unexpected end");
        json j;
        const char c = s_[at_];
        if (c == '{' || c == '[') {
            const bool object = c == '{';
            j.kind = object ? json::object : json::array;
            ++at_;
            skip_space();
            if (at_ < s_.size() && s_[at_] == (object ? '}' : ']')) { ++at_; return j; }
            for (;;) {
                if (object) { j.keys.push_back(string_body()); expect(':'); }
                j.items.push_back(value(depth + 1));
                skip_space();
                if (at_ < s_.size() && s_[at_] == ',') { ++at_; continue; }
                expect(object ? '}' : ']');
                return j;
            }
        }
        if (c == '"') { j.kind = json::string; j.text = string_body(); return j; }
        for (const char* word : {"true", "false", "null"}) {
            if (s_.substr(at_, std::strlen(word)) == word) {
                at_ += std::strlen(word);
                j.kind = word[0] == 'n' ? json::null : json::boolean;
                j.value = word[0] == 't';
                return j;
            }
        }
        const char* first = s_.data() + at_;
        const auto r = std::from_chars(first, s_.data() + s_.size(), j.value);
        if (r.ec == std::errc::invalid_argument || r.ptr == first) error("unexpected character");
        j.kind = json::number;
        at_ += std::size_t(r.ptr - first);
        return j;
    }

    const std::filesystem::path& file_;
    std::string_view s_;
    std::size_t at_ = 0;
};

std::uint32_t little_u32(const std::string& s, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= std::uint32_t(static_cast<unsigned char>(s[at + std::size_t(i)])) << (8 * i);
    return v;
}

// What a glTF 2.0 file says its primitives hold: per primitive, in the order assimp makes them meshes
// (mesh by mesh, primitive by primitive), the number of faces its index accessor makes, or -1 where no
// face can be dropped (no indices) or the count is not known.
struct gltf_expectation {
    std::vector<long long> faces;
    std::vector<std::string> names;  // "mesh 2, primitive 0"
};

gltf_expectation gltf_check(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::string_view text = data;
    if (data.compare(0, 4, "glTF") == 0) {
        // GLB: a 12-byte header (magic, version, total length), then chunks of (length, type, data);
        // version 1 has one content chunk described in a 20-byte header.
        if (data.size() < 20) fail(file, "is a GLB file of " + with_thousands(data.size()) + " bytes, too short for its header");
        const std::uint32_t version = little_u32(data, 4), length = little_u32(data, 8);
        if (length > data.size())
            fail(file, "its GLB header says the file has " + with_thousands(length) + " bytes, but it has " +
                           with_thousands(data.size()) + " (truncated or corrupt)");
        if (version == 1) {
            const std::uint32_t content = little_u32(data, 12);
            if (content > length - 20)
                fail(file, "its GLB header says the JSON content has " + with_thousands(content) +
                               " bytes, but only " + with_thousands(length - 20) + " follow the header");
            text = text.substr(20, content);
        } else {
            const std::uint32_t json_length = little_u32(data, 12), type = little_u32(data, 16);
            if (type != 0x4E4F534Au) fail(file, "its first GLB chunk is not the JSON chunk");
            if (json_length > length - 20)
                fail(file, "its GLB JSON chunk says it has " + with_thousands(json_length) + " bytes, but only " +
                               with_thousands(length - 20) + " follow its chunk header");
            text = text.substr(20, json_length);
            for (std::uint64_t at = 20 + std::uint64_t(json_length); at < length;) {
                if (length - at < 8) fail(file, "its GLB data ends inside a chunk header");
                const std::uint32_t chunk = little_u32(data, std::size_t(at));
                if (chunk > length - at - 8)
                    fail(file, "a GLB chunk says it has " + with_thousands(chunk) + " bytes, but only " +
                                   with_thousands(length - at - 8) + " follow its chunk header");
                at += 8 + std::uint64_t(chunk);
            }
        }
    }
    const json doc = json_reader(file, text).document();
    if (doc.kind != json::object) fail(file, "its glTF JSON is not an object");

    // The node tree: depth (a chain of nodes each the child of the one before is as deep as it is long)
    // and cycles, walked without recursion. glTF 2.0 lists nodes in an array and names children by index;
    // glTF 1.0 keeps them in an object and names them by key.
    if (const json* nodes = doc.get("nodes"); nodes && (nodes->kind == json::array || nodes->kind == json::object)) {
        const std::size_t n = nodes->items.size();
        const auto node_name = [&](std::size_t i) {
            return nodes->kind == json::array ? "node " + std::to_string(i) : "node '" + nodes->keys[i] + "'";
        };
        std::vector<std::vector<std::size_t>> children(n);
        for (std::size_t i = 0; i < n; ++i) {
            const json* list = nodes->items[i].get("children");
            if (!list || list->kind != json::array) continue;
            for (const json& c : list->items) {
                std::size_t child = n;
                if (c.kind == json::number && c.value >= 0 && c.value < double(n) && c.value == std::floor(c.value))
                    child = std::size_t(c.value);
                if (c.kind == json::string)
                    child = std::size_t(std::find(nodes->keys.begin(), nodes->keys.end(), c.text) - nodes->keys.begin());
                if (child >= n) fail(file, node_name(i) + " lists a child that is not one of the " + with_thousands(n) + " nodes");
                children[i].push_back(child);
            }
        }
        // Post-order walk: height[i] = 1 + the largest height of its children, once all are known.
        enum : char { unseen, open, done };
        std::vector<char> state(n, unseen);
        std::vector<std::size_t> height(n, 1);
        std::vector<std::pair<std::size_t, std::size_t>> stack;  // (node, next child to visit)
        std::size_t deepest = 0;
        for (std::size_t root = 0; root < n; ++root) {
            if (state[root] != unseen) continue;
            stack.emplace_back(root, 0);
            state[root] = open;
            while (!stack.empty()) {
                auto& [node, next] = stack.back();
                if (next < children[node].size()) {
                    const std::size_t child = children[node][next++];
                    if (state[child] == open)
                        fail(file, node_name(child) + " is its own descendant (a cycle in the node tree)");
                    if (state[child] == unseen) { state[child] = open; stack.emplace_back(child, 0); }
                    continue;
                }
                for (const std::size_t child : children[node]) height[node] = std::max(height[node], height[child] + 1);
                deepest = std::max(deepest, height[node]);
                state[node] = done;
                stack.pop_back();
            }
        }
        if (deepest > max_node_depth)
            fail(file, "its nodes are nested " + with_thousands(deepest) + " levels deep, more than the " +
                           with_thousands(max_node_depth) + " accepted (assimp recurses once per level)");
    }

    // Each primitive's face count, from its index accessor's count and its mode (glTF 2.0 only).
    gltf_expectation expect;
    const json* meshes = doc.get("meshes");
    const json* accessors = doc.get("accessors");
    if (!meshes || meshes->kind != json::array) return expect;
    for (std::size_t m = 0; m < meshes->items.size(); ++m) {
        const json* primitives = meshes->items[m].get("primitives");
        if (!primitives || primitives->kind != json::array) continue;
        for (std::size_t p = 0; p < primitives->items.size(); ++p) {
            const json& prim = primitives->items[p];
            const std::string name = "mesh " + std::to_string(m) + ", primitive " + std::to_string(p);
            long long faces = -1;
            const json* indices = prim.get("indices");
            const json* mode = prim.get("mode");
            const int kind = mode && mode->kind == json::number ? int(mode->value) : 4;
            if (indices && indices->kind == json::number && accessors && accessors->kind == json::array &&
                indices->value >= 0 && indices->value < double(accessors->items.size())) {
                const json* count = accessors->items[std::size_t(indices->value)].get("count");
                if (count && count->kind == json::number && count->value >= 0 && count->value < 9e15) {
                    const auto c = static_cast<long long>(count->value);
                    switch (kind) {
                        case 0: faces = c; break;                        // points
                        case 1: faces = c / 2; break;                    // lines
                        case 2: faces = c; break;                        // line loop
                        case 3: faces = std::max(0LL, c - 1); break;     // line strip
                        case 4:                                          // triangles
                            if (c % 3 != 0)
                                fail(file, name + " has " + with_thousands(std::size_t(c)) +
                                               " indices, not a whole number of triangles");
                            faces = c / 3;
                            break;
                        case 5: case 6: faces = std::max(0LL, c - 2); break;  // strip, fan
                        default: break;
                    }
                }
            }
            expect.faces.push_back(faces);
            expect.names.push_back(name);
        }
    }
    return expect;
}

bool is_gltf(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    const std::string ext = lower_extension(file);
    return ext == ".gltf" || ext == ".glb" || (in.gcount() == 4 && std::string(magic, 4) == "glTF");
}

// ---- After assimp reads the file: indices in range, referenced vertices finite, polygons of a size
// assimp can triangulate, and (glTF) every face the file holds, before any post-process touches them.
void check_raw_meshes(const std::filesystem::path& file, const aiScene& s, const gltf_expectation& expect) {
    if (expect.faces.size() == s.mNumMeshes) {
        for (unsigned m = 0; m < s.mNumMeshes; ++m)
            if (expect.faces[m] >= 0 && (long long)s.mMeshes[m]->mNumFaces < expect.faces[m])
                fail(file, expect.names[m] + ": " + with_thousands(std::size_t(expect.faces[m] - s.mMeshes[m]->mNumFaces)) +
                               " of its " + with_thousands(std::size_t(expect.faces[m])) +
                               " faces refer to a vertex beyond its " + with_thousands(s.mMeshes[m]->mNumVertices) +
                               " vertices (index out of range)");
    }
    for (unsigned m = 0; m < s.mNumMeshes; ++m) {
        const aiMesh& mesh = *s.mMeshes[m];
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            const std::string which = "face " + with_thousands(f) + " of mesh " + std::to_string(m);
            if (face.mNumIndices == 0)  // assimp 5.2's triangulation aborts on these
                fail(file, which + " has no vertices");
            if (face.mNumIndices > max_polygon_corners) fail(file, which + " " + too_many_corners(face.mNumIndices));
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                const unsigned idx = face.mIndices[k];
                if (idx >= mesh.mNumVertices)
                    fail(file, which + " refers to vertex " + std::to_string(idx) + ", but the mesh has " +
                                   with_thousands(mesh.mNumVertices) + " vertices (index out of range)");
                const aiVector3D& p = mesh.mVertices[idx];
                if (!is_finite(vec3(p.x, p.y, p.z)))
                    fail(file, "vertex " + with_thousands(idx) + " of mesh " + std::to_string(m) +
                                   " has a non-finite coordinate (NaN or Inf)");
            }
        }
    }
}

// ---- Meshes in node order with accumulated transforms, walked without recursion (depth first, a node's
// own meshes before its children). Each mesh instance's corners are welded where bit-identical.
struct gatherer {
    const aiScene& scene;
    triangle_mesh out;
    std::size_t skipped = 0;  // points and lines

    void add(const aiNode& node, const aiMatrix4x4& world) {
        // Exactly the identity: aiMatrix4x4::IsIdentity allows 0.01 off, which would drop a small translation.
        const bool identity = world == aiMatrix4x4();
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
            triangle_mesh part;
            welder weld(part);
            for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
                const aiFace& face = mesh.mFaces[f];
                if (face.mNumIndices != 3) { ++skipped; continue; }
                uvec3 tri;
                for (int k = 0; k < 3; ++k) {
                    const unsigned v = face.mIndices[k];
                    const aiVector3D p = identity ? mesh.mVertices[v] : world * mesh.mVertices[v];
                    weld.begin(vec3(p.x, p.y, p.z));
                    if (mesh.mNormals) weld.add(&mesh.mNormals[v].x, 3);
                    for (unsigned c = 0; c < AI_MAX_NUMBER_OF_TEXTURECOORDS && mesh.mTextureCoords[c]; ++c)
                        weld.add(&mesh.mTextureCoords[c][v].x, 3);
                    for (unsigned c = 0; c < AI_MAX_NUMBER_OF_COLOR_SETS && mesh.mColors[c]; ++c)
                        weld.add(&mesh.mColors[c][v].r, 4);
                    tri[k] = weld.index();
                }
                part.indices.push_back(tri);
            }
            out.append(part);
        }
    }
    void walk(const aiNode& root) {
        // The root's transform as the recursive walk had it, identity times the node's (bit for bit the same
        // world transforms as before).
        std::vector<std::pair<const aiNode*, aiMatrix4x4>> stack{{&root, aiMatrix4x4() * root.mTransformation}};
        while (!stack.empty()) {
            const auto [node, world] = stack.back();
            stack.pop_back();
            add(*node, world);
            for (unsigned c = node->mNumChildren; c-- > 0;)  // pushed in reverse: visited in order
                stack.emplace_back(node->mChildren[c], world * node->mChildren[c]->mTransformation);
        }
    }
};

}  // namespace

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
        // Step 2: checks before assimp (OBJ and glTF); steps 3 to 6: read, check, triangulate, gather.
        gltf_expectation expect;
        if (lower_extension(file) == ".obj") obj_check(file);
        if (is_gltf(file)) expect = gltf_check(file);
        Assimp::Importer importer;
        const aiScene* s = importer.ReadFile(file.string(), 0);
        if (!s) fail(file, std::string("cannot be read (assimp: ") + importer.GetErrorString() + ")");
        if ((s->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !s->mRootNode || s->mNumMeshes == 0)
            fail(file, "contains no triangles (no meshes found; malformed or not a mesh file)");
        check_raw_meshes(file, *s, expect);
        s = importer.ApplyPostProcessing(aiProcess_Triangulate);
        if (!s) fail(file, std::string("cannot be processed (assimp: ") + importer.GetErrorString() + ")");
        gatherer g{*s, {}, 0};
        g.walk(*s->mRootNode);
        mesh = std::move(g.out);
        skipped = g.skipped;
        for (const vec3& p : mesh.positions)
            if (!is_finite(p)) fail(file, "a node transform makes a coordinate non-finite (NaN or Inf)");
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
