// Chapter 12 beyond the exercises (0 points): every packet walk answers exactly as brute force does, on tiles
// of real ray sets (primary, diffuse and shadow rays; partial tiles at the image's edge and the batch's end),
// on consecutive packets of rays made to break it (every octant mixed in one packet, rays along the axes, NaN
// and Inf, zero and denormal direction components, empty intervals), on ties and on a scene far from the
// origin; and the lane counts add up.
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch05/sah.hpp"
#include "strahl/ch12/accel.hpp"
#include "strahl/procedural.hpp"
#include "bvh_rays.hpp"
#include "exactness.hpp"
#include "test_support.hpp"
#include "strahl/ch05/accel.hpp"
#include <catch2/catch.hpp>

using namespace strahl;
using namespace strahl::ch12;

namespace {

std::vector<packet_config> all_configs(int width) {
    using w = walk_kind;
    return {{w::masked, 4, 2, 2, width},    {w::masked, 8, 4, 2, width},      {w::masked, 16, 4, 4, width},
            {w::ranged, 16, 8, 8, width},   {w::ranged, 16, 16, 16, width},   {w::partition, 16, 8, 8, width},
            {w::partition, 16, 16, 16, width}, {w::wide, 8, 4, 2, width},     {w::wide, 16, 4, 4, width},
            {w::frustum, 16, 4, 4, width}};
}

ch04::bvh binary(const triangle_mesh& m) {
    std::vector<aabb> boxes(m.triangle_count());
    std::vector<vec3> centroids(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const auto t = m.triangle(i);
        boxes[i] = aabb().grow(t[0]).grow(t[1]).grow(t[2]), centroids[i] = boxes[i].centroid();
    }
    return ch05::build_sah_bvh_fast(boxes, centroids);
}

void check_exact(const scene& s, const std::vector<ray>& rays, int width) {
    for (const packet_config& c : all_configs(width)) {
        const auto a = make_accel("test", c);
        a->build(s);
        INFO(describe(c) << ", rows of " << width << ", " << rays.size() << " rays, " << s.mesh.triangle_count() << " triangles");
        CHECK(test::disagreements_with_brute_force(*a, s.mesh, rays) == 0);
    }
}

// An image's primary rays, and the diffuse and shadow rays from their hits.
std::vector<ray> image_rays(const scene& s, int w, int h, ch01::ray_kind kind) {
    const auto exact = ch05::make_accel(false, {}, ch05::walk_kind::fast);  // exact, as every course structure
    exact->build(s);
    return ch01::make_rays(kind, s, w, h, 7, *exact);
}

}  // namespace

TEST_CASE("ch12 packets: every walk equals brute force on tiles of the teapot's primary, diffuse and shadow rays",
          "[ch12]") {
    const scene s = teapot_scene(4);
    // 36 x 27: tiles cut by the right edge and by the last rows; secondary rays follow the hits, so their
    // batch is no whole number of rows.
    for (const ch01::ray_kind kind : {ch01::ray_kind::primary, ch01::ray_kind::diffuse, ch01::ray_kind::shadow}) {
        INFO(ch01::to_string(kind) << " rays");
        check_exact(s, image_rays(s, 36, 27, kind), 36);
    }
}

TEST_CASE("ch12 packets: every walk equals brute force on rays made to break it, in consecutive packets",
          "[ch12][adversarial]") {
    const scene s = teapot_scene(3);
    std::vector<ray> rays = test::nasty_rays(binary(s.mesh), 200, 31);
    // Denormal and tiny direction components, an empty and a reversed interval, a negative tmin.
    for (const float tiny : {1e-40f, -1e-42f, 1e-30f, 1e-20f})
        rays.push_back({vec3(0.1f, 0.2f, -3.0f), vec3(tiny, 0.05f, 1.0f)});
    rays.push_back({vec3(0.0f, 0.3f, -3.0f), vec3(0, 0, 1), 2.0f, 2.0f});
    rays.push_back({vec3(0.0f, 0.3f, -3.0f), vec3(0, 0, 1), 3.0f, 1.0f});
    rays.push_back({vec3(0.0f, 0.3f, 0.0f), vec3(0, 0, 1), -5.0f, inf});
    check_exact(s, rays, 0);
    check_exact(s, rays, 16);  // the same rays as rows of 16: tiles of unrelated rays, every octant mixed
}

TEST_CASE("ch12 packets: ties, one triangle, an empty scene, a flat soup", "[ch12][adversarial]") {
    const auto rays_for = [](const triangle_mesh& m) { return test::nasty_rays(binary(m), 120, 5); };
    const triangle_mesh ties = test::copies(300, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0));
    check_exact(test::mesh_only(ties), rays_for(ties), 0);
    const triangle_mesh one = test::copies(1, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0));
    check_exact(test::mesh_only(one), rays_for(one), 8);
    check_exact(test::mesh_only(triangle_mesh{}), rays_for(one), 0);
    triangle_mesh flat = random_soup(500, 5, 0.1f);
    for (vec3& p : flat.positions) p.z = 0.5f;
    check_exact(test::mesh_only(flat), rays_for(flat), 0);
}

TEST_CASE("ch12 packets: equal brute force on a scene far from the origin, and from far origins", "[ch12][adversarial]") {
    scene s = teapot_scene(3);
    for (vec3& p : s.mesh.positions) p += vec3(3e4f, -1e5f, 2e4f);
    std::vector<ray> rays = test::nasty_rays(binary(s.mesh), 150, 9);
    const vec3 c = s.mesh.bounds().centroid();
    for (int i = 0; i < 40; ++i) {  // origins 1e9 away (moved to the scene by ray_frame), aimed at the teapot
        const vec3 o = c + vec3(1e9f, 3e8f * float(i % 5), -2e8f);
        rays.push_back({o, c + vec3(0.01f * float(i), 0.0f, 0.0f) - o});
    }
    check_exact(s, rays, 0);
}

TEST_CASE("ch12 packets: lane counts add up, and packets visit fewer nodes than their rays alone", "[ch12]") {
    const scene s = teapot_scene(4);
    const std::vector<ray> rays = image_rays(s, 64, 48, ch01::ray_kind::primary);
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

TEST_CASE("ch12 packets: configurations not built are refused, naming what is", "[ch12]") {
    CHECK_THROWS_WITH(make_accel("x", {walk_kind::masked, 16, 8, 8, 0}), Catch::Contains("not built"));
    CHECK_THROWS_WITH(make_accel("x", {walk_kind::wide, 16, 3, 5, 0}), Catch::Contains("no whole number"));
    CHECK_THROWS_WITH(make_accel("x", {walk_kind::ranged, 4, 8, 8, 0}), Catch::Contains("masked 2x2"));
}
