// The scene loader's step 3 for OBJ: a line-by-line check before assimp reads the file. assimp 5.2 skips a
// vertex line without three numbers (so later indices point at the wrong vertices or past the end), reads a
// whole number it cannot hold in 64 bits as 0 or as a wrapped value, and takes minutes to triangulate a
// polygon of 100,000 corners. Each is refused here, naming the line; so are bad indices (assimp refuses
// those too, without the line). (Format: Wavefront's OBJ, Appendix B1 of the Advanced Visualizer manual;
// scene.cpp's top comment lists the loader's steps.)
#include "scene_detail.hpp"
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string_view>

namespace strahl::scene_detail {

namespace {

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

}  // namespace

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

}  // namespace strahl::scene_detail
