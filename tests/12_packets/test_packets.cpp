// Chapter 12 beyond the exercises (0 points): every packet walk answers exactly as brute force does, on tiles
// of real ray sets (primary, diffuse and shadow rays; partial tiles at the image's edge and the batch's end),
// on consecutive packets of rays made to break it (every octant mixed in one packet, rays along the axes, NaN
// and Inf, zero and denormal direction components, empty intervals), on ties and on a scene far from the
// origin; and the lane counts add up.
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch05/sah.hpp"
#include "strahl/ch12/accel.hpp"
#include "strahl/ch12/frustum_walk.hpp"
#include "strahl/ch12/packet.hpp"
#include "strahl/procedural.hpp"
#include "strahl/tree_query.hpp"
#include "packet_cases.hpp"
#include "exactness.hpp"
#include "test_support.hpp"
#include "strahl/ch05/accel.hpp"
#include <catch2/catch.hpp>
#include <memory>
#include <cstring>
#include "strahl/rng.hpp"

using namespace strahl;
using namespace strahl::ch12;
using strahl::test::scalar_entry;

namespace {

std::vector<packet_config> all_configs(int width) {
    using w = walk_kind;
    return {{w::masked, 4, 2, 2, width},    {w::masked, 8, 4, 2, width},      {w::masked, 16, 4, 4, width},
            {w::ranged, 16, 8, 8, width},   {w::ranged, 16, 16, 16, width},   {w::partition, 16, 8, 8, width},
            {w::partition, 16, 16, 16, width}, {w::wide, 8, 4, 2, width},     {w::wide, 16, 4, 4, width},
            {w::frustum, 16, 4, 4, width}};
}

void check_exact(const scene& s, const std::vector<ray>& rays, int width) {
    for (const packet_config& c : all_configs(width)) {
        const auto a = make_accel("test", c);
        a->build(s);
        INFO(describe(c) << ", rows of " << width << ", " << rays.size() << " rays, " << s.mesh.triangle_count() << " triangles");
        CHECK(test::disagreements_with_brute_force(*a, s.mesh, rays) == 0);
    }
}

}  // namespace

TEST_CASE("ch12 packets: every walk equals brute force on tiles of the teapot's primary, diffuse and shadow rays",
          "[ch12]") {
    const scene s = teapot_scene(4);
    // 36 x 27: tiles cut by the right edge and by the last rows; secondary rays follow the hits, so their
    // batch is no whole number of rows.
    for (const ch01::ray_kind kind : {ch01::ray_kind::primary, ch01::ray_kind::diffuse, ch01::ray_kind::shadow}) {
        INFO(ch01::to_string(kind) << " rays");
        check_exact(s, test::image_rays(s, 36, 27, kind), 36);
    }
}

TEST_CASE("ch12 packets: every walk equals brute force on rays made to break it, on ties, one triangle, an "
          "empty scene, a flat soup, non-finite triangles, a far scene and far origins", "[ch12][adversarial]") {
    for (const test::packet_case& c : test::packet_cases())
        for (const int width : c.widths) {
            INFO(c.what);
            check_exact(c.s, c.rays, width);
        }
}

TEST_CASE("ch12 packets: lane counts add up, and packets visit fewer nodes than their rays alone", "[ch12]") {
    const scene s = teapot_scene(4);
    const std::vector<ray> rays = test::image_rays(s, 64, 48, ch01::ray_kind::primary);
    const auto alone = ch05::make_accel(false, {}, ch05::walk_kind::fast);
    alone->build(s);
    std::vector<hit> alone_hits(rays.size());
    const counter_values single = *alone->intersect_counted(rays, alone_hits);
    for (const packet_config& c : all_configs(64)) {
        const auto a = make_accel("test", c);
        a->build(s);
        std::vector<hit> hits(rays.size());
        std::vector<float> per_ray;
        const lane_stats l = a->closest_lanes(rays, hits, &per_ray);
        INFO(describe(c));
        REQUIRE(l.visits.size() == std::size_t(c.lanes) + 1);
        std::uint64_t visits = 0;
        for (const std::uint64_t v : l.visits) visits += v;
        // One entry per vector at a node: per node visit where the packet is one vector, more for large packets.
        // (The frustum walk tests rays at its leaves only: its lanes are counted there.)
        if (c.walk == walk_kind::frustum) CHECK(visits > 0);
        else if (c.tile_w * c.tile_h == c.lanes) CHECK(visits == l.counts.nodes_visited);
        else CHECK(visits >= l.counts.nodes_visited);
        CHECK(l.counts.rays == rays.size());
        CHECK(l.packets == (64 / std::size_t(c.tile_w)) * ((48 + std::size_t(c.tile_h) - 1) / std::size_t(c.tile_h)));
        WARN(describe(c) << ": " << l.mean_active() << " active lanes of " << c.lanes);
        CHECK((l.mean_active() > 0.0 && l.mean_active() <= c.lanes));
        for (const float u : per_ray) CHECK((u >= 0.0f && u <= 1.0f));  // (0: a packet of rays that miss the scene)
        // A packet visits fewer nodes than its rays would alone (chapter 05's walk of the same tree): the
        // visits are shared.
        CHECK(l.counts.nodes_visited < single.nodes_visited);
    }
}

