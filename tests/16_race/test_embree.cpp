// Embree, the race's baseline and independent oracle: its medium and high quality builds find the same
// primitive as brute force on all but a handful of rays (its own triangle test rounds differently), and its
// packet and stream paths answer as its single-ray path. The counts go to the log (WARN).
#include "strahl/procedural.hpp"
#include "strahl/race/brute_force.hpp"
#include "strahl/race/embree_accel.hpp"
#include "strahl/race/measure.hpp"
#include "strahl/race/ray_sets.hpp"
#include "strahl/race/registry.hpp"
#include "reference.hpp"
#include "test_support.hpp"
#include <catch2/catch.hpp>
#include <algorithm>
#include <stdexcept>

using namespace strahl;
using namespace strahl::race;

namespace {

std::unique_ptr<accel> make_built(const std::string& name, const scene& s, const registry_options& o = {}) {
    std::unique_ptr<accel> a = find_accel(name, o).make();
    a->build(s);
    return a;
}

// Where this build has no Embree: says so (a warning in the log) and returns true, so the test returns.
bool skipped_without_embree() {
    if (embree_available()) return false;
    WARN("skipped: this build has no Embree 3");
    return true;
}

// Compares embree-medium and embree-high with brute force on the three ray sets of s; at most
// `allowed_percent` of each set's rays may differ (closest: a different primitive or hit/miss; any: the
// other answer).
void check_embree(const scene& s, int width, int height, double allowed_percent) {
    const std::vector<test::reference_set>& sets = test::shared_reference_sets(s, width, height);
    for (const char* name : {"embree-medium", "embree-high"}) {
        const std::unique_ptr<accel> a = make_built(name, s);
        CHECK(a->name() == name);
        CHECK_FALSE(a->exact());
        for (const test::reference_set& r : sets) {
            REQUIRE(!r.rays.empty());
            std::vector<hit> got(r.rays.size());
            std::vector<std::uint8_t> got_any(r.rays.size(), 7);
            test::closest_in_parallel(*a, r.rays, got);
            test::any_in_parallel(*a, r.rays, got_any);
            std::size_t closest_diff = 0, any_diff = 0, hits = 0, blocked = 0;
            for (std::size_t i = 0; i < r.rays.size(); ++i) {
                closest_diff += !agrees(got[i], r.closest[i], false);
                any_diff += got_any[i] != r.any[i];
                hits += r.closest[i].found();
                blocked += r.any[i];
            }
            WARN("embree vs brute force: " << s.name << ", " << name << ", " << to_string(r.kind) << " rays: "
                 << closest_diff << " of " << r.rays.size() << " closest hits and " << any_diff
                 << " any hits differ (brute force: " << hits << " hits, " << blocked << " blocked)");
            const double allowed = allowed_percent / 100.0 * double(r.rays.size());
            CHECK(double(closest_diff) <= allowed);
            CHECK(double(any_diff) <= allowed);
            if (r.kind == ray_kind::primary) CHECK(hits > 0);
        }
    }
}

// Embree's packet and stream rows, and the calls behind them (embree_config::calls), with and without rows.
struct tiled_row {
    const char* name;
    embree_config::calls queries;
    bool coherent;
    std::size_t tile_rows;  // a tile's height: batch_alignment() is this many image rows
};
const tiled_row tiled_rows[] = {
    {"embree-medium-packet8", embree_config::calls::packet8, false, 2},
    {"embree-medium-packet8-coherent", embree_config::calls::packet8, true, 2},
    {"embree-medium-packet16-coherent", embree_config::calls::packet16, true, 4},
    {"embree-medium-stream-coherent", embree_config::calls::stream, true, 8},
};

// Rays whose answers a and b differ on: closest (another primitive, hit against miss, or t further apart
// than 1e-4 relative: Embree's packet kernels may round t otherwise) or any.
std::size_t differing(std::span<const hit> a, std::span<const hit> b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        n += !agrees(a[i], b[i], false) || (a[i].found() && std::abs(a[i].t - b[i].t) > 1e-4f * std::abs(b[i].t));
    return n;
}
std::size_t differing(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
    return n;
}

}  // namespace

