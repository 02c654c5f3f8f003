// Chapter 16's cache of brute force's answers (reference_cache.hpp): a second run reads exactly what the
// first traced; a changed scene or ray set gets files of its own; a file that is corrupt, truncated, of the
// wrong size or whose answers brute force no longer gives is traced again and replaced, and so is one
// altered in a single record the audit's sample does not hold (the checksum catches it); a folder that
// cannot be written costs the cache, never the answers.
#include "strahl/procedural.hpp"
#include "strahl/race/ray_io.hpp"
#include "strahl/race/reference_cache.hpp"
#include "strahl/race/ray_sets.hpp"
#include "test_support.hpp"
#include <bit>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>

using namespace strahl;
using namespace strahl::race;
namespace fs = std::filesystem;

namespace {

bool same_bits(const std::vector<hit>& a, const std::vector<hit>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].prim != b[i].prim || std::bit_cast<std::uint32_t>(a[i].t) != std::bit_cast<std::uint32_t>(b[i].t) ||
            std::bit_cast<std::uint32_t>(a[i].u) != std::bit_cast<std::uint32_t>(b[i].u) ||
            std::bit_cast<std::uint32_t>(a[i].v) != std::bit_cast<std::uint32_t>(b[i].v))
            return false;
    return true;
}

std::vector<fs::path> files_in(const fs::path& dir) {
    std::vector<fs::path> out;
    if (fs::exists(dir))
        for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

fs::path only_file(const fs::path& dir, const std::string& part) {
    fs::path found;
    for (const fs::path& p : files_in(dir))
        if (p.filename().string().find(part) != std::string::npos) found = p;
    return found;
}

struct fixture {
    scene s = builtin_scene("teapot");
    brute_force exact;
    std::vector<ray> rays;
    std::vector<hit> hits;
    std::vector<std::uint8_t> blocked;
    explicit fixture(int width = 32, int height = 24) {
        exact.build(s);
        rays = primary_rays(s, width, height);
        hits.resize(rays.size());
        blocked.resize(rays.size());
        trace_closest(exact, rays, hits);
        trace_any(exact, rays, blocked);
    }
};

}  // namespace

TEST_CASE("ch16 reference cache: the second run reads what the first traced, bit for bit", "[ch16][cache]") {
    const fs::path dir = test::scratch_dir("ch16_cache_round_trip") / "cache";
    fixture f;
    {
        reference_cache first(dir, f.s, f.exact, 1);
        CHECK(same_bits(first.closest("primary", f.rays), f.hits));
        CHECK(first.any("primary", f.rays) == f.blocked);
        CHECK(first.traced() == 2);
        CHECK(first.loaded() == 0);
    }
    REQUIRE(files_in(dir).size() == 2);  // one .hits, one .flags; no temporary file left
    CHECK(only_file(dir, "closest").extension() == ".hits");
    CHECK(only_file(dir, "any").extension() == ".flags");
    reference_cache second(dir, f.s, f.exact, 1);
    CHECK(same_bits(second.closest("primary", f.rays), f.hits));
    CHECK(second.any("primary", f.rays) == f.blocked);
    CHECK(second.loaded() == 2);
    CHECK(second.traced() == 0);
    CHECK(second.stale() == 0);

    // An empty ray set is cached like any other.
    CHECK(second.closest("none", std::vector<ray>{}).empty());
    CHECK(reference_cache(dir, f.s, f.exact, 1).closest("none", std::vector<ray>{}).empty());
}

TEST_CASE("ch16 reference cache: another scene or other rays get files of their own", "[ch16][cache]") {
    const fs::path dir = test::scratch_dir("ch16_cache_keys");
    fixture f;
    reference_cache(dir, f.s, f.exact, 1).closest("primary", f.rays);
    REQUIRE(files_in(dir).size() == 1);

    // One ray's tmax a float's step shorter: a new file.
    std::vector<ray> other = f.rays;
    other[7].tmax = std::nextafter(other[7].tmax, 0.0f);
    reference_cache(dir, f.s, f.exact, 1).closest("primary", other);
    CHECK(files_in(dir).size() == 2);

    // One vertex moved by a float's step: a new file, and answers traced on the new scene.
    scene moved = f.s;
    moved.mesh.positions[0].x = std::nextafter(moved.mesh.positions[0].x, 1e9f);
    brute_force exact_moved;
    exact_moved.build(moved);
    reference_cache c(dir, moved, exact_moved, 1);
    c.closest("primary", f.rays);
    CHECK(c.traced() == 1);
    CHECK(files_in(dir).size() == 3);
}

