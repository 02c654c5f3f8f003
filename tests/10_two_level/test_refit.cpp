// Exercise 10.2 refit (6 points): unchanged boxes give back the same tree bit for bit; moved primitives give
// every node the exact union of its children (of its primitives for a leaf) and the tree's bounds; one leaf
// and the empty tree; a refit tree walked by chapter 05's traversal answers as brute force on the moved mesh.
#include "exactness.hpp"
#include "nasty_rays.hpp"
#include "strahl/ch05/accel.hpp"
#include "strahl/ch05/sah.hpp"
#include "mesh_boxes.hpp"
#include "strahl/ch10/refit.hpp"
#include "strahl/procedural.hpp"
#include "strahl/rng.hpp"
#include <catch2/catch.hpp>
#include <cstring>

using namespace strahl;
using namespace strahl::ch10;
using test::boxes_of;
using test::centroids_of;

namespace {
// Every vertex pushed along a swirl: the tree's shape no longer fits, its boxes must still bound.
triangle_mesh swirled(triangle_mesh m, float amount) {
    for (vec3& p : m.positions) {
        const float a = amount * p.y;
        p = vec3(std::cos(a) * p.x - std::sin(a) * p.z, p.y * (1.0f + 0.3f * amount), std::sin(a) * p.x + std::cos(a) * p.z);
    }
    return m;
}
bool same_box(const ch04::bvh_node& n, const aabb& b) {
    return n.bmin[0] == b.min.x && n.bmin[1] == b.min.y && n.bmin[2] == b.min.z && n.bmax[0] == b.max.x &&
           n.bmax[1] == b.max.y && n.bmax[2] == b.max.z;
}
}  // namespace

TEST_CASE("10.2 refit: the same boxes give back the same tree, bit for bit", "[ch10][pts:1]") {
    const triangle_mesh m = teapot_mesh(4);
    const std::vector<aabb> b = boxes_of(m);
    const ch04::bvh built = ch05::build_sah_bvh_fast(b, centroids_of(b));
    ch04::bvh t = built;
    for (ch04::bvh_node& n : t.nodes) n.bmin[0] = n.bmin[1] = n.bmin[2] = 7.0f, n.bmax[0] = -7.0f;  // forget the boxes
    t.bounds = aabb();
    refit(t, b);
    REQUIRE(t.nodes.size() == built.nodes.size());
    CHECK(std::memcmp(t.nodes.data(), built.nodes.data(), t.nodes.size() * sizeof(ch04::bvh_node)) == 0);
    CHECK(t.bounds.min == built.bounds.min);
    CHECK(t.bounds.max == built.bounds.max);
}

TEST_CASE("10.2 refit: after a deformation every node bounds exactly its children, every leaf its primitives",
          "[ch10][pts:2]") {
    const triangle_mesh m = teapot_mesh(4);
    const std::vector<aabb> b = boxes_of(m);
    ch04::bvh t = ch05::build_sah_bvh_fast(b, centroids_of(b));
    const ch04::bvh before = t;
    const std::vector<aabb> moved = boxes_of(swirled(m, 1.5f));
    refit(t, moved);
    REQUIRE(t.nodes.size() == before.nodes.size());
    for (std::size_t i = 0; i < t.nodes.size(); ++i) {
        const ch04::bvh_node& n = t.nodes[i];
        REQUIRE(n.offset == before.nodes[i].offset);  // the topology is kept
        REQUIRE(n.count == before.nodes[i].count);
        aabb want;
        if (n.is_leaf())
            for (std::uint32_t k = 0; k < n.count; ++k) want.grow(moved[t.prim_ids[n.offset + k]]);
        else
            want = unite(t.nodes[i + 1].box(), t.nodes[n.offset].box());
        REQUIRE(same_box(n, want));
    }
    aabb all;
    for (const aabb& x : moved) all.grow(x);
    CHECK(t.bounds.min == all.min);
    CHECK(t.bounds.max == all.max);
}

TEST_CASE("10.2 refit: a tree of one leaf, and the empty tree", "[ch10][pts:1]") {
    std::vector<aabb> one{aabb{vec3(0), vec3(1)}};
    ch04::bvh t = ch05::build_sah_bvh_fast(one, centroids_of(one));
    REQUIRE(t.nodes.size() == 1);
    one[0] = aabb{vec3(2), vec3(3, 5, 4)};
    refit(t, one);
    CHECK(same_box(t.nodes[0], one[0]));
    CHECK(t.bounds.max == vec3(3, 5, 4));
    ch04::bvh empty;
    refit(empty, {});
    CHECK(empty.nodes.empty());
    CHECK(empty.bounds.is_empty());
}

TEST_CASE("10.2 refit: a refit tree answers as brute force on the deformed mesh", "[ch10][pts:2]") {
    const triangle_mesh m = teapot_mesh(4);
    const std::vector<aabb> b = boxes_of(m);
    const ch04::bvh start = ch05::build_sah_bvh_fast(b, centroids_of(b));
    const triangle_mesh moved = swirled(m, 2.0f);
    // The accel built over the deformed mesh by "building" = refitting the first tree to its boxes.
    auto a = ch05::make_bvh_accel(false, "refit", [&](std::span<const aabb> now, std::span<const vec3>) {
        ch04::bvh t = start;
        refit(t, now);
        return t;
    }, ch05::walk_kind::fast);
    a->build(test::mesh_only(moved));
    test::nasty_ray_maker maker(moved.bounds(), 3);
    std::vector<ray> rays;
    maker.add_random_and_axis(rays, 3000);
    maker.add_degenerate(rays);
    CHECK(test::disagreements_with_brute_force(*a, moved, rays) == 0);
}
