// Chapter 11's graded exercises: 11.1 the variant's leaf test, 11.2 the triangle test from precomputed
// edges, 11.3 the type-sorted leaf; and the steps they make, exact against brute force.
#include "strahl/ch01/shapes.hpp"
#include "strahl/ch11/shapes.hpp"
#include "strahl/ch11/steps.hpp"
#include "strahl/ch11/triangles.hpp"
#include "strahl/ch11/type_sorted.hpp"
#include "strahl/procedural.hpp"
#include "strahl/rng.hpp"
#include "bvh_rays.hpp"
#include "exactness.hpp"
#include <catch2/catch.hpp>
#include <cstring>
#include <limits>

using namespace strahl;
using namespace strahl::ch11;

namespace {

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof(float)) == 0; }

// Rays through and around the unit cube, some with tmin > 0 or a short tmax, and a few made to break a
// test: parallel to an axis plane, a NaN, an infinite direction, a zero direction.
std::vector<ray> test_rays(std::size_t n, std::uint64_t seed) {
    pcg32 g(seed);
    const auto u = [&] { return g.next_float(); };
    std::vector<ray> rays;
    for (std::size_t i = 0; i < n; ++i) {
        ray r{vec3(u(), u(), u()) * 3.0f - 1.0f, vec3(u(), u(), u()) * 2.0f - 1.0f};
        if (i % 5 == 1) r.tmin = u() * 0.5f;
        if (i % 7 == 2) r.tmax = u() * 2.0f;
        if (i % 11 == 3) r.dir.z = 0.0f;
        rays.push_back(r);
    }
    const float nan = std::numeric_limits<float>::quiet_NaN();
    rays.push_back({vec3(0.2f, 0.2f, -1.0f), vec3(nan, 0.0f, 1.0f)});
    rays.push_back({vec3(0.2f, 0.2f, -1.0f), vec3(0.0f, 0.0f, inf)});
    rays.push_back({vec3(0.2f, 0.2f, -1.0f), vec3(0.0f)});
    return rays;
}

std::vector<shape> test_shapes(std::uint64_t seed) {
    pcg32 g(seed);
    const auto p = [&] { return vec3(g.next_float(), g.next_float(), g.next_float()); };
    std::vector<shape> s;
    for (int i = 0; i < 40; ++i) s.emplace_back(make_triangle(p(), p(), p()));
    s.emplace_back(make_triangle(vec3(0), vec3(1, 0, 0), vec3(2, 0, 0)));  // degenerate
    s.emplace_back(make_triangle(vec3(0, 0, 0.5f), vec3(1, 0, 0.5f), vec3(0, 1, 0.5f)));
    for (int i = 0; i < 10; ++i) s.emplace_back(sphere_shape{p(), 0.05f + 0.3f * g.next_float()});
    s.emplace_back(plane_shape{vec3(0, 1, 0), 0.25f});
    s.emplace_back(plane_shape{glm::normalize(vec3(1, 1, 1)), -0.5f});
    return s;
}

// Chapter 01's object for a shape: the reference.
bool reference(const shape& s, const ray& r, hit& h) {
    if (const auto* t = std::get_if<triangle_shape>(&s)) return ch01::triangle(t->v0, t->v1, t->v2).intersect(r, h);
    if (const auto* sp = std::get_if<sphere_shape>(&s)) return ch01::sphere(sp->center, sp->radius).intersect(r, h);
    // (chapter 01's plane object would normalise the normal once more: its function instead)
    const auto& pl = std::get<plane_shape>(s);
    h.u = h.v = 0.0f;
    return ch01::intersect_plane(r, pl.normal, pl.offset, h.t);
}