TEST_CASE("ch16 embree: available where found, refused clearly where not", "[ch16][embree]") {
    bool listed = false;
    for (const accel_entry& e : registered_accels()) listed = listed || e.name == "embree-medium";
    CHECK(listed == embree_available());
    // The race has Embree exactly when CMake found it: a build that lost the flag fails here, not silently.
    CHECK(embree_available() == bool(STRAHL_EMBREE_FOUND));
    if (!embree_available()) {
        CHECK_THROWS_WITH(make_embree_accel({}), Catch::Contains("Embree"));
        WARN("skipped: this build has no Embree 3");
    }
}

TEST_CASE("ch16 embree: agrees with brute force on the teapot but for a handful of rays", "[ch16][embree]") {
    if (skipped_without_embree()) return;
    check_embree(builtin_scene("teapot"), 48, 36, 1.0);
}

TEST_CASE("ch16 embree: agrees with brute force on a random soup but for a handful of rays", "[ch16][embree]") {
    if (skipped_without_embree()) return;
    check_embree(builtin_scene("soup"), 48, 36, 1.0);
}

TEST_CASE("ch16 embree: agrees with brute force on the teapot in a stadium", "[ch16][embree]") {
    if (skipped_without_embree()) return;
    check_embree(builtin_scene("teapot_stadium"), 48, 36, 1.0);
}

TEST_CASE("ch16 embree: agrees with brute force on the bunny", "[ch16][embree]") {
    if (skipped_without_embree()) return;
    const std::filesystem::path file = test::shared_scene("bunny.ply");
    if (file.empty()) {
        WARN("skipped: ../shared/scenes/bunny.ply is not beside this clone");
        return;
    }
    check_embree(load_scene(file), 32, 24, 1.0);
}

TEST_CASE("ch16 embree: its memory is what its device's monitor counts, the BVH with the geometry, net of what "
          "a rebuild released", "[ch16][embree]") {
    if (skipped_without_embree()) return;
    const scene s = builtin_scene("teapot_stadium");
    const std::size_t geometry = s.mesh.positions.size() * 12 + s.mesh.triangle_count() * 12;
    for (const embree_config::quality q : {embree_config::quality::low, embree_config::quality::medium,
                                           embree_config::quality::high}) {
        const auto a = make_embree_accel({q, 0, 1});
        a->build(s);
        const std::size_t first = a->memory_bytes();
        INFO(first << " bytes held, " << geometry << " of them the vertices and indices");
        CHECK(first > geometry * 2);    // the BVH and its leaves besides the buffers
        CHECK(first < geometry * 100);  // and nothing like a leak
        a->build(s);                    // a rebuild releases the first scene: the same again, not twice as much
        CHECK(a->memory_bytes() > first / 2);
        CHECK(a->memory_bytes() < first * 3 / 2);
    }
    const auto e = make_embree_accel({});
    scene empty;
    e->build(empty);
    CHECK(e->memory_bytes() < geometry);
}

TEST_CASE("ch16 embree: an empty scene misses everything", "[ch16][embree]") {
    if (skipped_without_embree()) return;
    scene empty;
    empty.name = "empty";
    const std::vector<ray> rays = primary_rays(builtin_scene("teapot"), 8, 6);
    std::vector<std::string> names = {"embree-medium", "embree-high"};
    for (const tiled_row& row : tiled_rows) names.push_back(row.name);
    for (const std::string& name : names) {
        INFO(name);
        const std::unique_ptr<accel> a = make_built(name, empty, registry_options{1, 8});
        std::vector<hit> hits(rays.size());
        std::vector<std::uint8_t> blocked(rays.size(), 7);
        a->intersect(rays, hits);
        a->occluded(rays, blocked);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            CHECK_FALSE(hits[i].found());
            CHECK(blocked[i] == 0);
        }
    }
}

