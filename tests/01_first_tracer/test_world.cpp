// Chapter 01's shared code (never graded): planes, materials, the brute-force world, the scene builder and
// the renderer's determinism. These use the solutions where they render, so they run in ctest only.
#include "strahl/ch01/render.hpp"
#include "strahl/ch01/shapes.hpp"
#include "strahl/parallel.hpp"
#include "strahl/procedural.hpp"
#include <catch2/catch.hpp>

using namespace strahl;
using namespace strahl::ch01;

TEST_CASE("ch01 plane: hits in (tmin, tmax), parallel and NaN rays miss", "[ch01]") {
    const plane p(vec3(0, 2, 0), 1.0f);  // y = 1 (normal normalised)
    hit h;
    REQUIRE(p.intersect(ray{vec3(0, 3, 0), vec3(0, -1, 0)}, h));
    CHECK(h.t == 2.0f);
    REQUIRE(p.intersect(ray{vec3(0, -3, 0), vec3(1, 2, 0)}, h));  // from below: two-sided
    CHECK(h.t == 2.0f);
    CHECK_FALSE(p.intersect(ray{vec3(0, 3, 0), vec3(0, -1, 0), 0.0f, 2.0f}, h));
    CHECK_FALSE(p.intersect(ray{vec3(0, 3, 0), vec3(0, 1, 0)}, h));
    CHECK_FALSE(p.intersect(ray{vec3(0, 3, 0), vec3(1, 0, 0)}, h));
    CHECK_FALSE(p.intersect(ray{vec3(0, 3, 0), vec3(std::nanf(""), -1, 0)}, h));
    CHECK(p.normal(vec3(0), h) == vec3(0, 1, 0));
    CHECK(p.bounds().min.x == -inf);
}

TEST_CASE("ch01 materials: Lambert, mirror and rough mirror samples", "[ch01]") {
    const vec3 n(0, 1, 0);
    const diffuse d(color(0.5f));
    CHECK(d.shade(n, n, glm::normalize(vec3(1, 1, 0))).r == Approx(0.5f / pi * std::sqrt(0.5f)));
    CHECK(d.shade(n, n, vec3(0, -1, 0)) == color(0.0f));
    CHECK(d.sample_count() == 0);
    const mirror m(color(0.9f));
    pcg32 rng(3);
    const scatter s = m.sample(glm::normalize(vec3(1, -1, 0)), n, 0, rng);
    CHECK(glm::length(s.dir - glm::normalize(vec3(1, 1, 0))) < 1e-6f);
    CHECK(s.weight == color(0.9f));
    const rough_mirror r(color(0.8f), 0.5f, 32);
    CHECK(r.sample_count() == 32);
    color total(0.0f);
    for (int i = 0; i < 32; ++i) {
        const scatter g = r.sample(glm::normalize(vec3(1, -0.2f, 0)), n, i, rng);
        INFO("rough mirror sample " << i << " of 32: direction (" << g.dir.x << ", " << g.dir.y << ", " << g.dir.z
                                    << ")");
        CHECK(glm::dot(g.dir, n) >= 0.0f);
        CHECK(std::abs(glm::length(g.dir) - 1.0f) < 1e-5f);
        total += g.weight;
    }
    CHECK(total.r == Approx(0.8f));
    CHECK_THROWS(rough_mirror(color(1.0f), 0.1f, 0));
}

TEST_CASE("ch01 world: brute force finds the closest of all primitives and counts every test", "[ch01]") {
    world w;
    const auto m = w.add(std::make_unique<diffuse>(color(1.0f)));
    for (int i = 5; i >= 1; --i) w.add(std::make_unique<plane>(vec3(0, 0, 1), float(i), m));
    CHECK_THROWS(w.add(std::make_unique<plane>(vec3(0, 0, 1), 0.0f, 7)));
    counting c;
    surface s;
    REQUIRE(w.closest_hit(ray{vec3(0, 0, 10), vec3(0, 0, -1)}, s, c));
    CHECK(s.h.t == 5.0f);
    CHECK(s.h.prim == 0);
    CHECK(s.p == vec3(0, 0, 5));
    CHECK(s.n == vec3(0, 0, 1));
    CHECK(s.mat == w.materials[0].get());
    REQUIRE(w.closest_hit(ray{vec3(0, 0, -10), vec3(0, 0, 1)}, s, c));
    CHECK(s.h.prim == 4);
    CHECK(s.n == vec3(0, 0, -1));  // turned to face the ray
    CHECK(c.values().rays == 2);
    CHECK(c.values().prim_tests == 10);
    CHECK_FALSE(w.closest_hit(ray{vec3(0, 0, 10), vec3(0, 0, 1)}, s, c));
    CHECK(w.occluded(ray{vec3(0, 0, 10), vec3(0, 0, -1)}, c));
    CHECK(c.values().prim_tests == 16);  // the any-hit query stopped at the first plane
    CHECK_FALSE(w.occluded(shadow_ray(vec3(0, 0, 5), vec3(0, 0, 1), vec3(0, 0, 9)), c));
}

TEST_CASE("ch01 build_world: one object per triangle, sphere and plane, with their materials", "[ch01]") {
    const scene s = cornell_box(true);
    world_counts n;
    const world w = build_world(s, 8, &n);
    CHECK(n.triangles == 10);
    CHECK(n.spheres == 2);
    CHECK(n.planes == 0);
    CHECK(w.primitives.size() == 12);
    CHECK(w.materials.size() == s.materials.size());
    CHECK(w.materials[4]->sample_count() == 8);
    CHECK(w.primitives[6]->material() == 1);
    CHECK(w.lights.size() == s.lights.size());
    const world t = build_world(teapot_scene(2), 16, &n);
    CHECK(n.triangles == 256);
    CHECK(n.planes == 1);
    scene bad = cornell_box(true);
    bad.spheres[0].material = 99;
    CHECK_THROWS(build_world(bad));
}

TEST_CASE("ch01 render: same seed, any thread count: bit-identical images and equal counts", "[ch01][render]") {
    const world w = build_world(cornell_box(true), 4);
    const camera cam(cornell_box(true).camera, 48, 40);
    render_settings settings;
    settings.max_depth = 3;
    settings.tile_size = 8;
    render_result one, two, again;
    {
        const thread_limit limit(1);
        one = render(w, cam, settings);
    }
    {
        const thread_limit limit(2);
        two = render(w, cam, settings);
        again = render(w, cam, settings);
    }
    CHECK(one.img.pixels == two.img.pixels);
    CHECK(two.img.pixels == again.img.pixels);
    CHECK(one.counts.total() == two.counts.total());
    CHECK(one.counts.primary == 48 * 40);
    CHECK(one.counts.reflection > 0);
    CHECK(one.counts.shadow > 0);
    CHECK(one.counts.tests.values().rays == one.counts.total());
    CHECK(one.counts.tests.values().prim_tests >= 12 * one.counts.primary);
    settings.seed = 2;
    const render_result other = render(w, cam, settings);
    CHECK(other.img.pixels != one.img.pixels);  // the rough mirror's samples changed
    settings.primary_only = true;
    const render_result primary = render(w, cam, settings);
    CHECK(primary.counts.total() == primary.counts.primary);
}