// Chapter 11's structure over a scene with spheres and planes, against chapter 01's world (brute force
// through virtual calls): closest hit bit for bit, any hit. Returns the rays that differ.
std::size_t disagreements_with_world(step st, const scene& s, const std::vector<ray>& rays) {
    const auto a = make_accel(st, true);
    a->build(s);
    const ch01::world w = ch01::build_world(s);
    const ray_frame frame = ray_frame::of_scene(s);  // far origins moved as the structure moves them
    std::vector<hit> got(rays.size());
    std::vector<std::uint8_t> blocked(rays.size());
    a->intersect(rays, got);
    a->occluded(rays, blocked);
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        counting c;
        const hit want = frame.closest(rays[i], [&](const ray& r) {
            ch01::surface ref;
            return w.closest_hit(r, ref, c) ? ref.h : hit{};
        });
        const bool occluded = frame.any(rays[i], [&](const ray& r) { return w.occluded(r, c); });
        const bool ok = test::bit_equal(got[i], want) && (blocked[i] != 0) == occluded;
        if (!ok && ++wrong <= 3)
            FAIL_CHECK("step " << info(st).name << ", ray " << i << ": prim " << got[i].prim << " t " << got[i].t
                               << ", brute force prim " << want.prim << " t " << want.t);
    }
    return wrong;
}

}  // namespace

TEST_CASE("11.1 the variant's leaf test: chapter 01's answer for every type, bit for bit", "[ch11][pts:2]") {
    const std::vector<shape> shapes = test_shapes(3);
    std::size_t hits = 0;
    for (const ray& r : test_rays(400, 5))
        for (const shape& s : shapes) {
            hit want;
            const bool expect = reference(s, r, want);
            float t = -7.0f, u = -7.0f, v = -7.0f;
            const bool got = intersect(s, r, t, u, v);
            REQUIRE(got == expect);
            if (got) {
                ++hits;
                CHECK((same_bits(t, want.t) && same_bits(u, want.u) && same_bits(v, want.v)));
            } else {
                CHECK((t == -7.0f && u == -7.0f && v == -7.0f));  // a miss leaves them alone
            }
        }
    CHECK(hits > 500);  // the rays do hit all three types
}

TEST_CASE("11.1 the variant's leaf test: step 2 equals brute force over spheres, planes and triangles", "[ch11][pts:1]") {
    scene s = cornell_box(true);
    s.planes.push_back({vec3(0, 1, 0), 0.05f, 0});
    const auto tree_of = make_accel(step::virtual_calls, true);
    tree_of->build(s);
    CHECK(disagreements_with_world(step::variant, s, test::nasty_rays(tree_of->tree(), 400, 9)) == 0);
    const scene teapot = teapot_scene(3);  // a ground plane
    CHECK(disagreements_with_world(step::variant, teapot, test_rays(300, 7)) == 0);
}

TEST_CASE("11.2 triangles from edges: intersect_triangle's answers bit for bit", "[ch11][pts:2]") {
    std::size_t hits = 0;
    for (const shape& s : test_shapes(11)) {
        const auto* tri = std::get_if<triangle_shape>(&s);
        if (!tri) continue;
        const edge_triangle e = make_edge_triangle(tri->v0, tri->v1, tri->v2);
        for (const ray& r : test_rays(300, 13)) {
            float t0 = -7, u0 = -7, v0 = -7, t1 = -7, u1 = -7, v1 = -7;
            const bool want = ch01::intersect_triangle(r, tri->v0, tri->v1, tri->v2, t0, u0, v0);
            const bool got = intersect_edges(r, e.v0, e.e1, e.e2, t1, u1, v1);
            REQUIRE(got == want);
            CHECK((same_bits(t0, t1) && same_bits(u0, u1) && same_bits(v0, v1)));
            hits += got;
        }
    }
    CHECK(hits > 30);
    // On an edge and at a vertex (edges count), and the tie with the ray's interval.
    const vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    float t, u, v;
    CHECK(intersect_edges(ray{vec3(0.5f, 0.0f, -1.0f), vec3(0, 0, 1)}, a, b - a, c - a, t, u, v));
    CHECK(intersect_edges(ray{vec3(0.0f, 0.0f, 1.0f), vec3(0, 0, -1)}, a, b - a, c - a, t, u, v));
    CHECK_FALSE(intersect_edges(ray{vec3(0.2f, 0.2f, -1.0f), vec3(0, 0, 1), 0.0f, 1.0f}, a, b - a, c - a, t, u, v));
}