// Every packet and stream row against embree-medium (rtcIntersect1 / rtcOccluded1) on the same rays, both
// queries, within the tolerance of the tests against brute force (1% of a set's rays): on the race's three
// ray sets (the secondary sets, one ray per primary hit, end in partial tiles), cut into the race's thread
// chunks; on a batch that is not whole rows of tiles; on batches holding rays Embree cannot take, which
// must get brute force's own answers; and without rows (width 0: tiles of consecutive rays).
TEST_CASE("ch16 embree: packet and stream rows answer as rtcIntersect1 does, both queries, every ray set, "
          "partial tiles and rays Embree cannot take", "[ch16][embree]") {
    if (skipped_without_embree()) return;
    const int width = 48, height = 36;
    for (const char* scene_name : {"teapot", "soup", "teapot_stadium"}) {
        const scene s = builtin_scene(scene_name);
        const std::vector<test::reference_set>& sets = test::shared_reference_sets(s, width, height);
        const std::unique_ptr<accel> single = make_built("embree-medium", s);
        brute_force exact;
        exact.build(s);
        // The batches: each ray set whole; 5 rows and 13 rays of the primary rays from the image's 15th row on
        // (partial tiles in both directions); and the primary and diffuse rays with every 37th ray made one
        // Embree cannot take (tmin < 0 or a huge origin, alternately).
        struct batch {
            std::string what;
            std::vector<ray> rays;
            int threads = 2;
        };
        std::vector<batch> batches;
        for (const test::reference_set& r : sets) batches.push_back({to_string(r.kind) + " rays", r.rays});
        const auto row_15 = sets[0].rays.begin() + 14 * width;
        batches.push_back({"a batch of 5 rows and 13 rays", std::vector<ray>(row_15, row_15 + 5 * width + 13), 1});
        for (const std::size_t k : {std::size_t(0), std::size_t(1)}) {
            batch b{to_string(sets[k].kind) + " rays, every 37th one Embree cannot take", sets[k].rays, 1};
            for (std::size_t i = 5; i < b.rays.size(); i += 37) {
                if (i / 37 % 2) b.rays[i].tmin = -1e-3f;
                else b.rays[i].org.x += 1e19f;
            }
            batches.push_back(std::move(b));
        }
        for (const tiled_row& row : tiled_rows)
            for (const int rows_of : {width, 0}) {
                INFO(scene_name << ", " << row.name << (rows_of ? "" : " without rows (width 0)"));
                std::unique_ptr<accel> a;
                if (rows_of) {
                    a = make_built(row.name, s, registry_options{1, rows_of});
                    CHECK(a->name() == row.name);
                    CHECK(a->batch_alignment() == row.tile_rows * std::size_t(width));
                } else {
                    embree_config c;
                    c.queries = row.queries, c.coherent = row.coherent;
                    a = make_embree_accel(c);
                    a->build(s);
                }
                CHECK_FALSE(a->exact());
                for (const batch& b : batches) {
                    INFO(b.what << " (" << b.rays.size() << ")");
                    std::vector<hit> want(b.rays.size()), got(b.rays.size(), hit{-1.0f, 12345u, 0.0f, 0.0f, invalid_id});
                    std::vector<std::uint8_t> want_any(b.rays.size()), got_any(b.rays.size(), 7);
                    single->intersect(b.rays, want);
                    single->occluded(b.rays, want_any);
                    trace_closest(*a, b.rays, got, b.threads);
                    trace_any(*a, b.rays, got_any, b.threads);
                    const std::size_t closest_diff = differing(got, want), any_diff = differing(got_any, want_any);
                    if (closest_diff || any_diff)
                        WARN(scene_name << ", " << row.name << (rows_of ? "" : " (width 0)") << ", " << b.what << ": "
                             << closest_diff << " closest and " << any_diff << " any hits of " << b.rays.size()
                             << " differ from rtcIntersect1's");
                    const double allowed = 0.01 * double(b.rays.size());
                    CHECK(double(closest_diff) <= allowed);
                    CHECK(double(any_diff) <= allowed);
                    CHECK(test::found(got) > 0);
                    CHECK(std::count_if(got_any.begin(), got_any.end(), [](std::uint8_t x) { return x > 1; }) == 0);
                    if (b.what.find("cannot take") == std::string::npos) continue;
                    // The rays Embree cannot take: brute force's answers, bit for bit.
                    std::size_t fallback_diff = 0, fallback_found = 0;
                    for (std::size_t i = 5; i < b.rays.size(); i += 37) {
                        hit h;
                        std::uint8_t blocked = 7;
                        exact.intersect(std::span(b.rays).subspan(i, 1), std::span(&h, 1));
                        exact.occluded(std::span(b.rays).subspan(i, 1), std::span(&blocked, 1));
                        fallback_found += h.found();
                        fallback_diff += !agrees(got[i], h, true) || got_any[i] != blocked;
                    }
                    CHECK(fallback_found > 0);
                    CHECK(fallback_diff == 0);
                }
            }
    }
    // Without a packet width, there are no packet or stream entries; nor instanced packets.
    for (const accel_entry& e : registered_accels()) {
        CHECK(e.name.find("packet") == std::string::npos);
        CHECK(e.name.find("stream") == std::string::npos);
    }
    embree_config instanced_packets;
    instanced_packets.instanced = true, instanced_packets.queries = embree_config::calls::packet8;
    CHECK_THROWS_AS(make_embree_accel(instanced_packets), std::invalid_argument);
}

