// The scene loader's step 3 for glTF and GLB: checks before assimp reads the file (scene.cpp's top comment
// lists the loader's steps). assimp 5.2 allocates whatever a GLB's chunk length says (4 GB for
// 0xFFFFFFFF), recurses once per level of node nesting and of JSON nesting (20,000 nested nodes overflow
// the stack), and drops faces with an out-of-range index without a word. The header and chunk lengths are
// checked against the file size, the JSON is read here with bounded nesting, the node tree is walked for
// its depth and for cycles, and each primitive's face count is kept so that a face assimp dropped is
// noticed after it reads the file. (Formats: the Khronos glTF 2.0 specification, sections 3 and 4.4 on
// GLB; glTF 1.0 for its object of nodes. JSON: RFC 8259.)
//
// The JSON is read with nlohmann-json's SAX interface (nlohmann::json::sax_parse, a handler deriving from
// nlohmann::json_sax): the parser calls the handler once per value, key and bracket, without recursing
// itself, so the nesting depth is checked as the text is read, before anything deep is built. The handler
// keeps only what the checks read (kept_paths below: the nodes' children, each primitive's indices and
// mode, each accessor's count) in a small nlohmann::ordered_json document; everything else (buffers in
// base64, extras, materials, ...) is checked for syntax and depth, then dropped. What is kept is a few
// values per node, primitive and accessor, so its memory is bounded by the file's size with a small factor.
// (A whole DOM after a depth pre-pass would hold every number of an "extras" array as a 16-byte value.)
#include "scene_detail.hpp"
#include <nlohmann/json.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace strahl::scene_detail {

namespace {

// The deepest JSON nesting accepted (assimp's JSON reader, rapidjson, recurses once per level) and the
// deepest node tree (assimp's glTF importer and post-processing recurse once per level; 20,000 overflow
// the stack): far more than any real file needs.
constexpr std::size_t max_json_depth = 1000;
constexpr std::size_t max_node_depth = 1000;

using json = nlohmann::ordered_json;  // objects keep their keys in file order (glTF 1.0's nodes are named)

// The values the checks read, by their path from the document's root; "*" stands for any key or index.
// A value is kept when its path leads along one of these (a container on the way keeps only what leads on).
const std::array<std::vector<std::string_view>, 4> kept_paths = {{
    {"nodes", "*", "children", "*"},  // the node tree (glTF 2.0: an array of nodes; 1.0: an object of them)
    {"meshes", "*", "primitives", "*", "indices"},
    {"meshes", "*", "primitives", "*", "mode"},
    {"accessors", "*", "count"},
}};

// The SAX handler: checks the nesting depth as the parser reads, and builds the kept part of the document.
// Numbers are kept as doubles, as the checks compare them (exact for whole numbers up to 2^53). Where an
// object repeats a key, the first value counts (and a glTF 1.0 node named twice is one node).
class gltf_json_reader final : public nlohmann::json_sax<nlohmann::json> {
public:
    explicit gltf_json_reader(const std::filesystem::path& file) : file_(file) {}
    json& document() { return document_; }

    bool null() override { return scalar(nullptr); }
    bool boolean(bool value) override { return scalar(value); }
    bool number_integer(number_integer_t value) override { return scalar(double(value)); }
    bool number_unsigned(number_unsigned_t value) override { return scalar(double(value)); }
    bool number_float(number_float_t value, const string_t&) override { return scalar(value); }
    bool string(string_t& value) override { return scalar(std::move(value)); }
    bool binary(binary_t&) override { return scalar(nullptr); }  // (only the binary formats have these)
    bool start_object(std::size_t) override { return open(json::object()); }
    bool start_array(std::size_t) override { return open(json::array()); }
    bool key(string_t& key) override {
        levels_.back().key = std::move(key);
        return true;
    }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    // position: the bytes read, up to and including the one where reading stopped (nlohmann's byte count).
    bool parse_error(std::size_t position, const std::string&, const nlohmann::json::exception& e) override {
        // e.what() reads "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ...".
        std::string what = e.what();
        const std::string_view at = "parse error at ";
        if (const std::size_t p = what.find(at); p != std::string::npos) what = ", " + what.substr(p + at.size());
        else what = ": " + what;
        fail(file_, "malformed glTF JSON at byte " + with_thousands(position) + what);
    }

private:
    // An open object or array.
    struct level {
        json* kept;                       // where it is kept, or nullptr: its values are dropped
        std::optional<std::string> name;  // its key in its parent object (none: an array item, or the root)
        std::string key;                  // an object's: the key of the value being read
    };

