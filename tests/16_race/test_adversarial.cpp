// Edge cases every exact structure in the registry must survive with brute force's answers: an empty
// scene, a single triangle, thousands of copies of one triangle (ties: the lowest id wins, closer() in
// ray.hpp), and rays no renderer should send (NaN, Inf, tmin > tmax, a zero direction), which must give
// a defined answer: a miss, not occluded; no crash, no hang.
#include "strahl/procedural.hpp"
#include "strahl/race/brute_force.hpp"
#include "strahl/race/measure.hpp"
#include "strahl/race/ray_sets.hpp"
#include "strahl/race/registry.hpp"
#include <catch2/catch.hpp>
#include <limits>

using namespace strahl;
using namespace strahl::race;

namespace {

constexpr float nan_f = std::numeric_limits<float>::quiet_NaN();

scene one_mesh(triangle_mesh mesh) {
    scene s;
    s.name = "adversarial";
    s.mesh = std::move(mesh);
    return s;
}

// A triangle in the plane z = 0 covering (0, 0), (1, 0), (0, 1).
triangle_mesh unit_triangle() {
    triangle_mesh m;
    m.positions = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)};
    m.indices = {uvec3(0, 1, 2)};
    return m;
}

// Rays from z = 1 straight down onto a grid over [-0.5, 1.5]^2: some hit the unit triangle, some miss.
// The grid is shifted by 0.01 in x so that no ray meets an edge of the triangle (x = 0, y = 0, x + y = 1).
std::vector<ray> grid_rays(int n) {
    std::vector<ray> rays;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            rays.push_back(ray{vec3(-0.49f + 2.0f * (i + 0.5f) / n, -0.5f + 2.0f * (j + 0.5f) / n, 1.0f), vec3(0, 0, -1)});
    return rays;
}

struct answers {
    std::vector<hit> closest;
    std::vector<std::uint8_t> any;
};

answers trace(const accel& a, const std::vector<ray>& rays) {
    answers r{std::vector<hit>(rays.size()), std::vector<std::uint8_t>(rays.size(), 7)};
    a.intersect(rays, r.closest);
    a.occluded(rays, r.any);
    return r;
}

// Calls check(structure name, answers) for every exact structure built on s, after checking that its
// answers equal brute force's.
template <class Check>
void for_each_exact(const scene& s, const std::vector<ray>& rays, Check&& check) {
    brute_force brute;
    brute.build(s);
    const answers ref = trace(brute, rays);
    for (const accel_entry& e : registered_accels()) {
        std::unique_ptr<accel> a = e.make();
        if (!a->exact()) continue;
        INFO("structure " << e.name);
        a->build(s);
        const answers got = trace(*a, rays);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            INFO("ray " << i);
            CHECK(agrees(got.closest[i], ref.closest[i], true));
            CHECK(int(got.any[i]) == int(ref.any[i]));
        }
        check(got);
    }
}

}  // namespace

TEST_CASE("ch16 adversarial: an empty scene, every ray misses", "[ch16][adversarial]") {
    const scene s = one_mesh(triangle_mesh{});
    const std::vector<ray> rays = grid_rays(8);
    for_each_exact(s, rays, [&](const answers& got) {
        for (std::size_t i = 0; i < rays.size(); ++i) {
            CHECK_FALSE(got.closest[i].found());
            CHECK(got.closest[i].t == inf);
            CHECK(got.any[i] == 0);
        }
    });
    // An empty batch of rays is fine too.
    for (const accel_entry& e : registered_accels()) {
        std::unique_ptr<accel> a = e.make();
        a->build(s);
        CHECK_NOTHROW(a->intersect({}, {}));
        CHECK_NOTHROW(a->occluded({}, {}));
    }
}

TEST_CASE("ch16 adversarial: one triangle, hits exactly where it is", "[ch16][adversarial]") {
    const std::vector<ray> rays = grid_rays(16);
    for_each_exact(one_mesh(unit_triangle()), rays, [&](const answers& got) {
        std::size_t hits = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const vec3 o = rays[i].org;
            const bool inside = o.x > 0.0f && o.y > 0.0f && o.x + o.y < 1.0f;  // no grid point lies on an edge
            INFO("ray " << i << " at " << o.x << ", " << o.y);
            CHECK(got.closest[i].found() == inside);
            CHECK(int(got.any[i]) == int(inside));
            if (inside) {
                ++hits;
                CHECK(got.closest[i].prim == 0);
                CHECK(got.closest[i].t == 1.0f);
                CHECK(got.closest[i].u == Approx(o.x));
                CHECK(got.closest[i].v == Approx(o.y));
            }
        }
        CHECK(hits > 0);
    });
}