// The yardstick: Embree's queries run with flush-to-zero and denormals-are-zero set (Embree's documentation;
// without them its traversal ran 1.3 to 2.1 times slower here), and with a tnear that is not a denormal
// (tnear = nextafter(0) was), in every way the wrapper calls Embree. The probe's filter function reads MXCSR,
// tnear and the context's flags inside Embree's traversal.
TEST_CASE("ch16 embree: called as its documentation asks (FTZ and DAZ on inside Embree, tnear never a denormal, "
          "MXCSR restored after)", "[ch16][embree]") {
    CHECK_FALSE(denormals_are_flushed());  // the course's own arithmetic runs with IEEE denormals
    {
        const denormals_flushed flushed;
        CHECK(denormals_are_flushed());
    }
    CHECK_FALSE(denormals_are_flushed());
    if (skipped_without_embree()) return;
    const scene s = builtin_scene("teapot");
    const int width = 32, height = 24;
    // Every way the wrapper calls Embree, both queries, on the three ray sets (the secondary ones end in
    // partial tiles).
    struct call {
        const char* what;
        embree_config::calls queries;
        bool coherent;
    };
    using c = embree_config::calls;
    for (const call& k : {call{"rtcIntersect1, rtcOccluded1", c::single, false},
                          call{"rtcIntersect8, rtcOccluded8", c::packet8, false},
                          call{"rtcIntersect8, rtcOccluded8, coherent", c::packet8, true},
                          call{"rtcIntersect16, rtcOccluded16, coherent", c::packet16, true},
                          call{"rtcIntersect1M, rtcOccluded1M, coherent", c::stream, true}}) {
        embree_call_probe probe;
        embree_config config;
        config.packet_image_width = k.queries == c::single ? 0 : width;
        config.queries = k.queries, config.coherent = k.coherent;
        config.probe = &probe;
        const std::unique_ptr<accel> a = make_embree_accel(config);
        a->build(s);
        for (const test::reference_set& r : test::shared_reference_sets(s, width, height)) {
            INFO(k.what << ", " << to_string(r.kind) << " rays");
            std::vector<hit> hits(r.rays.size());
            std::vector<std::uint8_t> blocked(r.rays.size());
            const std::uint64_t before = probe.candidate_hits.load();
            a->intersect(r.rays, hits);
            CHECK_FALSE(denormals_are_flushed());  // restored after the batch
            const std::uint64_t after_closest = probe.candidate_hits.load();
            a->occluded(r.rays, blocked);
            CHECK_FALSE(denormals_are_flushed());
            std::size_t found = 0, any = 0;
            for (const hit& h : hits) found += h.found();
            for (const std::uint8_t b : blocked) any += b;
            REQUIRE(found > 0);
            REQUIRE(any > 0);
            // Every hit found and every ray blocked went through the filter, inside Embree's traversal.
            CHECK(after_closest - before >= found);
            CHECK(probe.candidate_hits.load() - after_closest >= any);
            CHECK(probe.without_ftz_daz.load() == 0);
            CHECK(probe.denormal_tnear.load() == 0);
            // The coherent rows tell Embree so in every call, the others in none.
            CHECK(probe.coherent.load() == (k.coherent ? probe.candidate_hits.load() : 0));
        }
    }
}

