// The scene loader's step 2: PLY, read here, not by assimp (format: Greg Turk, "The PLY Polygon File
// Format", 1994). assimp 5.2 reads past the end of a truncated binary PLY (a crash), repeats the last face
// of a short ASCII PLY, keeps one triangle of each triangle strip and puts vertices without x, y or z at 0;
// this reader refuses or reads each of these right. (scene.cpp's top comment lists the loader's steps.)
#include "scene_detail.hpp"
#include <assimp/types.h>  // aiVector3D with its operators, AI_MATH_PI_F
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <utility>

namespace strahl::scene_detail {

namespace {

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

}  // namespace

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

}  // namespace strahl::scene_detail