TEST_CASE("ch16 adversarial: thousands of copies of one triangle, the lowest id wins every tie",
          "[ch16][adversarial]") {
    // Triangles 0..99 lie further away (z = -1), then 3000 identical copies of the unit triangle at z = 0:
    // every ray through the unit triangle ties 3000 ways at t = 1, and the first copy, id 100, must win.
    triangle_mesh m;
    m.positions = {vec3(0, 0, -1), vec3(1, 0, -1), vec3(0, 1, -1), vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)};
    for (int k = 0; k < 100; ++k) m.indices.push_back(uvec3(0, 1, 2));
    for (int k = 0; k < 3000; ++k) m.indices.push_back(uvec3(3, 4, 5));
    const std::vector<ray> rays = grid_rays(12);
    for_each_exact(one_mesh(m), rays, [&](const answers& got) {
        std::size_t hits = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            if (!got.closest[i].found()) continue;
            ++hits;
            INFO("ray " << i);
            CHECK(got.closest[i].prim == 100u);
            CHECK(got.closest[i].t == 1.0f);
            CHECK(got.any[i] == 1);
        }
        CHECK(hits > 0);
    });
    // Rays from below (z = -2, going up) meet the far copies first: the lowest of those, id 0, wins.
    std::vector<ray> up = grid_rays(12);
    for (ray& r : up) r = ray{vec3(r.org.x, r.org.y, -2.0f), vec3(0, 0, 1)};
    for_each_exact(one_mesh(m), up, [&](const answers& got) {
        for (const hit& h : got.closest)
            if (h.found()) CHECK(h.prim == 0u);
    });
}

TEST_CASE("ch16 adversarial: NaN, Inf, empty-interval and zero-direction rays miss", "[ch16][adversarial]") {
    // Rays that would hit the unit triangle (at t = 1) but for one poisoned field each.
    const ray good{vec3(0.25f, 0.25f, 1.0f), vec3(0, 0, -1)};
    std::vector<ray> bad;
    for (int k = 0; k < 3; ++k) {
        for (float value : {nan_f, inf, -inf}) {
            ray r = good;
            r.org[k] = value;
            bad.push_back(r);
            r = good;
            r.dir[k] = value;
            bad.push_back(r);
        }
    }
    for (float value : {nan_f, inf}) {
        ray r = good;
        r.tmin = value;
        bad.push_back(r);
    }
    for (float value : {nan_f, -inf, 0.0f, -1.0f}) {
        ray r = good;
        r.tmax = value;
        bad.push_back(r);
    }
    bad.push_back(ray{good.org, good.dir, 2.0f, 0.5f});  // tmin > tmax around the hit
    bad.push_back(ray{good.org, good.dir, 1.0f, 1.0f});  // an empty open interval at the hit itself
    bad.push_back(ray{good.org, vec3(0.0f), 0.0f, inf});  // zero direction
    bad.push_back(ray{vec3(nan_f), vec3(nan_f), nan_f, nan_f});
    // The unpoisoned ray last: it does hit, so the misses above are not the structure missing everything.
    bad.push_back(good);

    triangle_mesh m = unit_triangle();
    triangle_mesh teapot = teapot_mesh(2);  // more triangles, off to the side, so a tree has something to traverse
    for (vec3& p : teapot.positions) p.x += 10.0f;
    m.append(teapot);
    for_each_exact(one_mesh(m), bad, [&](const answers& got) {
        for (std::size_t i = 0; i + 1 < bad.size(); ++i) {
            const ray& r = bad[i];
            INFO("ray " << i << ": org " << r.org.x << " " << r.org.y << " " << r.org.z << ", dir " << r.dir.x << " "
                        << r.dir.y << " " << r.dir.z << ", t in (" << r.tmin << ", " << r.tmax << ")");
            CHECK_FALSE(got.closest[i].found());
            CHECK(got.closest[i].t == inf);
            CHECK(got.any[i] == 0);
        }
        CHECK(got.closest.back().found());
        CHECK(got.closest.back().prim == 0u);
        CHECK(got.any.back() == 1);
    });
}