TEST_CASE("ch16 reference cache: corrupt, truncated and stale files are traced again and replaced",
          "[ch16][cache]") {
    const fs::path dir = test::scratch_dir("ch16_cache_stale");
    fixture f;
    {
        reference_cache c(dir, f.s, f.exact, 1);
        c.closest("primary", f.rays);
        c.any("primary", f.rays);
    }
    const fs::path hits_file = only_file(dir, "closest"), flags_file = only_file(dir, "any");
    const auto check_replaced = [&](const char* what) {
        INFO(what);
        reference_cache c(dir, f.s, f.exact, 1);
        CHECK(same_bits(c.closest("primary", f.rays), f.hits));
        CHECK(c.any("primary", f.rays) == f.blocked);
        CHECK(c.stale() >= 1);
        // ... and the replaced files are good again.
        reference_cache again(dir, f.s, f.exact, 1);
        again.closest("primary", f.rays);
        again.any("primary", f.rays);
        CHECK(again.loaded() == 2);
    };

    // Well-formed files whose answers brute force does not give: every hit's t one step further, every
    // any-hit answer flipped. The audit's sample catches both.
    std::vector<hit> wrong = f.hits;
    std::size_t found = 0;
    for (hit& h : wrong)
        if (h.found()) h.t = std::nextafter(h.t, inf), ++found;
    REQUIRE(found > 0);
    write_hits(hits_file, wrong);
    std::vector<std::uint8_t> flipped = f.blocked;
    for (std::uint8_t& b : flipped) b ^= 1;
    write_flags(flags_file, flipped);
    check_replaced("well-formed but wrong answers");

    // One hit's u one step off, the first hit of the set: the audit's sample over the rays that hit always
    // holds the first of them.
    std::vector<hit> one = f.hits;
    for (hit& h : one)
        if (h.found()) {
            h.u = std::nextafter(h.u, 1.0f);
            break;
        }
    write_hits(hits_file, one);
    check_replaced("one hit off by a float's step");

    // Truncated, of another kind, and answering a different number of rays.
    {
        std::ifstream in(hits_file, std::ios::binary);
        std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        in.close();
        std::ofstream(hits_file, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size() - 3));
    }
    write_hits(flags_file, f.hits);
    check_replaced("truncated, and of the wrong kind");
    write_hits(hits_file, std::vector<hit>(f.hits.begin(), f.hits.end() - 1));
    write_flags(flags_file, std::vector<std::uint8_t>(f.blocked.size() + 1, 0));
    check_replaced("answers for a different number of rays");
}

namespace {

// The rays the audit re-traces (reference_cache.cpp's rule): audit_rays spread evenly over the set, and as
// many spread evenly over the rays the file says hit. A record outside both is one the audit cannot catch.
template <class Answer, class Hits>
std::vector<bool> audited(const std::vector<Answer>& answers, Hits says_hit) {
    std::vector<bool> in(answers.size(), false);
    std::vector<std::size_t> all(answers.size()), hit_ids;
    for (std::size_t i = 0; i < answers.size(); ++i) {
        all[i] = i;
        if (says_hit(answers[i])) hit_ids.push_back(i);
    }
    for (const std::vector<std::size_t>* from : {&all, &hit_ids}) {
        const std::size_t m = std::min(from->size(), reference_cache::audit_rays);
        for (std::size_t k = 0; k < m; ++k) in[(*from)[k * from->size() / m]] = true;
    }
    return in;
}

}  // namespace

TEST_CASE("ch16 reference cache: one record altered outside the audit's sample is caught by the checksum",
          "[ch16][cache]") {
    const fs::path dir = test::scratch_dir("ch16_cache_checksum");
    fixture f(64, 48);  // 3,072 rays: the audit's 256 leave most records unchecked
    {
        reference_cache c(dir, f.s, f.exact, 1);
        c.closest("primary", f.rays);
        c.any("primary", f.rays);
    }
    const fs::path hits_file = only_file(dir, "closest"), flags_file = only_file(dir, "any");
    REQUIRE(!hits_file.empty());
    REQUIRE(!flags_file.empty());

    // A hit the audit does not re-trace, its t one float step further: well-formed, and wrong.
    const std::vector<bool> hit_sampled = audited(f.hits, [](const hit& h) { return h.found(); });
    std::size_t victim = f.hits.size();
    for (std::size_t i = 0; i < f.hits.size() && victim == f.hits.size(); ++i)
        if (f.hits[i].found() && !hit_sampled[i]) victim = i;
    REQUIRE(victim < f.hits.size());
    std::vector<hit> wrong = f.hits;
    wrong[victim].t = std::nextafter(wrong[victim].t, inf);
    write_hits(hits_file, wrong);

    // An any-hit flag flipped where the audit of the altered file does not look (flipping one changes the
    // rays the file says hit, and so the audit's second half).
    std::vector<std::uint8_t> flags;
    for (std::size_t i = 0; i < f.blocked.size(); ++i) {
        flags = f.blocked;
        flags[i] ^= 1;
        if (!audited(flags, [](std::uint8_t b) { return b != 0; })[i]) break;
        flags.clear();
    }
    REQUIRE(!flags.empty());
    write_flags(flags_file, flags);

    reference_cache c(dir, f.s, f.exact, 1);
    CHECK(same_bits(c.closest("primary", f.rays), f.hits));
    CHECK(c.any("primary", f.rays) == f.blocked);
    CHECK(c.stale() == 2);
    CHECK(c.traced() == 2);
    CHECK(files_in(dir).size() == 2);  // the altered files replaced, not kept beside the new ones

    // The files written again are whole and used as they are.
    reference_cache again(dir, f.s, f.exact, 1);
    CHECK(same_bits(again.closest("primary", f.rays), f.hits));
    CHECK(again.any("primary", f.rays) == f.blocked);
    CHECK(again.loaded() == 2);
}

