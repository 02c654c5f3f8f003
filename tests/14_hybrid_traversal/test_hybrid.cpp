// Chapter 14 beyond the exercises (0 points): the hybrid tracer answers exactly as brute force does at every
// threshold (never leaving, leaving at 1, 2, K/4, K/2, K-2, K-1 lanes, every ray alone from the root, and the
// threshold chosen per packet), on tiles of real ray sets, on rays made to break it, on ties and degenerate
// scenes and far from the origin; rays leave where the threshold says; the renderer's image is unchanged.
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch05/accel.hpp"
#include "strahl/ch05/sah.hpp"
#include "strahl/ch12/render.hpp"
#include "strahl/ch13/accel.hpp"
#include "strahl/ch14/accel.hpp"
#include "strahl/procedural.hpp"
#include "packet_cases.hpp"
#include "exactness.hpp"
#include "test_support.hpp"
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstring>

using namespace strahl;
using namespace strahl::ch14;

namespace {

std::vector<hybrid_config> all_configs(int width) {
    std::vector<hybrid_config> out;
    for (const int k : {8, 16})
        for (const int t : {0, 1, 2, k / 4, k / 2, k - 2, k - 1, k, automatic}) {
            if (k == 8 && t == 2 && !out.empty() && out.back().threshold == 2) continue;  // K/4 = 2 for K = 8
            out.push_back({k, 4, k / 4, width, t});
        }
    for (const int k : {8, 16}) out.push_back({k, 4, k / 4, width, automatic, false, ch13::child_order::collapsed});
    for (const int t : {1, automatic, 16}) {  // the lone rays' closest hit in the octant's order (16 lanes)
        out.push_back({16, 4, 4, width, t});
        out.back().octant_order = true;
    }
    return out;
}

void check_exact(const scene& s, const std::vector<ray>& rays, int width) {
    for (const hybrid_config& c : all_configs(width)) {
        const auto a = make_accel("test", c);
        a->build(s);
        INFO(describe(c) << ", rows of " << width << ", " << rays.size() << " rays, " << s.mesh.triangle_count() << " triangles");
        CHECK(test::disagreements_with_brute_force(*a, s.mesh, rays) == 0);
    }
}

}  // namespace

TEST_CASE("ch14 hybrid: equals brute force at every threshold on tiles of the teapot's primary, diffuse and "
          "shadow rays", "[ch14]") {
    const scene s = teapot_scene(4);
    for (const ch01::ray_kind kind : {ch01::ray_kind::primary, ch01::ray_kind::diffuse, ch01::ray_kind::shadow}) {
        INFO(ch01::to_string(kind) << " rays");
        check_exact(s, test::image_rays(s, 36, 27, kind), 36);
    }
}

TEST_CASE("ch14 hybrid: equals brute force on rays made to break it, on ties, degenerate, non-finite and far scenes",
          "[ch14][adversarial]") {
    for (const test::packet_case& c : test::packet_cases())
        for (const int width : c.widths) {
            INFO(c.what);
            check_exact(c.s, c.rays, width);
        }
}

TEST_CASE("ch14 hybrid: a tree whose leaves name each triangle twice in a row (as an SBVH's may), brute force's "
          "answers", "[ch14][adversarial]") {
    // Chapter 09's spatial splits reference a triangle from several leaves, and the optimal collapse may gather
    // two of them into one wide leaf, side by side; the packet's leaf test must not take a repeated id for the
    // padding past the leaf's end (which repeats the last triangle) and stop there.
    const auto doubled = [](const triangle_mesh& m) {
        const ch04::bvh t = test::binned_tree(m);
        ch04::bvh d = t;
        d.prim_ids.clear();
        for (ch04::bvh_node& n : d.nodes) {
            if (!n.is_leaf()) continue;
            const std::uint32_t first = n.offset;
            n.offset = std::uint32_t(d.prim_ids.size());
            for (std::uint32_t j = first; j < first + n.count; ++j) d.prim_ids.insert(d.prim_ids.end(), 2, t.prim_ids[j]);
            n.count = std::uint16_t(2 * n.count);
        }
        return d;
    };
    const scene s = teapot_scene(4);
    for (const ch01::ray_kind kind : {ch01::ray_kind::primary, ch01::ray_kind::diffuse, ch01::ray_kind::shadow})
        for (hybrid_config c : all_configs(36)) {
            c.builder = doubled;
            const auto a = make_accel("test", c);
            a->build(s);
            INFO(ch01::to_string(kind) << " rays, " << describe(c));
            CHECK(test::disagreements_with_brute_force(*a, s.mesh, test::image_rays(s, 36, 27, kind)) == 0);
        }
}