    // Segment k of the path to the value being read: the key it (or its container at depth k + 1) sits
    // under, or nullptr for an array index.
    const std::string* segment(std::size_t k) const {
        if (k + 1 < levels_.size()) return levels_[k + 1].name ? &*levels_[k + 1].name : nullptr;
        return levels_.back().kept->is_object() ? &levels_.back().key : nullptr;
    }
    bool wanted() const {
        const std::size_t length = levels_.size();
        return std::any_of(kept_paths.begin(), kept_paths.end(), [&](const std::vector<std::string_view>& path) {
            if (path.size() < length) return false;
            for (std::size_t k = 0; k < length; ++k) {
                const std::string* s = segment(k);
                if (path[k] != "*" && (!s || *s != path[k])) return false;
            }
            return true;
        });
    }

    // A value begins: checks its depth; returns where it is kept, or nullptr where it is dropped.
    json* place(json&& value) {
        if (levels_.size() > max_json_depth)
            fail(file_, "its JSON is nested more than " + with_thousands(max_json_depth) +
                            " levels deep (no glTF needs that; assimp's JSON reader recurses once per level)");
        if (levels_.empty()) {
            document_ = std::move(value);
            return &document_;
        }
        const level& parent = levels_.back();
        if (!parent.kept || !wanted()) return nullptr;
        if (parent.kept->is_array()) {
            parent.kept->push_back(std::move(value));
            return &parent.kept->back();
        }
        if (parent.kept->contains(parent.key)) return nullptr;  // a repeated key: the first one counts
        return &((*parent.kept)[parent.key] = std::move(value));
    }
    bool scalar(json&& value) {
        place(std::move(value));
        return true;
    }
    bool open(json&& empty) {
        std::optional<std::string> name;
        if (!levels_.empty() && levels_.back().kept && levels_.back().kept->is_object()) name = levels_.back().key;
        json* kept = place(std::move(empty));
        levels_.push_back(level{kept, std::move(name), {}});
        return true;
    }
    bool close() {
        levels_.pop_back();
        return true;
    }

    const std::filesystem::path& file_;
    json document_;
    std::vector<level> levels_;  // the containers open, the root's first
};

// Replaces every byte of [first, last) that is not part of well-formed UTF-8 (the Unicode Standard,
// table 3-7) by '?', one byte for one, so that byte positions stay. nlohmann-json refuses ill-formed UTF-8
// in a string; assimp's reader passes it through (a node named in Latin-1 loads), and so must this check.
void replace_ill_formed_utf8(char* first, char* last) {
    const auto byte = [](const char* p) { return static_cast<unsigned char>(*p); };
    for (char* p = first; p < last;) {
        const unsigned char b = byte(p);
        // The sequence's length, and the range of its second byte (the others are 80..BF).
        std::size_t n = 1;
        unsigned char low = 0x80, high = 0xBF;
        if (b >= 0xC2 && b <= 0xDF) n = 2;
        else if (b >= 0xE0 && b <= 0xEF) n = 3, low = b == 0xE0 ? 0xA0 : 0x80, high = b == 0xED ? 0x9F : 0xBF;
        else if (b >= 0xF0 && b <= 0xF4) n = 4, low = b == 0xF0 ? 0x90 : 0x80, high = b == 0xF4 ? 0x8F : 0xBF;
        else if (b >= 0x80) n = 0;  // a continuation byte without its lead, or C0, C1, F5..FF
        bool ok = n > 0 && std::size_t(last - p) >= n;
        for (std::size_t k = 1; ok && k < n; ++k) {
            const unsigned char c = byte(p + k);
            ok = k == 1 ? c >= low && c <= high : c >= 0x80 && c <= 0xBF;
        }
        if (ok) {
            p += n;
        } else {
            *p = '?';
            ++p;
        }
    }
}

// The member key of an object, or nullptr (also where j is no object).
const json* member(const json& j, const char* key) {
    if (!j.is_object()) return nullptr;
    const auto it = j.find(key);
    return it == j.end() ? nullptr : &*it;
}

std::uint32_t little_u32(const std::string& s, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= std::uint32_t(static_cast<unsigned char>(s[at + std::size_t(i)])) << (8 * i);
    return v;
}

}  // namespace