TEST_CASE("ch16 reference cache: no folder, or one that cannot be written: answers all the same",
          "[ch16][cache]") {
    const fs::path dir = test::scratch_dir("ch16_cache_unwritable");
    fixture f;
    reference_cache none({}, f.s, f.exact, 1);
    CHECK(same_bits(none.closest("primary", f.rays), f.hits));
    CHECK(none.traced() == 1);
    CHECK(files_in(dir).empty());

    std::ofstream(dir / "plain_file") << "x";
    reference_cache blocked(dir / "plain_file" / "cache", f.s, f.exact, 1);
    CHECK(same_bits(blocked.closest("primary", f.rays), f.hits));
    CHECK(blocked.any("primary", f.rays) == f.blocked);
    CHECK(blocked.traced() == 2);
    CHECK(files_in(dir).size() == 1);  // the plain file, nothing else
}

TEST_CASE("ch16 reference cache: pruning removes the least recently used of the cache's own files", "[ch16][cache]") {
    const fs::path dir = strahl::test::scratch_dir("ch16_cache_prune");
    const auto now = fs::file_time_type::clock::now();
    using std::chrono::hours;
    // Five cache files of 1,000 bytes, used 5 to 1 hours ago, and a file of the user's, older than all.
    const std::vector<std::string> names = {"bunny_primary_closest_0123456789abcdef.hits",
                                            "bunny_primary_any_0123456789abcdef.flags",
                                            "sponza_diffuse_closest_fedcba9876543210.hits",
                                            "sponza_diffuse_any_fedcba9876543210.flags",
                                            "teapot_shadow_any_00000000000000aa.flags.tmp"};
    for (std::size_t k = 0; k < names.size(); ++k) {
        std::ofstream(dir / names[k]) << std::string(1000, 'x');
        fs::last_write_time(dir / names[k], now - hours(5 - int(k)));
    }
    std::ofstream(dir / "my_notes.hits") << std::string(5000, 'x');
    fs::last_write_time(dir / "my_notes.hits", now - hours(10));

    SECTION("within the limit: nothing removed") {
        const pruned_files p = prune_reference_cache(dir, 5000, now);
        CHECK(p.files == 0);
        CHECK(files_in(dir).size() == 6);
    }
    SECTION("over it: the oldest of the cache's files go first, the user's file stays") {
        const pruned_files p = prune_reference_cache(dir, 2500, now);
        CHECK(p.files == 3);
        CHECK(p.bytes == 3000);
        CHECK_FALSE(fs::exists(dir / names[0]));
        CHECK_FALSE(fs::exists(dir / names[2]));
        CHECK(fs::exists(dir / names[3]));
        CHECK(fs::exists(dir / names[4]));
        CHECK(fs::exists(dir / "my_notes.hits"));
    }
    SECTION("files used since the run began stay, even over the limit") {
        const pruned_files p = prune_reference_cache(dir, 0, now - hours(3) - std::chrono::minutes(30));
        CHECK(p.files == 2);  // the two used before then
        CHECK(fs::exists(dir / names[2]));
        CHECK(files_in(dir).size() == 4);
    }
    SECTION("a missing folder: nothing to do") {
        CHECK(prune_reference_cache(dir / "absent", 0, now).files == 0);
    }
}

TEST_CASE("ch16 reference cache: a file read from the cache counts as used now", "[ch16][cache]") {
    const fs::path dir = strahl::test::scratch_dir("ch16_cache_touch");
    const fixture x;
    reference_cache(dir, x.s, x.exact, 1).closest("primary", x.rays);
    const fs::path f = only_file(dir, "closest");
    const auto old = fs::file_time_type::clock::now() - std::chrono::hours(24);
    fs::last_write_time(f, old);
    reference_cache again(dir, x.s, x.exact, 1);
    again.closest("primary", x.rays);
    CHECK(again.loaded() == 1);
    CHECK(fs::last_write_time(f) > old + std::chrono::hours(23));
    // So a prune right after this run keeps it.
    CHECK(prune_reference_cache(dir, 0, old + std::chrono::hours(1)).files == 0);
}