// The course's interval is open at both ends; Embree's test excludes t = tnear by itself, and the wrapper
// moves tfar inwards by one ulp. A triangle in the plane z = 0 and rays along z.
TEST_CASE("ch16 embree: hits exactly at tmin or tmax are not hits, as for the course's structures", "[ch16][embree]") {
    if (skipped_without_embree()) return;
    scene s;
    s.name = "one triangle";
    s.mesh.positions = {vec3(-1.0f, -1.0f, 0.0f), vec3(3.0f, -1.0f, 0.0f), vec3(-1.0f, 3.0f, 0.0f)};
    s.mesh.indices = {{0u, 1u, 2u}};
    const float after_one = std::nextafter(1.0f, 2.0f);
    const std::vector<ray> rays = {
        ray{vec3(0.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, 1.0f), 0.0f, inf},        // starts on the triangle: t = 0
        ray{vec3(0.0f, 0.0f, -1.0f), vec3(0.0f, 0.0f, 1.0f), 0.0f, 1.0f},      // ends on it: t = tmax = 1
        ray{vec3(0.0f, 0.0f, -1.0f), vec3(0.0f, 0.0f, 1.0f), 0.0f, after_one},  // t = 1 < tmax
        ray{vec3(0.0f, 0.0f, -2.0f), vec3(0.0f, 0.0f, 1.0f), 2.0f, inf},        // t = 2 = tmin
        ray{vec3(0.0f, 0.0f, -2.0f), vec3(0.0f, 0.0f, 1.0f), 1.0f, inf},        // t = 2 > tmin
    };
    brute_force exact;
    exact.build(s);
    std::vector<hit> want(rays.size());
    exact.intersect(rays, want);
    const std::vector<bool> expected = {false, false, true, false, true};
    for (std::size_t i = 0; i < rays.size(); ++i) REQUIRE(want[i].found() == expected[i]);
    // The packet and stream rows too, on rows of 2 rays: 5 rays make partial tiles.
    std::vector<std::string> names = {"embree-medium", "embree-high"};
    for (const tiled_row& row : tiled_rows) names.push_back(row.name);
    for (const std::string& name : names) {
        const std::unique_ptr<accel> a = make_built(name, s, registry_options{1, 2});
        std::vector<hit> got(rays.size());
        std::vector<std::uint8_t> blocked(rays.size(), 7);
        a->intersect(rays, got);
        a->occluded(rays, blocked);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            INFO(name << ", ray " << i);
            CHECK(got[i].found() == expected[i]);
            CHECK(bool(blocked[i]) == expected[i]);
            if (expected[i]) CHECK(got[i].t == want[i].t);
        }
    }
}