TEST_CASE("ch14 hybrid: rays leave where the threshold says, and never leaving is chapter 12's wide walk", "[ch14]") {
    const scene s = teapot_scene(4);
    const std::vector<ray> rays = test::image_rays(s, 64, 48, ch01::ray_kind::primary);
    std::vector<hit> hits(rays.size());
    std::vector<float> left;
    const auto lanes_at = [&](int threshold) {
        const auto a = make_accel("test", {16, 4, 4, 64, threshold});
        a->build(s);
        return a->closest_lanes(rays, hits, &left);
    };
    // Never: chapter 12's 16-lane wide walk visits the same nodes with the same lanes, and no ray leaves.
    const auto ch12 = ch12::make_accel("wide", {ch12::walk_kind::wide, 16, 4, 4, 64});
    ch12->build(s);
    const ch12::lane_stats packets = ch12->closest_lanes(rays, hits, nullptr);
    const ch12::lane_stats never = lanes_at(0);
    CHECK(never.counts.nodes_visited == packets.counts.nodes_visited);
    CHECK(never.visits == packets.visits);
    for (const float f : left) CHECK(f == 1.0f);
    // At the root: no node is visited with its lanes by a packet (every visit is a ray's alone), every ray
    // leaves at once, and the packets' box tests are gone.
    const ch12::lane_stats root = lanes_at(16);
    std::uint64_t packet_visits = 0;
    for (const std::uint64_t v : root.visits) packet_visits += v;
    CHECK(packet_visits == 0);
    for (const float f : left) CHECK((f == 0.0f || f == -1.0f));
    // In between: no packet visits a node with `threshold` lanes or fewer; every share of visits lies in [0, 1].
    // More rays leave the higher the threshold (a ray that left reads below 1, even after its packet's last visit).
    std::size_t before = 0;
    for (const int t : {1, 2, 4, 8, 14, 15}) {
        INFO("threshold " << t);
        const ch12::lane_stats l = lanes_at(t);
        for (int k = 0; k <= t; ++k) CHECK(l.visits[std::size_t(k)] == 0);
        for (const float f : left) CHECK((f >= 0.0f && f <= 1.0f));
        const std::size_t gone = std::size_t(std::count_if(left.begin(), left.end(), [](float f) { return f < 1.0f; }));
        CHECK(gone >= before);
        before = gone;
    }
    CHECK(before > rays.size() / 10);
}

TEST_CASE("ch14 hybrid: chapter 12's renderer with the hybrid tracer draws the single-ray image bit for bit", "[ch14]") {
    scene s = teapot_in_stadium(4, 16);
    s.materials.push_back({});
    s.materials.back().kind = material_kind::mirror;
    s.triangle_materials.resize(s.mesh.triangle_count());
    for (std::size_t i = 0; i < s.triangle_materials.size(); ++i)
        s.triangle_materials[i] = i % 3 == 0 ? std::uint32_t(s.materials.size() - 1) : 0u;
    const camera cam = scene_camera(s, 37, 29);
    ch01::render_settings settings;
    settings.max_depth = 3;
    ch13::wide_config wc;
    wc.collapse.method = ch13::collapse_method::optimal;
    const auto single = ch13::make_accel("single", [](std::span<const aabb> b, std::span<const vec3> c) {
        return ch05::build_sah_bvh_fast(b, c);
    }, wc);
    single->build(s);
    const ch01::render_result want = ch12::render_single(*single, s, cam, settings, 0);
    for (const int t : {0, 4, 16, automatic}) {
        const auto hybrid = make_accel("hybrid", {16, 4, 4, 0, t});
        hybrid->build(s);
        const ch01::render_result got = ch12::render_packets(*hybrid, *hybrid, s, cam, settings, 0);
        INFO("threshold " << threshold_name(t));
        REQUIRE(got.img.pixels.size() == want.img.pixels.size());
        CHECK(std::memcmp(got.img.pixels.data(), want.img.pixels.data(), want.img.pixels.size() * sizeof(color)) == 0);
        CHECK(got.counts.total() == want.counts.total());
        CHECK(got.rays_per_pixel == want.rays_per_pixel);
    }
}

TEST_CASE("ch14 hybrid, strict: boxes tested from tmin, far fewer triangle tests for rays leaving the stadium's "
          "field, and said to be inexact", "[ch14]") {
    // Diffuse rays start just above the field, a fan of long flat triangles whose boxes hold the start: the
    // exact walk tests every box from tmin - slack, so those fan triangles are tested (and missed) by every
    // ray; the strict walk starts at tmin and skips them. Not exact by design, yet on these rays (as on the
    // race's) its answers are brute force's: what it gives up is a triangle just behind tmin that rounding
    // could still hit.
    const scene s = teapot_in_stadium(4, 16);
    const std::vector<ray> rays = test::image_rays(s, 64, 48, ch01::ray_kind::diffuse);
    std::vector<hit> hits(rays.size());
    for (const int t : {0, 16, automatic}) {
        INFO("threshold " << threshold_name(t));
        const auto exact = make_accel("exact", {16, 4, 4, 64, t});
        const auto strict = make_accel("strict", {16, 4, 4, 64, t, true});
        exact->build(s), strict->build(s);
        CHECK(exact->exact());
        CHECK_FALSE(strict->exact());
        const std::uint64_t all = exact->closest_lanes(rays, hits, nullptr).counts.prim_tests;
        const std::uint64_t fewer = strict->closest_lanes(rays, hits, nullptr).counts.prim_tests;
        INFO(all << " triangle tests exact, " << fewer << " strict");
        CHECK(fewer * 2 < all);
        CHECK(test::disagreements_with_brute_force(*strict, s.mesh, rays) == 0);
    }
    CHECK_THAT(describe({16, 4, 4, 0, automatic, true}), Catch::Contains("not exact"));
}

TEST_CASE("ch14 hybrid: configurations not built are refused, naming what is", "[ch14]") {
    CHECK_THROWS_WITH(make_accel("x", {16, 8, 2, 0, 0}), Catch::Contains("built: 8 lanes 4x2"));
    CHECK_THROWS_WITH(make_accel("x", {16, 4, 4, 0, 17}), Catch::Contains("threshold 17"));
    CHECK_THROWS_WITH(make_accel("x", {8, 4, 2, 0, -2}), Catch::Contains("not in 0..8"));
    hybrid_config octant8{8, 4, 2, 0, automatic};
    octant8.octant_order = true;
    CHECK_THROWS_WITH(make_accel("x", octant8), Catch::Contains("octant order is built for 16 lanes"));
}
