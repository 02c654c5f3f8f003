// Mesh files written at test time, for the scene loader's tests (tests/common/test_scene_*.cpp): a file
// from text, a small ASCII PLY header, and glTF and GLB files of one mesh with their buffer embedded.
#pragma once
#include "strahl/scene.hpp"
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace strahl::test {

// dir/name holding text, byte for byte.
inline std::filesystem::path write_file(const std::filesystem::path& dir, const std::string& name,
                                        const std::string& text) {
    const std::filesystem::path p = dir / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
}

// An ASCII PLY's header for 3 vertices (x, y, z) and 1 face: the data lines follow.
inline const std::string ply_header_3v1f =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

// Base64 (RFC 4648, with padding), as a glTF data: URI holds a buffer.
inline std::string base64(const std::string& bytes) {
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

// value's bytes as they are in memory (little endian here, as glTF wants).
template <class T> inline void append_raw(std::string& out, const T& value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// The binary buffer of a glTF mesh: float positions, then unsigned short indices.
inline std::string gltf_buffer(const std::vector<vec3>& positions, const std::vector<std::uint16_t>& indices) {
    std::string bin;
    for (const vec3& p : positions) { append_raw(bin, p.x); append_raw(bin, p.y); append_raw(bin, p.z); }
    for (const std::uint16_t i : indices) append_raw(bin, i);
    while (bin.size() % 4 != 0) bin += '\0';
    return bin;
}

// The JSON of a one-mesh glTF whose buffer (positions, then indices) is `uri` (empty: a GLB's own chunk),
// with the given "nodes" array and scene roots.
inline std::string gltf_json(std::size_t vertices, std::size_t indices, std::size_t buffer_bytes,
                             const std::string& uri, const std::string& nodes = R"([{"mesh":0}])",
                             const std::string& roots = "[0]") {
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

// A .gltf of one mesh, its buffer embedded as a base64 data: URI.
inline std::string gltf_text(const std::vector<vec3>& positions, const std::vector<std::uint16_t>& indices,
                             const std::string& nodes = R"([{"mesh":0}])") {
    const std::string bin = gltf_buffer(positions, indices);
    return gltf_json(positions.size(), indices.size(), bin.size(),
                     "data:application/octet-stream;base64," + base64(bin), nodes);
}

// A binary glTF: 12-byte header, a JSON chunk padded with spaces, a BIN chunk padded with zeros.
inline std::string glb(const std::vector<vec3>& positions, const std::vector<std::uint16_t>& indices) {
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

// A unit square in z = 0, corners counter-clockwise from the origin.
inline const std::vector<vec3> unit_quad = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)};

// Seconds of wall time since start.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace strahl::test
