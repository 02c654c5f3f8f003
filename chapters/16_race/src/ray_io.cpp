#include "strahl/race/ray_io.hpp"
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>

namespace strahl::race {

static_assert(std::endian::native == std::endian::little, "the ray and hit formats are little-endian");
static_assert(sizeof(float) == 4);

namespace {

constexpr char ray_magic[8] = {'S', 'T', 'R', 'A', 'H', 'L', 'R', '1'};
constexpr char hit_magic[8] = {'S', 'T', 'R', 'A', 'H', 'L', 'H', '1'};
constexpr char flag_magic[8] = {'S', 'T', 'R', 'A', 'H', 'L', 'F', '1'};
constexpr std::size_t header_bytes = 16, ray_bytes = 32, hit_bytes = 16;

void write_file(const std::filesystem::path& file, const char (&magic)[8], std::uint64_t count,
                const std::vector<char>& payload) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    if (!out) throw format_error("cannot write '" + file.string() + "': " + std::strerror(errno));
    out.write(magic, 8);
    out.write(reinterpret_cast<const char*>(&count), 8);
    out.write(payload.data(), std::streamsize(payload.size()));
    out.close();
    if (!out) throw format_error("writing '" + file.string() + "' failed (disk full?)");
}

// Reads the whole file after checking its magic and that its size matches its count.
std::vector<char> read_file(const std::filesystem::path& file, const char (&magic)[8], std::size_t record_bytes,
                            std::uint64_t& count) {
    const std::string name = "'" + file.string() + "'";
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) throw format_error(name + " is a folder, not a file");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw format_error("cannot open " + name + ": " + std::strerror(errno));
    const auto size = std::filesystem::file_size(file, ec);
    if (ec) throw format_error("cannot read the size of " + name);
    char head[header_bytes];
    if (size < header_bytes || !in.read(head, header_bytes))
        throw format_error(name + " is too short for a header (" + std::to_string(size) + " bytes)");
    if (std::memcmp(head, magic, 8) != 0)
        throw format_error(name + " does not start with " + std::string(magic, 8) + ": not this kind of file");
    std::memcpy(&count, head + 8, 8);
    const std::uint64_t payload = size - header_bytes;
    if (count > payload / record_bytes || payload != count * record_bytes)
        throw format_error(name + " says it holds " + std::to_string(count) + " records of " +
                           std::to_string(record_bytes) + " bytes, but has " + std::to_string(payload) +
                           " bytes after its header (truncated or corrupt)");
    std::vector<char> data(payload);
    if (!in.read(data.data(), std::streamsize(payload))) throw format_error("reading " + name + " failed");
    return data;
}

}  // namespace

void write_rays(const std::filesystem::path& file, std::span<const ray> rays) {
    std::vector<char> payload(rays.size() * ray_bytes);
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const ray& r = rays[i];
        const float f[8] = {r.org.x, r.org.y, r.org.z, r.tmin, r.dir.x, r.dir.y, r.dir.z, r.tmax};
        std::memcpy(payload.data() + i * ray_bytes, f, ray_bytes);
    }
    write_file(file, ray_magic, rays.size(), payload);
}

namespace {
std::string shortest(float x) {
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof buf, x).ptr;
    return std::string(buf, end);
}
}  // namespace

std::vector<ray> read_rays(const std::filesystem::path& file) {
    std::uint64_t count = 0;
    const std::vector<char> data = read_file(file, ray_magic, ray_bytes, count);
    static const char* const fields[8] = {"ox", "oy", "oz", "tmin", "dx", "dy", "dz", "tmax"};
    std::vector<ray> rays(count);
    for (std::size_t i = 0; i < count; ++i) {
        float f[8];
        std::memcpy(f, data.data() + i * ray_bytes, ray_bytes);
        for (int k = 0; k < 8; ++k) {
            const bool ok = k == 7 ? !std::isnan(f[k]) && f[k] != -inf : std::isfinite(f[k]);
            if (!ok)
                throw format_error("'" + file.string() + "': ray " + std::to_string(i) + " has " + fields[k] + " = " +
                                   std::to_string(f[k]) + (k == 7 ? " (tmax may be +inf, never NaN)" : " (must be finite)"));
        }
        for (int k : {0, 1, 2, 4, 5, 6})
            if (std::abs(f[k]) > max_coordinate)
                throw format_error("'" + file.string() + "': ray " + std::to_string(i) + " has " + fields[k] + " = " +
                                   shortest(f[k]) + ", beyond +-1e12, the largest coordinate the course "
                                   "accepts (the triangle tests multiply three lengths, which overflow float above "
                                   "about 7e12)");
        rays[i] = ray{vec3(f[0], f[1], f[2]), vec3(f[4], f[5], f[6]), f[3], f[7]};
    }
    return rays;
}

void write_hits(const std::filesystem::path& file, std::span<const hit> hits) {
    std::vector<char> payload(hits.size() * hit_bytes);
    for (std::size_t i = 0; i < hits.size(); ++i) {
        char* p = payload.data() + i * hit_bytes;
        std::memcpy(p, &hits[i].t, 4);
        std::memcpy(p + 4, &hits[i].prim, 4);
        std::memcpy(p + 8, &hits[i].u, 4);
        std::memcpy(p + 12, &hits[i].v, 4);
    }
    write_file(file, hit_magic, hits.size(), payload);
}

std::vector<hit> read_hits(const std::filesystem::path& file) {
    std::uint64_t count = 0;
    const std::vector<char> data = read_file(file, hit_magic, hit_bytes, count);
    std::vector<hit> hits(count);
    for (std::size_t i = 0; i < count; ++i) {
        const char* p = data.data() + i * hit_bytes;
        hit& h = hits[i];
        std::memcpy(&h.t, p, 4);
        std::memcpy(&h.prim, p + 4, 4);
        std::memcpy(&h.u, p + 8, 4);
        std::memcpy(&h.v, p + 12, 4);
        const std::string where = "'" + file.string() + "': hit " + std::to_string(i);
        if (std::isnan(h.t) || std::isnan(h.u) || std::isnan(h.v)) throw format_error(where + " holds NaN");
        if ((h.t == inf) != (h.prim == invalid_id))
            throw format_error(where + ": a miss needs t = +inf and primitive id 0xFFFFFFFF together");
    }
    return hits;
}

void write_flags(const std::filesystem::path& file, std::span<const std::uint8_t> flags) {
    write_file(file, flag_magic, flags.size(), std::vector<char>(flags.begin(), flags.end()));
}

std::vector<std::uint8_t> read_flags(const std::filesystem::path& file) {
    std::uint64_t count = 0;
    const std::vector<char> data = read_file(file, flag_magic, 1, count);
    std::vector<std::uint8_t> flags(data.begin(), data.end());
    for (std::size_t i = 0; i < flags.size(); ++i)
        if (flags[i] > 1)
            throw format_error("'" + file.string() + "': flag " + std::to_string(i) + " is " +
                               std::to_string(flags[i]) + ", not 0 or 1");
    return flags;
}

}  // namespace strahl::race
