// ray_frame (ray_frame.hpp): far origins moved along their line to just before the scene, the interval
// shifted with them, t0 added back to the hit; near origins and rays that cannot be placed left alone.
#include "strahl/procedural.hpp"
#include "strahl/ray_frame.hpp"
#include <catch2/catch.hpp>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

using namespace strahl;

namespace {

// The box [-1, 1]^3: centre 0, diagonal 2 sqrt(3) = 3.46; origins beyond 16 diagonals (55.4) move.
const aabb unit_box{vec3(-1.0f), vec3(1.0f)};

bool same_ray(const ray& a, const ray& b) {
    return std::bit_cast<std::array<std::uint32_t, 8>>(a) == std::bit_cast<std::array<std::uint32_t, 8>>(b);
}

}  // namespace

TEST_CASE("ray_frame: origins near the scene stay exactly as they are", "[common][ray_frame]") {
    const ray_frame f(unit_box);
    REQUIRE(f.active());
    for (const vec3 o : {vec3(0.3f, -0.2f, 0.1f), vec3(50.0f, 0.0f, 0.0f), vec3(-30.0f, 30.0f, 30.0f)}) {
        const ray r{o, vec3(-0.2f, 0.9f, 0.1f), 0.25f, 7.0f};
        float t0 = 99.0f;
        CHECK_FALSE(f.moves(r));
        CHECK(same_ray(f.moved(r, t0), r));
        CHECK(t0 == 0.0f);
    }
}

TEST_CASE("ray_frame: a far origin moves along its line to just before the scene", "[common][ray_frame]") {
    const ray_frame f(unit_box);
    const float diagonal = 2.0f * std::sqrt(3.0f);
    for (const float distance : {1e2f, 1e4f, 1e6f, 1e9f}) {
        INFO("origin " << distance << " from the centre");
        const vec3 dir = vec3(-0.6f, -0.3f, -0.74f) * 2.5f;  // not unit length: t is in dir's units
        const ray r{-glm::normalize(dir) * distance + vec3(0.2f, 0.1f, 0.0f), dir, 1.0f, 1e30f};
        REQUIRE(f.moves(r));
        float t0 = 0.0f;
        const ray m = f.moved(r, t0);
        // The new origin lies before the scene, about one diagonal (plus 2^-20 of the distance, the margin
        // for the rounding of org + t0 dir) from its centre.
        const float from_center = glm::length(m.org);
        CHECK(from_center > diagonal);
        CHECK(from_center < 1.5f * diagonal + 0x1p-19f * distance);
        CHECK(glm::dot(-m.org, m.dir) > 0.0f);  // the scene is ahead
        // It lies on the line (up to the rounding of org + t0 dir) and the interval moved by t0.
        const vec3 on_line = r.org + t0 * r.dir;
        CHECK(glm::length(m.org - on_line) <= 1e-6f * distance);
        CHECK(m.dir == r.dir);
        CHECK(m.tmin == r.tmin - t0);
        CHECK(m.tmax == r.tmax - t0);
        CHECK(std::abs(t0 * glm::length(dir) - distance) < 1.5f * diagonal + 0x1p-19f * distance);
    }
}

TEST_CASE("ray_frame: the hit comes back in the ray's own t, a miss stays a miss", "[common][ray_frame]") {
    // A unit triangle in z = 0 seen from z = 1e6 straight down, through the frame: t near 1e6, not near a
    // few diagonals, and the barycentrics of the moved query.
    const ray_frame f(unit_box);
    const ray r{vec3(0.25f, 0.25f, 1e6f), vec3(0, 0, -1), 0.0f, inf};
    float t0 = 0.0f;
    const ray m = f.moved(r, t0);
    const hit h = f.closest(r, [&](const ray& q) {
        CHECK(same_ray(q, m));
        hit x;
        x.t = q.org.z / -q.dir.z;  // the plane z = 0 along the moved ray
        x.prim = 3;
        x.u = x.v = 0.25f;
        return x;
    });
    CHECK(h.prim == 3);
    CHECK(h.t == m.org.z + t0);
    CHECK(h.t == Approx(1e6f));
    const hit miss = f.closest(r, [](const ray&) { return hit{}; });
    CHECK_FALSE(miss.found());
    CHECK(miss.t == inf);
    CHECK(f.any(r, [&](const ray& q) { return same_ray(q, m); }));
}

TEST_CASE("ray_frame: unplaceable rays and unbounded scenes move nothing", "[common][ray_frame]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const ray_frame f(unit_box);
    for (const ray& r : {ray{vec3(nan, 1e6f, 0.0f), vec3(0, -1, 0)}, ray{vec3(inf, 0.0f, 0.0f), vec3(-1, 0, 0)},
                         ray{vec3(1e6f, 0.0f, 0.0f), vec3(0.0f)}, ray{vec3(1e6f, 0.0f, 0.0f), vec3(nan, 0.0f, 0.0f)},
                         ray{vec3(1e6f, 0.0f, 0.0f), vec3(-inf, 0.0f, 0.0f)}}) {
        float t0 = 5.0f;
        CHECK(same_ray(f.moved(r, t0), r));
        CHECK(t0 == 0.0f);
    }
    const ray far{vec3(1e6f, 0.0f, 0.0f), vec3(-1, 0, 0)};
    CHECK_FALSE(ray_frame().moves(far));
    CHECK_FALSE(ray_frame(aabb()).active());
    CHECK_FALSE(ray_frame(aabb{vec3(-inf), vec3(1.0f)}).active());
    scene with_plane;
    with_plane.mesh = tessellated_sphere(4, 8);
    CHECK(ray_frame::of_scene(with_plane).active());
    with_plane.planes.push_back({vec3(0, 1, 0), 0.0f, 0});
    CHECK_FALSE(ray_frame::of_scene(with_plane).active());
}
