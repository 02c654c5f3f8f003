// Exercise 10.3 the two-level walk: the closest hit through both levels against the instanced brute force
// (the chapter's oracle), and the counters that show the top level at work: a ray that misses every
// instance tests one box, and a hit in a near instance keeps a far one from being entered. Every instance
// here is placed by its vertices, its transform the identity: the world ray is used as it is, so these
// tests need nothing of exercise 10.1.
#include "exactness.hpp"
#include "nasty_rays.hpp"
#include "test_support.hpp"
#include "strahl/ch10/accel.hpp"
#include "strahl/ch10/two_level.hpp"
#include "strahl/instancing.hpp"
#include "strahl/procedural.hpp"
#include <catch2/catch.hpp>

using namespace strahl;
using namespace strahl::ch10;

namespace {

// Closest hits of the two-level accel against the instanced brute force: t, u, v, triangle and instance.
std::size_t walk_disagreements(const scene& s, const std::vector<ray>& rays, std::size_t& found) {
    auto two = make_accel();
    auto brute = make_brute_accel();
    two->build(s);
    brute->build(s);
    std::vector<hit> got(rays.size()), ref(rays.size());
    two->intersect(rays, got);
    brute->intersect(rays, ref);
    std::size_t wrong = 0;
    found = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        found += ref[i].found();
        if (test::bit_equal(got[i], ref[i]) && got[i].inst == ref[i].inst) continue;
        if (++wrong <= 3)
            FAIL_CHECK("ray " << i << ": t " << got[i].t << " triangle " << got[i].prim << " instance " << got[i].inst
                              << ", instanced brute force t " << ref[i].t << " triangle " << ref[i].prim
                              << " instance " << ref[i].inst);
    }
    return wrong;
}

std::vector<ray> walk_rays(const aabb& box, std::uint64_t seed, std::size_t n) {
    test::nasty_ray_maker m(box, seed);
    std::vector<ray> rays;
    m.add_random_and_axis(rays, n);
    m.add_degenerate(rays);
    return rays;
}

// mesh scaled and moved so that its box is [lo, hi] (the vertices themselves: no transform).
triangle_mesh fitted(triangle_mesh mesh, vec3 lo, vec3 hi) {
    const aabb b = mesh.bounds();
    for (vec3& p : mesh.positions) p = lo + (p - b.min) / b.extent() * (hi - lo);
    return mesh;
}

// Instances of the meshes, instance i of mesh which[i], every transform the identity.
scene identity_instances(std::vector<triangle_mesh> meshes, const std::vector<std::uint32_t>& which) {
    instanced_meshes inst;
    for (std::size_t m = 0; m < meshes.size(); ++m) inst.names.push_back("mesh " + std::to_string(m));
    inst.meshes = std::move(meshes);
    for (const std::uint32_t m : which) inst.instances.push_back({m, affine{}});
    return instanced_scene(std::move(inst), "identity instances");
}

}  // namespace

TEST_CASE("10.3 two-level walk: a plain scene, one instance, has brute force's closest hits bit for bit",
          "[ch10][pts:1]") {
    for (const char* name : {"teapot", "soup", "cornell"}) {
        const scene s = builtin_scene(name);
        INFO(name);
        std::size_t found = 0;
        CHECK(walk_disagreements(s, walk_rays(s.mesh.bounds(), 31, 1500), found) == 0);
        CHECK(found > 100);
    }
}

TEST_CASE("10.3 two-level walk: a hit names its instance and its flattened triangle, a tie the lower instance",
          "[ch10][pts:1]") {
    // Three teapots side by side and a soup across them; instance 3 is instance 0 again (every hit on it a
    // tie, which the lower instance wins); flattened ids run over the instances in order.
    std::vector<triangle_mesh> meshes;
    for (int i = 0; i < 3; ++i)
        meshes.push_back(fitted(teapot_mesh(3), vec3(2.0f * float(i), 0, 0), vec3(2.0f * float(i) + 1.5f, 1, 1)));
    meshes.push_back(fitted(random_soup(400, 7, 0.1f), vec3(0, -0.5f, -0.5f), vec3(5.5f, 1.5f, 1.5f)));
    const scene s = identity_instances(std::move(meshes), {0, 1, 2, 0, 3});
    std::size_t found = 0;
    CHECK(walk_disagreements(s, walk_rays(s.instances->bounds(), 32, 3000), found) == 0);
    CHECK(found > 300);
}

TEST_CASE("10.3 two-level walk: the top level culls: a ray that misses every instance tests one box, no triangle",
          "[ch10][pts:1]") {
    // 64 instances in an 8 x 8 field; rays above it that miss the top level's root box. Visiting every
    // instance instead of walking the top level would test 64 mesh boxes per ray.
    std::vector<triangle_mesh> meshes;
    std::vector<std::uint32_t> which;
    for (int i = 0; i < 64; ++i) {
        const vec3 at(2.0f * float(i % 8), 2.0f * float(i / 8), 0.0f);
        meshes.push_back(fitted(random_soup(40, 100 + std::uint64_t(i), 0.3f), at, at + vec3(1.0f)));
        which.push_back(std::uint32_t(i));
    }
    const scene s = identity_instances(std::move(meshes), which);
    two_level t;
    t.build(*s.instances);
    for (int k = 0; k < 50; ++k) {
        const ray r{vec3(-3.0f + 0.4f * float(k), -3.0f, 3.0f), vec3(0.1f, 1.0f, 0.05f * float(k % 5))};
        counting c;
        const hit h = t.closest(r, c);
        INFO("ray " << k);
        CHECK(!h.found());
        CHECK(c.v.box_tests == 1);
        CHECK(c.v.prim_tests == 0);
    }
    // And the field's hits are brute force's.
    std::size_t found = 0;
    CHECK(walk_disagreements(s, walk_rays(s.instances->bounds(), 33, 1500), found) == 0);
    CHECK(found > 100);
}

TEST_CASE("10.3 two-level walk: a hit in a near instance shortens the ray, and the far instance is never entered",
          "[ch10][pts:1]") {
    // Instance 0 a wall of two triangles at z = 1; instance 1 a teapot of thousands behind it, z in [5, 7].
    // Rays along +z through the teapot's shadow: each hits the wall, and with the world ray's tmax taken from
    // the object ray after instance 0, the top level drops instance 1 (or its mesh tree's root box does).
    triangle_mesh wall;
    wall.positions = {vec3(-4, -4, 1), vec3(4, -4, 1), vec3(4, 4, 1), vec3(-4, 4, 1)};
    wall.indices = {uvec3(0, 1, 2), uvec3(0, 2, 3)};
    const triangle_mesh teapot = fitted(teapot_mesh(8), vec3(-1, -1, 5), vec3(1, 1, 7));
    REQUIRE(teapot.triangle_count() > 1000);
    const scene s = identity_instances({wall, teapot}, {0, 1});
    two_level t;
    t.build(*s.instances);
    std::uint64_t rays = 0;
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 10; ++x) {
            const ray r{vec3(-0.9f + 0.2f * float(x), -0.9f + 0.2f * float(y), -5.0f), vec3(0.001f, 0.002f, 1.0f)};
            counting c;
            const hit h = t.closest(r, c);
            INFO("ray " << x << ", " << y);
            REQUIRE(h.found());
            CHECK(h.inst == 0);
            CHECK(c.v.prim_tests <= 2);  // the wall's two triangles, none of the teapot's
            ++rays;
        }
    CHECK(rays == 100);
}