TEST_CASE("ch12 packets: a batch of fewer rows than a tile still fills the packets", "[ch12]") {
    // A thread's chunk of a small ray set may hold one row of the image: its tiles are 16 x 1, not 4 x 1.
    const scene s = teapot_scene(4);
    const std::vector<ray> rays = test::image_rays(s, 64, 48, ch01::ray_kind::primary);
    const std::span<const ray> one_row(rays.data() + 64 * 20, 64 + 5), three_rows(rays.data() + 64 * 20, 3 * 64);
    for (const walk_kind w : {walk_kind::wide, walk_kind::masked}) {
        const auto a = make_accel("test", packet_config{w, 16, 4, 4, 64});
        a->build(s);
        std::vector<hit> hits(three_rows.size());
        INFO(to_string(w));
        CHECK(a->closest_lanes(one_row, std::span(hits).first(one_row.size()), nullptr).packets == 4 + 1);
        CHECK(a->closest_lanes(three_rows, hits, nullptr).packets == 3 * 64 / 15 + 1);  // tiles 5 x 3, the last 4 x 3
    }
}

TEST_CASE("ch12 packets: the lanes' terms computed K at a time equal lane_terms bit for bit, refusals included",
          "[ch12]") {
    pcg32 g(1207);
    const tree_frame f(aabb{vec3(-3.0f, 1e-3f, -200.0f), vec3(50.0f, 2.0f, 7.0f)});
    int refused_seen = 0;
    for (int round = 0; round < 300; ++round) {
        auto scalar = std::make_unique<ray_packet<16, 4>>(), lanes = std::make_unique<ray_packet<16, 4>>();
        scalar->clear(), lanes->clear();
        bool ok[64];
        for (int i = 0; i < 64; ++i) {
            ray r{vec3(g.next_float() * 100 - 50, g.next_float() * 4 - 2, g.next_float() * 1e4f - 5e3f),
                  vec3(g.next_float() * 2 - 1, g.next_float() * 2 - 1, g.next_float() * 2 - 1)};
            // Directions the fast test refuses: zero, denormal and tiny components, now and then.
            const std::uint32_t odd = g.next_u32() % 16;
            if (odd == 0) r.dir.y = 0.0f;
            if (odd == 1) r.dir.x = -1e-40f;
            if (odd == 2) r.dir.z = 1e-33f;
            if (odd == 3) r.org.x = -0.0f, r.dir.y = -0.0f;
            r.tmin = g.next_float(), r.tmax = g.next_float() < 0.5f ? inf : 1.0f + 100.0f * g.next_float();
            // Rays no packet takes: an empty interval, a non-finite or absurdly far origin, a vanishing or
            // non-finite direction (placeable's edges: |d|^2 of 1e-30, |o|^2 of 1e36).
            if (odd == 4) r.tmax = r.tmin;
            if (odd == 5) r.org.z = g.next_float() < 0.5f ? std::numeric_limits<float>::quiet_NaN() : -inf;
            if (odd == 6) r.org = vec3(1e18f, 0.0f, 0.0f) * (g.next_float() < 0.5f ? 0.999f : 1.0001f);
            if (odd == 7) r.dir = glm::normalize(r.dir) * (1e-15f * (g.next_float() < 0.5f ? 0.999f : 1.0001f));
            if (odd == 8) r.dir.x = g.next_float() < 0.5f ? inf : 3e19f;
            const lane_terms l(r, f);
            ok[i] = l.ok && r.tmin < r.tmax && placeable(r);
            scalar->set(i, r, l, std::uint32_t(i));
            lanes->set_ray(i, r, std::uint32_t(i));
        }
        unsigned refused[4];
        lanes->set_terms(f, refused);
        for (int i = 0; i < 64; ++i) {
            INFO("round " << round << ", lane " << i);
            CHECK(bool((refused[i / 16] >> (i % 16)) & 1u) == !ok[i]);
            refused_seen += !ok[i];
            if (!ok[i]) continue;  // (a refused lane's terms are never read)
            for (int a = 0; a < 3; ++a) {
                CHECK(std::memcmp(&lanes->inv[a][i], &scalar->inv[a][i], 4) == 0);
                CHECK(std::memcmp(&lanes->org_near[a][i], &scalar->org_near[a][i], 4) == 0);
                CHECK(std::memcmp(&lanes->org_far[a][i], &scalar->org_far[a][i], 4) == 0);
            }
            CHECK(std::memcmp(&lanes->slack[i], &scalar->slack[i], 4) == 0);
            CHECK(std::memcmp(&lanes->t0[i], &scalar->t0[i], 4) == 0);
            CHECK(std::memcmp(&lanes->t1[i], &scalar->t1[i], 4) == 0);
        }
    }
    CHECK(refused_seen > 100);
}

