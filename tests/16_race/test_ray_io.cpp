// Chapter 16's file formats (ray_io.hpp): rays and hits round-trip bit for bit, the bytes on disk are
// exactly the documented layout, and every kind of bad file is refused with a message saying what is wrong.
#include "strahl/race/ray_io.hpp"
#include "test_support.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

using namespace strahl;
using namespace strahl::race;
namespace fs = std::filesystem;

namespace {

constexpr float quiet_nan = std::numeric_limits<float>::quiet_NaN();

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::vector<char> file_bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void put_bytes(const fs::path& file, const std::vector<char>& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

// The file's bytes with the float at byte offset `at` replaced.
void patch_float(const fs::path& file, std::size_t at, float value) {
    std::vector<char> bytes = file_bytes(file);
    REQUIRE(at + 4 <= bytes.size());
    std::memcpy(bytes.data() + at, &value, 4);
    put_bytes(file, bytes);
}

void patch_u32(const fs::path& file, std::size_t at, std::uint32_t value) {
    std::vector<char> bytes = file_bytes(file);
    REQUIRE(at + 4 <= bytes.size());
    std::memcpy(bytes.data() + at, &value, 4);
    put_bytes(file, bytes);
}

void patch_count(const fs::path& file, std::uint64_t count) {
    std::vector<char> bytes = file_bytes(file);
    REQUIRE(bytes.size() >= 16);
    std::memcpy(bytes.data() + 8, &count, 8);
    put_bytes(file, bytes);
}

std::vector<ray> some_rays() {
    return {
        ray{vec3(1.5f, -2.25f, 3.0f), vec3(0.1f, 0.2f, -0.97f), 0.0f, inf},
        ray{vec3(-0.0f, 1e-30f, -7e11f), vec3(-1.0f, 0.0f, 0.0f), 1e-4f, 12.5f},
        ray{vec3(0.3f, 0.7f, 0.1f), vec3(0.0f, 0.0f, 0.0f), 2.0f, 1.0f},  // odd but finite: stored as is
        ray{vec3(std::nextafter(1.0f, 2.0f)), vec3(3.0f, -4.0f, 5.0f), -1.0f, std::numeric_limits<float>::max()},
    };
}

std::vector<hit> some_hits() {
    return {
        hit{1.25f, 7u, 0.25f, 0.5f, invalid_id},
        hit{},  // a miss: t = +inf, prim 0xFFFFFFFF
        hit{std::numeric_limits<float>::denorm_min(), 0u, 0.0f, 1.0f, invalid_id},
        hit{3e38f, 0xFFFFFFFEu, std::nextafter(0.3f, 1.0f), -0.0f, invalid_id},
    };
}

// read_rays / read_hits must throw a format_error whose message contains every one of `parts`.
template <class Read>
void refused(Read&& read, const fs::path& file, std::initializer_list<std::string> parts) {
    try {
        read(file);
        FAIL("'" << file.string() << "' was accepted");
    } catch (const format_error& e) {
        const std::string what = e.what();
        INFO("message: " << what);
        for (const std::string& p : parts) CHECK(what.find(p) != std::string::npos);
    }
}

auto read_r = [](const fs::path& f) { return read_rays(f); };
auto read_h = [](const fs::path& f) { return read_hits(f); };

}  // namespace

TEST_CASE("ch16 ray_io: rays round-trip bit for bit, tmax = +inf included", "[ch16][ray_io]") {
    const fs::path dir = test::scratch_dir("ch16_ray_io_rays");
    const std::vector<ray> rays = some_rays();
    write_rays(dir / "r.bin", rays);
    const std::vector<ray> back = read_rays(dir / "r.bin");
    REQUIRE(back.size() == rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
        INFO("ray " << i);
        for (int k = 0; k < 3; ++k) {
            CHECK(same_bits(back[i].org[k], rays[i].org[k]));
            CHECK(same_bits(back[i].dir[k], rays[i].dir[k]));
        }
        CHECK(same_bits(back[i].tmin, rays[i].tmin));
        CHECK(same_bits(back[i].tmax, rays[i].tmax));
    }
    CHECK(back[0].tmax == inf);
    CHECK(std::signbit(back[1].org.x));  // -0 stays -0

    // No rays at all is a valid file too.
    write_rays(dir / "none.bin", {});
    CHECK(read_rays(dir / "none.bin").empty());
    CHECK(fs::file_size(dir / "none.bin") == 16);
}

TEST_CASE("ch16 ray_io: hits round-trip bit for bit, misses included", "[ch16][ray_io]") {
    const fs::path dir = test::scratch_dir("ch16_ray_io_hits");
    const std::vector<hit> hits = some_hits();
    write_hits(dir / "h.bin", hits);
    const std::vector<hit> back = read_hits(dir / "h.bin");
    REQUIRE(back.size() == hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i) {
        INFO("hit " << i);
        CHECK(same_bits(back[i].t, hits[i].t));
        CHECK(back[i].prim == hits[i].prim);
        CHECK(same_bits(back[i].u, hits[i].u));
        CHECK(same_bits(back[i].v, hits[i].v));
    }
    CHECK(back[1].t == inf);
    CHECK(back[1].prim == 0xFFFFFFFFu);
    CHECK_FALSE(back[1].found());
    CHECK(std::signbit(back[3].v));
}

TEST_CASE("ch16 ray_io: the bytes on disk are the documented layout", "[ch16][ray_io]") {
    const fs::path dir = test::scratch_dir("ch16_ray_io_layout");
    const std::vector<ray> rays = some_rays();
    write_rays(dir / "r.bin", rays);
    const std::vector<char> rb = file_bytes(dir / "r.bin");
    REQUIRE(rb.size() == 16 + 32 * rays.size());
    CHECK(std::string(rb.data(), 8) == "STRAHLR1");
    // The count, little-endian, byte by byte: 4 = 04 00 00 00 00 00 00 00.
    CHECK(rb[8] == 4);
    for (int k = 9; k < 16; ++k) CHECK(rb[k] == 0);
    // Ray 1 (the second record): ox oy oz tmin dx dy dz tmax, float32 each.
    const float expect[8] = {-0.0f, 1e-30f, -7e11f, 1e-4f, -1.0f, 0.0f, 0.0f, 12.5f};
    for (int k = 0; k < 8; ++k) {
        INFO("field " << k);
        float f;
        std::memcpy(&f, rb.data() + 16 + 32 + 4 * k, 4);
        CHECK(same_bits(f, expect[k]));
    }
    // One float spelled out as bytes: 12.5f is 0x41480000, little-endian 00 00 48 41.
    const unsigned char* tmax1 = reinterpret_cast<const unsigned char*>(rb.data()) + 16 + 32 + 28;
    CHECK(tmax1[0] == 0x00);
    CHECK(tmax1[1] == 0x00);
    CHECK(tmax1[2] == 0x48);
    CHECK(tmax1[3] == 0x41);

    const std::vector<hit> hits = some_hits();
    write_hits(dir / "h.bin", hits);
    const std::vector<char> hb = file_bytes(dir / "h.bin");
    REQUIRE(hb.size() == 16 + 16 * hits.size());
    CHECK(std::string(hb.data(), 8) == "STRAHLH1");
    CHECK(hb[8] == 4);
    for (int k = 9; k < 16; ++k) CHECK(hb[k] == 0);
    // Hit 0: t = 1.25 (0x3FA00000), prim 7, u = 0.25, v = 0.5; hit 1, a miss: +inf (0x7F800000), FFFFFFFF.
    const auto* h = reinterpret_cast<const unsigned char*>(hb.data()) + 16;
    const unsigned char hit0[16] = {0x00, 0x00, 0xA0, 0x3F, 7, 0, 0, 0, 0x00, 0x00, 0x80, 0x3E, 0x00, 0x00, 0x00, 0x3F};
    const unsigned char hit1_head[8] = {0x00, 0x00, 0x80, 0x7F, 0xFF, 0xFF, 0xFF, 0xFF};
    for (int k = 0; k < 16; ++k) {
        INFO("hit 0, byte " << k);
        CHECK(int(h[k]) == int(hit0[k]));
    }
    for (int k = 0; k < 8; ++k) {
        INFO("hit 1, byte " << k);
        CHECK(int(h[16 + k]) == int(hit1_head[k]));
    }
}

TEST_CASE("ch16 ray_io: files of the wrong kind or size are refused", "[ch16][ray_io]") {
    const fs::path dir = test::scratch_dir("ch16_ray_io_bad_files");
    write_rays(dir / "r.bin", some_rays());
    write_hits(dir / "h.bin", some_hits());

    // A hits file read as rays and the reverse: the magic says which it is.
    refused(read_r, dir / "h.bin", {"h.bin", "STRAHLR1"});
    refused(read_h, dir / "r.bin", {"r.bin", "STRAHLH1"});

    // A wrong magic.
    fs::copy_file(dir / "r.bin", dir / "magic.bin");
    {
        std::vector<char> b = file_bytes(dir / "magic.bin");
        b[6] = 'X';
        put_bytes(dir / "magic.bin", b);
    }
    refused(read_r, dir / "magic.bin", {"magic.bin", "does not start with STRAHLR1"});

    // A count larger than the size says, smaller, and absurdly large (no overflow, no huge allocation).
    for (const std::uint64_t count : {std::uint64_t(5), std::uint64_t(3), std::uint64_t(1) << 59,
                                      std::numeric_limits<std::uint64_t>::max()}) {
        INFO("count " << count);
        fs::copy_file(dir / "r.bin", dir / "count.bin", fs::copy_options::overwrite_existing);
        patch_count(dir / "count.bin", count);
        refused(read_r, dir / "count.bin", {"count.bin", "says it holds " + std::to_string(count), "128 bytes"});
        fs::copy_file(dir / "h.bin", dir / "hcount.bin", fs::copy_options::overwrite_existing);
        patch_count(dir / "hcount.bin", count);
        refused(read_h, dir / "hcount.bin", {"hcount.bin", "says it holds " + std::to_string(count), "64 bytes"});
    }

    // A record cut short: the size is no multiple of the record.
    {
        std::vector<char> b = file_bytes(dir / "r.bin");
        b.resize(b.size() - 5);
        put_bytes(dir / "cut.bin", b);
    }
    refused(read_r, dir / "cut.bin", {"cut.bin", "truncated or corrupt"});

    // A truncated header and an empty file.
    {
        std::vector<char> b = file_bytes(dir / "r.bin");
        b.resize(11);
        put_bytes(dir / "short.bin", b);
        put_bytes(dir / "empty.bin", {});
    }
    refused(read_r, dir / "short.bin", {"short.bin", "too short for a header", "11 bytes"});
    refused(read_h, dir / "short.bin", {"short.bin", "too short for a header"});
    refused(read_r, dir / "empty.bin", {"empty.bin", "too short for a header", "0 bytes"});
    refused(read_h, dir / "empty.bin", {"empty.bin", "too short for a header", "0 bytes"});

    // A missing file and a folder.
    refused(read_r, dir / "missing.bin", {"missing.bin", "cannot open"});
    refused(read_h, dir / "missing.bin", {"missing.bin", "cannot open"});
    fs::create_directories(dir / "folder.bin");
    refused(read_r, dir / "folder.bin", {"folder.bin", "is a folder"});
    refused(read_h, dir / "folder.bin", {"folder.bin", "is a folder"});
}

TEST_CASE("ch16 ray_io: NaN and infinities in rays are refused, naming ray and field", "[ch16][ray_io]") {
    const fs::path dir = test::scratch_dir("ch16_ray_io_bad_rays");
    write_rays(dir / "good.bin", some_rays());
    // Byte offset of field k of ray i: 16 + 32 i + 4 k (ox oy oz tmin dx dy dz tmax).
    struct bad_field {
        int ray, field;
        float value;
        const char* name;
    };
    const bad_field cases[] = {
        {0, 0, quiet_nan, "ox"},  {1, 1, quiet_nan, "oy"},  {2, 2, quiet_nan, "oz"},   {0, 3, quiet_nan, "tmin"},
        {1, 4, quiet_nan, "dx"},  {2, 5, quiet_nan, "dy"},  {3, 6, quiet_nan, "dz"},   {2, 7, quiet_nan, "tmax"},
        {3, 7, -inf, "tmax"}, {1, 0, inf, "ox"},    {2, 1, -inf, "oy"},    {0, 2, inf, "oz"},
        {1, 3, inf, "tmin"},  {0, 3, -inf, "tmin"}, {2, 4, inf, "dx"},     {3, 6, -inf, "dz"},
    };
    for (const bad_field& c : cases) {
        INFO("ray " << c.ray << " field " << c.name << " = " << c.value);
        fs::copy_file(dir / "good.bin", dir / "bad.bin", fs::copy_options::overwrite_existing);
        patch_float(dir / "bad.bin", 16 + 32 * std::size_t(c.ray) + 4 * std::size_t(c.field), c.value);
        refused(read_r, dir / "bad.bin", {"bad.bin", "ray " + std::to_string(c.ray), std::string(" ") + c.name + " ="});
    }
    // Beyond the course's range (max_coordinate): refused, saying why; at the range's edge, read.
    for (const auto& [field, name] : {std::pair{0, "ox"}, {2, "oz"}, {4, "dx"}, {6, "dz"}}) {
        INFO(name);
        fs::copy_file(dir / "good.bin", dir / "far.bin", fs::copy_options::overwrite_existing);
        patch_float(dir / "far.bin", 16 + 32 + 4 * std::size_t(field), -2e12f);
        refused(read_r, dir / "far.bin", {"far.bin", "ray 1", std::string(" ") + name + " =", "beyond +-1e12"});
        patch_float(dir / "far.bin", 16 + 32 + 4 * std::size_t(field), max_coordinate);
        CHECK(read_rays(dir / "far.bin").size() == some_rays().size());
    }
    // The one infinity allowed: tmax = +inf (ray 0 has it already; give it to ray 3 too).
    fs::copy_file(dir / "good.bin", dir / "inf.bin", fs::copy_options::overwrite_existing);
    patch_float(dir / "inf.bin", 16 + 32 * 3 + 28, inf);
    CHECK(read_rays(dir / "inf.bin")[3].tmax == inf);
}

TEST_CASE("ch16 ray_io: inconsistent or NaN hits are refused", "[ch16][ray_io]") {
    const fs::path dir = test::scratch_dir("ch16_ray_io_bad_hits");
    write_hits(dir / "good.bin", some_hits());
    const auto fresh = [&] { fs::copy_file(dir / "good.bin", dir / "bad.bin", fs::copy_options::overwrite_existing); };
    // Hit i's record starts at 16 + 16 i: t, prim, u, v.
    SECTION("t = inf but a primitive id") {
        fresh();
        patch_float(dir / "bad.bin", 16 + 0, inf);
        refused(read_h, dir / "bad.bin", {"bad.bin", "hit 0", "miss"});
    }
    SECTION("a miss's primitive id with a finite t") {
        fresh();
        patch_u32(dir / "bad.bin", 16 + 16 * 2 + 4, invalid_id);
        refused(read_h, dir / "bad.bin", {"bad.bin", "hit 2", "miss"});
    }
    SECTION("a miss (t = inf) with a primitive id") {
        fresh();
        patch_u32(dir / "bad.bin", 16 + 16 + 4, 3u);
        refused(read_h, dir / "bad.bin", {"bad.bin", "hit 1", "miss"});
    }
    SECTION("NaN t, u or v") {
        for (int field : {0, 2, 3}) {
            INFO("field " << field);
            fresh();
            patch_float(dir / "bad.bin", 16 + 16 * 3 + 4 * std::size_t(field), quiet_nan);
            refused(read_h, dir / "bad.bin", {"bad.bin", "hit 3", "NaN"});
        }
    }
}

TEST_CASE("ch16 ray_io: writing where no file can be written throws format_error", "[ch16][ray_io]") {
    const fs::path dir = test::scratch_dir("ch16_ray_io_unwritable");
    put_bytes(dir / "plain_file", {'x'});
    fs::create_directories(dir / "a_folder");
    // Under a plain file (ENOTDIR), into a missing folder and onto a folder: none can be opened for writing
    // (these hold even for root, unlike a read-only permission).
    for (const fs::path& p : {dir / "plain_file" / "r.bin", dir / "missing" / "r.bin", dir / "a_folder"}) {
        INFO(p.string());
        try {
            write_rays(p, some_rays());
            FAIL("write_rays accepted " << p.string());
        } catch (const format_error& e) {
            CHECK(std::string(e.what()).find(p.string()) != std::string::npos);
        }
        CHECK_THROWS_AS(write_hits(p, some_hits()), format_error);
    }
}

TEST_CASE("ch16 ray_io: any-hit flags round-trip, the layout is one byte each, bad flags are refused",
          "[ch16][ray_io]") {
    const fs::path dir = test::scratch_dir("ch16_ray_io_flags");
    const std::vector<std::uint8_t> flags{1, 0, 0, 1, 1};
    write_flags(dir / "f.bin", flags);
    CHECK(read_flags(dir / "f.bin") == flags);
    const std::vector<char> b = file_bytes(dir / "f.bin");
    REQUIRE(b.size() == 16 + flags.size());
    CHECK(std::string(b.data(), 8) == "STRAHLF1");
    for (std::size_t i = 0; i < flags.size(); ++i) CHECK(std::uint8_t(b[16 + i]) == flags[i]);
    write_flags(dir / "none.bin", std::vector<std::uint8_t>{});
    CHECK(read_flags(dir / "none.bin").empty());

    const auto read_f = [](const fs::path& f) { return read_flags(f); };
    std::vector<char> two = b;
    two[16 + 3] = 2;
    put_bytes(dir / "two.bin", two);
    refused(read_f, dir / "two.bin", {"two.bin", "flag 3 is 2, not 0 or 1"});
    put_bytes(dir / "cut.bin", std::vector<char>(b.begin(), b.end() - 1));
    refused(read_f, dir / "cut.bin", {"cut.bin", "truncated or corrupt"});
    write_hits(dir / "h.bin", some_hits());
    refused(read_f, dir / "h.bin", {"h.bin", "does not start with STRAHLF1"});
}
