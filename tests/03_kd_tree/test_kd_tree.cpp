// Chapter 03 beyond the exercises (0 points): the k-d tree must give brute force's answers bit for bit
// on scenes and rays made to break it, and build bounded trees on degenerate input.
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch03/accel.hpp"
#include "strahl/procedural.hpp"
#include "exactness.hpp"
#include "nasty_rays.hpp"
#include <catch2/catch.hpp>

using namespace strahl;
using namespace strahl::ch03;

using test::copies;
using test::mesh_only;

namespace {

// Rays made to break a k-d tree: nasty_rays.hpp's random, axis-aligned and degenerate rays, and rays lying
// in, starting on and crossing the split planes of the tree's first six levels.
std::vector<ray> nasty_rays(const kd_tree& t, std::size_t n, std::uint64_t seed) {
    test::nasty_ray_maker m(t.bounds, seed);
    std::vector<ray> rays;
    m.add_random_and_axis(rays, n);
    for (const kd_plane& p : split_planes(t, 6)) {
        const vec3 c = 0.5f * (p.corners[0] + p.corners[2]);  // the middle of the plane's rectangle
        m.add_plane(rays, p.axis, c[p.axis], c);
    }
    m.add_degenerate(rays);
    return rays;
}

// Checks both primitive sets against brute force over triangle_set, closest and any hit, counted too.
void check_exact(const scene& s, std::size_t n_rays) {
    for (const bool is_virtual : {false, true}) {
        const auto a = make_kd_accel(is_virtual);
        a->build(s);
        INFO(a->name() << " on " << s.mesh.triangle_count() << " triangles");
        CHECK(test::disagreements_with_brute_force(*a, s.mesh, nasty_rays(a->tree(), n_rays, 7)) == 0);
    }
}

}  // namespace

TEST_CASE("ch03 k-d tree: both primitive sets equal brute force on the teapot", "[ch03][adversarial]") {
    check_exact(teapot_scene(4), 2000);
}

TEST_CASE("ch03 k-d tree: a random soup and all triangles in one place", "[ch03][adversarial]") {
    check_exact(mesh_only(random_soup(2000, 3, 0.1f)), 2000);
    triangle_mesh clump = random_soup(500, 4, 0.01f);
    for (vec3& p : clump.positions) p = 0.001f * p;  // everything within a thousandth of the origin
    check_exact(mesh_only(clump), 1000);
}

TEST_CASE("ch03 k-d tree: a flat scene, one triangle, an empty scene", "[ch03][adversarial]") {
    triangle_mesh flat = random_soup(1000, 5, 0.1f);
    for (vec3& p : flat.positions) p.z = 0.5f;  // zero extent on z: every triangle planar
    check_exact(mesh_only(flat), 2000);
    check_exact(mesh_only(copies(1, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0))), 500);
    check_exact(mesh_only(triangle_mesh{}), 100);
}

TEST_CASE("ch03 k-d tree: thousands of identical triangles terminate with bounded depth", "[ch03][adversarial]") {
    const scene s = mesh_only(copies(3000, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)));
    const auto a = make_kd_accel(false);
    a->build(s);
    const kd_stats& st = a->tree().stats;
    CHECK(st.depth <= st.depth_limit);
    CHECK(st.depth_limit <= kd_max_depth);
    CHECK(st.references <= 3000 * std::size_t(st.leaves));
    // Ties: the lowest id wins, as with brute force.
    std::vector<ray> rays = {ray{vec3(0.2f, 0.2f, 1.0f), vec3(0, 0, -1)}};
    std::vector<hit> h(1);
    a->intersect(rays, h);
    CHECK(h[0].prim == 0u);
    check_exact(s, 300);
}

TEST_CASE("ch03 k-d tree: the SAH cost of a hand-made tree", "[ch03][adversarial]") {
    // Root [0, 4] x [0, 1] x [0, 1] (area 18) split at x = 1: a leaf of 2 (area 6) and a leaf of 1 (area 14).
    kd_tree t;
    t.bounds = aabb{vec3(0), vec3(4, 1, 1)};
    t.sah = sah_params{1.0f, 1.5f, 0.2f};
    t.nodes = {kd_node::inner(0, 1.0f, 1), kd_node::leaf(0, 2), kd_node::leaf(2, 1)};
    t.prim_refs = {0, 1, 2};
    t.stats.references = 3;
    CHECK(t.sah_cost() == Approx((18.0 + 1.5 * 2 * 6 + 1.5 * 1 * 14) / 18.0));
    CHECK(t.memory_bytes() == 3 * 8 + 3 * 4);
    CHECK(t.nodes[0].axis() == 0);
    CHECK(t.nodes[0].left() == 1u);
    CHECK(t.nodes[2].is_leaf());
    CHECK(t.nodes[2].count == 1u);
    CHECK(t.nodes[2].first() == 2u);
}