TEST_CASE("ch12 packets: a child the frustum says every lane enters, every lane enters", "[ch12]") {
    // The wide walk lets a coherent packet into such a child without testing its rays: sound only if each
    // lane's own test (chapter 05's fast slab test) would enter it, and the frustum's entry bound lies below
    // each lane's entry. Tiles of rays towards a patch, boxes along their way, and boxes that one lane
    // misses by a hair (2^-17 of the coordinates, beyond the lanes' widening) while the others enter.
    pcg32 g(1212);
    const tree_frame f(aabb{vec3(-5), vec3(5)});
    int covered = 0, candidates = 0, dangerous = 0;
    for (int round = 0; round < 3000; ++round) {
        auto p = std::make_unique<ray_packet<16, 1>>();
        p->clear();
        const auto in = [&](float s) { return s * vec3(g.next_float() - 0.5f, g.next_float() - 0.5f, g.next_float() - 0.5f); };
        const vec3 from = in(8.0f), towards = in(6.0f) - from;
        const float spread = round % 2 ? 0.02f : 0.2f;
        for (int i = 0; i < 16; ++i) {
            ray r{from + (round % 3 == 0 ? in(0.02f) : vec3(0.0f)), glm::normalize(towards) + in(spread)};
            r.tmin = g.next_float() < 0.3f ? 0.5f * g.next_float() : 0.0f;
            r.tmax = g.next_float() < 0.3f ? 1.0f + 10.0f * g.next_float() : inf;
            p->set(i, r, lane_terms(r, f), std::uint32_t(i));
        }
        p->finish(f);
        if (!p->coherent) continue;
        ch13::wide_node<8> n;
        int lone[8] = {-1, -1, -1, -1, -1, -1, -1, -1};  // the lane a grazing box is made to miss
        for (int c = 0; c < 8; ++c) {
            const int lane = int(g.next_u32() % 16);
            const vec3 o(p->org[0][lane], p->org[1][lane], p->org[2][lane]), d(p->dir[0][lane], p->dir[1][lane], p->dir[2][lane]);
            const vec3 q = o + (0.5f + 6.0f * g.next_float()) * d;
            aabb box{q - vec3(0.05f + 2.0f * g.next_float()), q + vec3(0.05f + 2.0f * g.next_float())};
            if (c >= 4) {
                // Ends at q on axis a (the lane leaves its slab there), starts a hair past q on axis b.
                const int a = int(g.next_u32() % 3), b = (a + 1 + int(g.next_u32() % 2)) % 3;
                const float gap = 0x1p-17f * (std::fabs(q[b]) + std::fabs(o[b]) + 1.0f);
                if (d[a] > 0) box.max[a] = q[a]; else box.min[a] = q[a];
                if (d[b] > 0) box.min[b] = q[b] + gap; else box.max[b] = q[b] - gap;
                lone[c] = lane;
            }
            for (int a = 0; a < 3; ++a) n.lo[a][c] = box.min[a], n.hi[a][c] = box.max[a];
            n.child[c] = std::uint32_t(c);
        }
        float t0_hi = -inf, t1_lo = inf;
        for (int i = 0; i < 16; ++i) t0_hi = std::max(t0_hi, p->t0[i]), t1_lo = std::min(t1_lo, p->t1[i]);
        simd::vfloat<8> entry;
        unsigned all = 0;
        const unsigned maybe = frustum_children<true>(*p, n, entry, t0_hi, t1_lo, &all);
        candidates += std::popcount(maybe), covered += std::popcount(all);
        for (int c = 4; c < 8; ++c) {
            int others = 0;
            for (int i = 0; i < 16; ++i) others += i != lone[c] && scalar_entry(*p, i, n.box(c)) != inf;
            dangerous += scalar_entry(*p, lone[c], n.box(c)) == inf && others == 15;
        }
        for (unsigned b = all; b != 0; b &= b - 1) {
            const int c = std::countr_zero(b);
            for (int i = 0; i < 16; ++i) {
                INFO("round " << round << ", child " << c << ", lane " << i);
                const float t = scalar_entry(*p, i, n.box(c));
                REQUIRE(t != inf);
                REQUIRE(entry[c] <= t);
            }
        }
    }
    WARN("covered " << covered << " of " << candidates << " children the frustum may enter; " << dangerous
                    << " boxes missed by one lane alone");
    CHECK(covered > candidates / 4);
    CHECK(dangerous > 100);
}

TEST_CASE("ch12 packets: configurations not built are refused, naming what is", "[ch12]") {
    CHECK_THROWS_WITH(make_accel("x", {walk_kind::masked, 16, 8, 8, 0}), Catch::Contains("not built"));
    CHECK_THROWS_WITH(make_accel("x", {walk_kind::wide, 16, 3, 5, 0}), Catch::Contains("no whole number"));
    CHECK_THROWS_WITH(make_accel("x", {walk_kind::ranged, 4, 8, 8, 0}), Catch::Contains("masked 2x2"));
}