gltf_expectation gltf_check(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
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
    // The JSON (a .gltf file, or a GLB's JSON chunk), read into what the checks need.
    if (text.substr(0, 3) == "\xEF\xBB\xBF")  // (nlohmann-json would skip it; assimp refuses the file)
        fail(file, "malformed glTF JSON at byte 1: it starts with a byte order mark (glTF's JSON is UTF-8 "
                   "without one)");
    char* const json_begin = data.data() + (text.data() - data.data());  // (text views data)
    replace_ill_formed_utf8(json_begin, json_begin + text.size());
    gltf_json_reader reader(file);
    nlohmann::json::sax_parse(text.data(), text.data() + text.size(), &reader);
    const json& doc = reader.document();
    if (!doc.is_object()) fail(file, "its glTF JSON is not an object");

    // The node tree: depth (a chain of nodes each the child of the one before is as deep as it is long)
    // and cycles, walked without recursion. glTF 2.0 lists nodes in an array and names children by index;
    // glTF 1.0 keeps them in an object and names them by key.
    if (const json* nodes = member(doc, "nodes"); nodes && (nodes->is_array() || nodes->is_object())) {
        const std::size_t n = nodes->size();
        std::vector<const json*> items;
        std::vector<std::string> keys;  // glTF 1.0: the nodes' names
        for (auto it = nodes->begin(); it != nodes->end(); ++it) {
            items.push_back(&*it);
            if (nodes->is_object()) keys.push_back(it.key());
        }
        const auto node_name = [&](std::size_t i) {
            return nodes->is_array() ? "node " + std::to_string(i) : "node '" + keys[i] + "'";
        };
        std::vector<std::vector<std::size_t>> children(n);
        for (std::size_t i = 0; i < n; ++i) {
            const json* list = member(*items[i], "children");
            if (!list || !list->is_array()) continue;
            for (const json& c : *list) {
                std::size_t child = n;
                if (c.is_number()) {
                    const double v = c.get<double>();
                    if (v >= 0 && v < double(n) && v == std::floor(v)) child = std::size_t(v);
                }
                if (c.is_string() && nodes->is_object()) {  // (a name, in glTF 1.0 only)
                    const std::string& key = c.get_ref<const std::string&>();
                    child = std::size_t(std::find(keys.begin(), keys.end(), key) - keys.begin());
                }
                if (child >= n)
                    fail(file, node_name(i) + " lists a child that is not one of the " + with_thousands(n) + " nodes");
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
    const json* meshes = member(doc, "meshes");
    const json* accessors = member(doc, "accessors");
    if (!meshes || !meshes->is_array()) return expect;
    for (std::size_t m = 0; m < meshes->size(); ++m) {
        const json* primitives = member((*meshes)[m], "primitives");
        if (!primitives || !primitives->is_array()) continue;
        for (std::size_t p = 0; p < primitives->size(); ++p) {
            const json& prim = (*primitives)[p];
            const std::string name = "mesh " + std::to_string(m) + ", primitive " + std::to_string(p);
            long long faces = -1;
            const json* indices = member(prim, "indices");
            const json* mode = member(prim, "mode");
            // (A mode beyond int's range is no mode the switch below knows.)
            const double mode_value = mode && mode->is_number() ? mode->get<double>() : 4.0;
            const int kind = std::abs(mode_value) < 1e9 ? int(mode_value) : -1;
            if (indices && indices->is_number() && accessors && accessors->is_array() &&
                indices->get<double>() >= 0 && indices->get<double>() < double(accessors->size())) {
                const json* count = member((*accessors)[std::size_t(indices->get<double>())], "count");
                if (count && count->is_number() && count->get<double>() >= 0 && count->get<double>() < 9e15) {
                    const auto c = static_cast<long long>(count->get<double>());
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

}  // namespace strahl::scene_detail
