// Chapter 04 beyond the exercises (0 points): the BVH must give brute force's answers bit for bit on
// scenes and rays made to break it, and build bounded trees on degenerate input.
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch04/accel.hpp"
#include "strahl/procedural.hpp"
#include "strahl/rng.hpp"
#include "bvh_rays.hpp"
#include "exactness.hpp"
#include <catch2/catch.hpp>
#include <cstring>
#include <limits>

using namespace strahl;
using namespace strahl::ch04;

using test::copies;
using test::mesh_only;
using test::nasty_rays;

namespace {

// Checks both primitive sets and both splits against brute force over triangle_set, closest and any hit,
// counted too.
void check_exact(const scene& s, std::size_t n_rays) {
    for (const split_method m : {split_method::object_median, split_method::spatial_median})
        for (const bool is_virtual : {false, true}) {
            bvh_build_params p;
            p.split = m;
            const auto a = make_bvh_accel(is_virtual, p);
            a->build(s);
            INFO(a->name() << " on " << s.mesh.triangle_count() << " triangles");
            const bvh& t = a->tree();
            CHECK(t.nodes.size() <= std::max<std::size_t>(1, 2 * t.prim_ids.size()) - 1);
            CHECK(t.stats.depth <= bvh_max_depth);
            CHECK(test::disagreements_with_brute_force(*a, s.mesh, nasty_rays(t, n_rays, 7)) == 0);
        }
}

}  // namespace

TEST_CASE("ch04 BVH: the node is 32 bytes, the tree at most 2N - 1 nodes, leaves at most the leaf size",
          "[ch04][adversarial]") {
    STATIC_REQUIRE(sizeof(bvh_node) == 32);
    const scene s = teapot_scene(4);
    for (const int leaf_size : {1, 4, 16}) {
        INFO("leaf size " << leaf_size << " on the teapot");
        bvh_build_params p;
        p.leaf_size = leaf_size;
        const auto a = make_bvh_accel(false, p);
        a->build(s);
        const bvh& t = a->tree();
        const std::size_t n = s.mesh.triangle_count();
        CHECK(t.prim_ids.size() == n);
        CHECK(t.nodes.size() == t.stats.inner + t.stats.leaves);
        CHECK(t.stats.leaves == t.stats.inner + 1);
        CHECK(t.nodes.size() <= 2 * n - 1);
        CHECK(t.stats.max_leaf <= std::size_t(leaf_size));
        CHECK(t.memory_bytes() == t.nodes.size() * 32 + n * 4);
        // Every leaf's box holds its primitives' boxes; every inner box its children's.
        const ch01::triangle_set tris(s.mesh);
        for (std::size_t i = 0; i < t.nodes.size(); ++i) {
            const bvh_node& nd = t.nodes[i];
            const aabb b = nd.box();
            if (nd.is_leaf()) {
                for (std::uint32_t k = nd.offset; k < nd.offset + nd.count; ++k) {
                    INFO("leaf node " << i << "'s box against its triangle " << t.prim_ids[k] << " (prim_ids[" << k
                                      << "])");
                    CHECK(unite(b, tris.bounds(t.prim_ids[k])).surface_area() == b.surface_area());
                }
            } else {
                INFO("inner node " << i << "'s box against its children's, nodes " << i + 1 << " and " << nd.offset);
                CHECK(unite(b, t.nodes[i + 1].box()).surface_area() == b.surface_area());
                CHECK(unite(b, t.nodes[nd.offset].box()).surface_area() == b.surface_area());
            }
        }
    }
}

TEST_CASE("ch04 BVH: both primitive sets and both splits equal brute force on the teapot", "[ch04][adversarial]") {
    check_exact(teapot_scene(4), 1500);
}

TEST_CASE("ch04 BVH: a random soup and all triangles in one place", "[ch04][adversarial]") {
    check_exact(mesh_only(random_soup(1500, 3, 0.1f)), 1500);
    triangle_mesh clump = random_soup(400, 4, 0.01f);
    for (vec3& p : clump.positions) p = 0.001f * p;  // everything within a thousandth of the origin
    check_exact(mesh_only(clump), 800);
}

TEST_CASE("ch04 BVH: a planar scene, one triangle, an empty scene", "[ch04][adversarial]") {
    triangle_mesh flat = random_soup(800, 5, 0.1f);
    for (vec3& p : flat.positions) p.z = 0.5f;  // zero thickness on z: every box flat
    check_exact(mesh_only(flat), 1500);
    check_exact(mesh_only(copies(1, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0))), 400);
    check_exact(mesh_only(triangle_mesh{}), 100);
}

TEST_CASE("ch04 BVH: thousands of identical triangles terminate with bounded depth", "[ch04][adversarial]") {
    const scene s = mesh_only(copies(3000, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)));
    for (const split_method m : {split_method::object_median, split_method::spatial_median}) {
        INFO((m == split_method::object_median ? "object median" : "spatial median")
             << " split, 3000 copies of one triangle, all met by the ray at (0.2, 0.2)");
        const auto a = make_accel(false, m);
        a->build(s);
        // Ties: the lowest id wins, as with brute force.
        std::vector<ray> rays = {ray{vec3(0.2f, 0.2f, 1.0f), vec3(0, 0, -1)}};
        std::vector<hit> h(1);
        a->intersect(rays, h);
        CHECK(h[0].prim == 0u);
    }
    bvh_build_params p;
    p.split = split_method::spatial_median;
    const auto a = make_bvh_accel(false, p);
    a->build(s);
    CHECK(a->tree().stats.depth <= 12);  // halving 3000 down to leaves of 4: depth 10
    check_exact(s, 300);
}

TEST_CASE("ch04 BVH: centroids far apart in a geometric series keep the spatial median's depth bounded",
          "[ch04][adversarial]") {
    triangle_mesh m;
    for (int i = 0; i < 300; ++i) {
        const float x = std::ldexp(1.0f, -i / 2);  // every spatial median peels off a few triangles
        const auto k = std::uint32_t(m.positions.size());
        m.positions.insert(m.positions.end(), {vec3(x, 0, 0), vec3(x, 1, 0), vec3(x, 0, 1)});
        m.indices.push_back(uvec3(k, k + 1, k + 2));
    }
    bvh_build_params p;
    p.split = split_method::spatial_median;
    const auto a = make_bvh_accel(false, p);
    a->build(mesh_only(m));
    CHECK(a->tree().stats.depth <= bvh_max_depth);
    check_exact(mesh_only(m), 400);
}