TEST_CASE("ch16 embree: its own report names the version and the kernels it runs", "[ch16][embree]") {
    const embree_report& r = embree_configuration();
    if (!embree_available()) {
        CHECK(r.summary() == "no Embree");
        return;
    }
    CHECK(r.version.rfind("3.", 0) == 0);
    REQUIRE_FALSE(r.kernels.empty());
    CHECK((" " + r.supported + " ").find(" " + r.kernels + " ") != std::string::npos);
    CHECK((" " + r.compiled + " ").find(" " + r.kernels + " ") != std::string::npos);
    CHECK(r.summary().find(r.kernels) != std::string::npos);
    WARN("Embree's report: " << r.summary() << " (CPU supports " << r.supported << "; compiled for " << r.compiled << ")");
}

// Embree's traversal asserts tnear >= 0 and components within 1.844e18, and aborts the process otherwise:
// the wrapper must answer those rays itself (with brute force), and pass Embree only the others.
TEST_CASE("ch16 embree: rays Embree cannot take (negative tmin, huge components) get brute force's answer, "
          "no abort", "[ch16][embree]") {
    if (skipped_without_embree()) return;
    const scene s = builtin_scene("teapot");
    std::vector<ray> rays = primary_rays(s, 16, 12);
    const std::size_t n = rays.size();
    for (std::size_t i = 0; i < n; ++i) {
        ray r = rays[i];
        r.tmin = -1e-3f;
        rays.push_back(r);  // a negative tmin
        r = rays[i];
        r.tmin = -5.0f;     // far behind the camera: hits behind the origin count too
        rays.push_back(r);
        r = rays[i];
        r.dir *= 1e19f;     // a huge direction: the same line, t scaled down
        rays.push_back(r);
        r = rays[i];
        r.org.x += 1e19f;   // a huge origin
        rays.push_back(r);
    }
    brute_force exact;
    exact.build(s);
    std::vector<hit> want(rays.size());
    std::vector<std::uint8_t> want_any(rays.size());
    exact.intersect(rays, want);
    exact.occluded(rays, want_any);
    std::size_t found = 0;
    for (std::size_t i = n; i < rays.size(); ++i) found += want[i].found();
    CHECK(found > 0);
    for (const char* name : {"embree-medium", "embree-high"}) {
        const std::unique_ptr<accel> a = make_built(name, s);
        std::vector<hit> got(rays.size());
        std::vector<std::uint8_t> blocked(rays.size(), 7);
        a->intersect(rays, got);
        a->occluded(rays, blocked);
        std::size_t differ = 0;
        for (std::size_t i = n; i < rays.size(); ++i)
            differ += !agrees(got[i], want[i], true) || blocked[i] != want_any[i];
        INFO(name);
        CHECK(differ == 0);
    }
}

TEST_CASE("ch16 embree: its own instancing agrees with the instanced brute force, instance ids included",
          "[ch16][embree]") {
    if (skipped_without_embree()) return;
    const scene s = builtin_scene("teapot_field");
    const std::unique_ptr<accel> a = make_built("embree-medium-instanced", s);
    const std::unique_ptr<accel> brute = make_built("ch10-brute-instanced", s);
    CHECK(a->name() == "embree-medium-instanced");
    // Rays from the camera's eye at every 23rd triangle's centre: nearly all of them meet a teapot.
    std::vector<ray> rays;
    for (std::size_t i = 0; i < s.mesh.triangle_count(); i += 23) {
        const auto t = s.mesh.triangle(i);
        rays.push_back({s.camera.eye, (t[0] + t[1] + t[2]) / 3.0f - s.camera.eye});
    }
    std::vector<hit> got(rays.size()), want(rays.size());
    a->intersect(rays, got);
    brute->intersect(rays, want);
    std::size_t differ = 0, found = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        found += want[i].found();
        differ += got[i].prim != want[i].prim || got[i].inst != want[i].inst ||
                  (want[i].found() && std::abs(got[i].t - want[i].t) > 1e-4f * want[i].t);
    }
    WARN("embree instanced vs instanced brute force: " << differ << " of " << rays.size() << " rays differ");
    CHECK(found > rays.size() * 9 / 10);
    CHECK(differ <= rays.size() / 100);
}
