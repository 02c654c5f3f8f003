// The race's file formats: rays and hits, little-endian binary, so that every structure, every tool and
// every run traces exactly the same rays and can be checked against the same answers.
//
//   rays:  8 bytes magic "STRAHLR1", uint64 count, then per ray 8 float32: ox oy oz tmin dx dy dz tmax
//   hits:  8 bytes magic "STRAHLH1", uint64 count, then per ray: float32 t (+inf for a miss),
//          uint32 primitive id (0xFFFFFFFF for a miss), float32 u, float32 v
//   flags: 8 bytes magic "STRAHLF1", uint64 count, then per ray one byte, 0 or 1 (any-hit: blocked or not)
//
// Reading refuses, with a message naming the file and the first offending record: a wrong magic, a count
// that disagrees with the file's size, NaN anywhere, an infinite origin, direction or tmin (tmax may be
// +inf), an origin or direction component beyond max_coordinate (1e12, scene.hpp), a hit with infinite t but a primitive id (or the reverse), a flag other than 0 or 1.
#pragma once
#include "strahl/ray.hpp"
#include "strahl/scene.hpp"
#include <filesystem>
#include <span>
#include <stdexcept>
#include <vector>

namespace strahl::race {

class format_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

void write_rays(const std::filesystem::path& file, std::span<const ray> rays);
std::vector<ray> read_rays(const std::filesystem::path& file);

// Only t, prim, u and v are stored (the instance id is not part of the format).
void write_hits(const std::filesystem::path& file, std::span<const hit> hits);
std::vector<hit> read_hits(const std::filesystem::path& file);

void write_flags(const std::filesystem::path& file, std::span<const std::uint8_t> flags);
std::vector<std::uint8_t> read_flags(const std::filesystem::path& file);

}  // namespace strahl::race