TEST_CASE("11.2 triangles from edges: steps 5 and 6 equal brute force on the teapot, a soup and far away",
          "[ch11][pts:2]") {
    triangle_mesh far = teapot_mesh(3);
    for (vec3& p : far.positions) p += vec3(3e4f, -1e5f, 2e4f);
    for (const triangle_mesh& m : {teapot_mesh(3), random_soup(800, 3, 0.1f), far,
                                   test::copies(300, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0))}) {
        for (const step st : {step::inlined, step::soa}) {
            const auto a = make_accel(st);
            a->build(test::mesh_only(m));
            INFO(info(st).name << ", " << m.triangle_count() << " triangles");
            CHECK(test::disagreements_with_brute_force(*a, m, test::nasty_rays(a->tree(), 300, 17)) == 0);
        }
    }
}

TEST_CASE("11.3 the type-sorted leaf: each type's run in the leaf's order, ids beside", "[ch11][pts:2]") {
    const std::vector<shape> shapes = {
        make_triangle(vec3(0), vec3(1, 0, 0), vec3(0, 1, 0)),  // 0
        sphere_shape{vec3(1), 0.5f},                            // 1
        plane_shape{vec3(0, 1, 0), 2.0f},                       // 2
        make_triangle(vec3(5), vec3(6, 5, 5), vec3(5, 6, 5)),  // 3
        sphere_shape{vec3(2), 0.25f},                           // 4
    };
    sorted_primitives out;
    const std::uint32_t leaf1[] = {4, 3, 1, 0};
    const sorted_leaf a = sort_leaf_by_type(leaf1, shapes, out);
    CHECK(a.first == std::array<std::uint32_t, 3>{0, 0, 0});
    CHECK(a.count == std::array<std::uint32_t, 3>{2, 2, 0});
    CHECK(out.ids[0] == std::vector<std::uint32_t>{3, 0});
    CHECK(out.ids[1] == std::vector<std::uint32_t>{4, 1});
    REQUIRE(out.triangles.size() == 2);
    CHECK(out.triangles[0].v0 == vec3(5));
    REQUIRE(out.spheres.size() == 2);
    CHECK(out.spheres[0].radius == 0.25f);
    // A second leaf appends after the first; an empty run starts at its array's end.
    const std::uint32_t leaf2[] = {2, 3};
    const sorted_leaf b = sort_leaf_by_type(leaf2, shapes, out);
    CHECK(b.first == std::array<std::uint32_t, 3>{2, 2, 0});
    CHECK(b.count == std::array<std::uint32_t, 3>{1, 0, 1});
    CHECK(out.ids[2] == std::vector<std::uint32_t>{2});
    REQUIRE(out.planes.size() == 1);
    CHECK(out.planes[0].offset == 2.0f);
    const sorted_leaf c = sort_leaf_by_type(std::span<const std::uint32_t>(), shapes, out);
    CHECK(c.first == std::array<std::uint32_t, 3>{3, 2, 1});
    CHECK(c.count == std::array<std::uint32_t, 3>{0, 0, 0});
}

TEST_CASE("11.3 the type-sorted leaf: step 3 equals brute force, with and without spheres and planes", "[ch11][pts:1]") {
    scene s = cornell_box(true);
    s.planes.push_back({vec3(0, 1, 0), 0.05f, 0});
    const auto tree_of = make_accel(step::virtual_calls, true);
    tree_of->build(s);
    CHECK(disagreements_with_world(step::type_sorted, s, test::nasty_rays(tree_of->tree(), 400, 9)) == 0);
    const triangle_mesh m = random_soup(800, 5, 0.1f);
    const auto a = make_accel(step::type_sorted);
    a->build(test::mesh_only(m));
    CHECK(test::disagreements_with_brute_force(*a, m, test::nasty_rays(a->tree(), 300, 21)) == 0);
}
