// Exercise 01.3 ray/triangle (4 of its 6 points; the raster oracle has the other 2). Only intersect_triangle.
#include "strahl/ch01/shapes.hpp"
#include <catch2/catch.hpp>

using namespace strahl;

namespace {
const vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);  // the unit right triangle in z = 0

bool hit_tri(const ray& r, const vec3& v0, const vec3& v1, const vec3& v2, float& t, float& u, float& v) {
    t = u = v = -12345.0f;
    return ch01::intersect_triangle(r, v0, v1, v2, t, u, v);
}
bool hits_at(float x, float y) {
    float t, u, v;
    return hit_tri(ray{vec3(x, y, 2), vec3(0, 0, -1)}, a, b, c, t, u, v);
}
}  // namespace

TEST_CASE("01.3 ray/triangle: a hit returns t and the barycentrics u, v, from both sides", "[ch01][pts:1]") {
    float t, u, v;
    REQUIRE(hit_tri(ray{vec3(0.25f, 0.5f, 2), vec3(0, 0, -1)}, a, b, c, t, u, v));
    CHECK(t == Approx(2.0f).epsilon(1e-6));
    CHECK(u == Approx(0.25f).epsilon(1e-6));
    CHECK(v == Approx(0.5f).epsilon(1e-6));
    REQUIRE(hit_tri(ray{vec3(0.25f, 0.5f, 2), vec3(0, 0, -4)}, a, b, c, t, u, v));  // t in units of |dir|
    CHECK(t == Approx(0.5f).epsilon(1e-6));
    REQUIRE(hit_tri(ray{vec3(0.25f, 0.5f, -2), vec3(0, 0, 1)}, a, b, c, t, u, v));  // from behind: two-sided
    CHECK(t == Approx(2.0f).epsilon(1e-6));
    CHECK(u == Approx(0.25f).epsilon(1e-6));
    CHECK(v == Approx(0.5f).epsilon(1e-6));
    // A general triangle and an oblique ray: the hit point from t equals the one from (u, v).
    const vec3 p0(1, 2, 3), p1(-2, 0.5f, 4), p2(0.5f, -1, -2);
    const vec3 target = 0.2f * p0 + 0.5f * p1 + 0.3f * p2;
    const vec3 o(4, 5, -6);
    const ray r{o, (target - o) * 0.7f};
    REQUIRE(hit_tri(r, p0, p1, p2, t, u, v));
    CHECK(u == Approx(0.5f).epsilon(1e-4));
    CHECK(v == Approx(0.3f).epsilon(1e-4));
    CHECK(glm::length(r.at(t) - ((1 - u - v) * p0 + u * p1 + v * p2)) < 1e-4f);
    CHECK(t == Approx(1.0f / 0.7f).epsilon(1e-5));
}

TEST_CASE("01.3 ray/triangle: edges and vertices are inside, just outside misses", "[ch01][pts:1]") {
    CHECK(hits_at(0.5f, 0.0f));   // edge v0 v1
    CHECK(hits_at(0.0f, 0.5f));   // edge v0 v2
    CHECK(hits_at(0.5f, 0.5f));   // edge v1 v2: u + v == 1
    CHECK(hits_at(0.0f, 0.0f));   // the vertices
    CHECK(hits_at(1.0f, 0.0f));
    CHECK(hits_at(0.0f, 1.0f));
    CHECK_FALSE(hits_at(0.5f, -1e-4f));
    CHECK_FALSE(hits_at(-1e-4f, 0.5f));
    CHECK_FALSE(hits_at(0.5f + 1e-4f, 0.5f));
    CHECK_FALSE(hits_at(1.0f + 1e-4f, 0.0f));
    CHECK_FALSE(hits_at(-1e-4f, -1e-4f));
    CHECK_FALSE(hits_at(2.0f, 2.0f));
    CHECK_FALSE(hits_at(-0.5f, 1.2f));
    float t, u, v;
    REQUIRE(hit_tri(ray{vec3(1, 0, 2), vec3(0, 0, -1)}, a, b, c, t, u, v));
    CHECK(u == Approx(1.0f));
    CHECK(v == Approx(0.0f).margin(1e-6));
}

TEST_CASE("01.3 ray/triangle: only hits inside the open interval (tmin, tmax) count", "[ch01][pts:1]") {
    float t, u, v;
    const vec3 o(0.25f, 0.25f, 2), d(0, 0, -1);  // hit at t = 2
    CHECK_FALSE(hit_tri(ray{o, d, 0.0f, 1.9f}, a, b, c, t, u, v));
    CHECK_FALSE(hit_tri(ray{o, d, 0.0f, 2.0f}, a, b, c, t, u, v));
    CHECK(hit_tri(ray{o, d, 0.0f, 2.1f}, a, b, c, t, u, v));
    CHECK(hit_tri(ray{o, d, 1.9f, inf}, a, b, c, t, u, v));
    CHECK_FALSE(hit_tri(ray{o, d, 2.0f, inf}, a, b, c, t, u, v));
    CHECK_FALSE(hit_tri(ray{o, d, 2.5f, inf}, a, b, c, t, u, v));
    CHECK_FALSE(hit_tri(ray{o, -d}, a, b, c, t, u, v));                            // triangle behind
    CHECK_FALSE(hit_tri(ray{vec3(0.25f, 0.25f, 0), d}, a, b, c, t, u, v));  // origin on it: t = 0 is out
}

TEST_CASE("01.3 ray/triangle: degenerate triangles, parallel rays and NaN rays never hit", "[ch01][pts:1]") {
    float t, u, v;
    const ray down{vec3(0.25f, 0.25f, 2), vec3(0, 0, -1)};
    CHECK_FALSE(hit_tri(down, a, a, a, t, u, v));                                  // a point
    CHECK_FALSE(hit_tri(down, a, b, vec3(2, 0, 0), t, u, v));                      // collinear
    CHECK_FALSE(hit_tri(ray{vec3(0.5f, 0.5f, 2), vec3(0, 0, -1)}, vec3(0), vec3(1, 1, 0), vec3(2, 2, 0), t, u, v));
    CHECK_FALSE(hit_tri(ray{vec3(-1, 0.25f, 0), vec3(1, 0, 0)}, a, b, c, t, u, v));  // in the plane
    CHECK_FALSE(hit_tri(ray{vec3(-1, 0.25f, 1), vec3(1, 0, 0)}, a, b, c, t, u, v));  // above, parallel
    CHECK_FALSE(hit_tri(ray{vec3(-1, 0.25f, 1), vec3(1, 1, 0)}, a, b, c, t, u, v));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    CHECK_FALSE(hit_tri(ray{vec3(nan, 0.25f, 2), vec3(0, 0, -1)}, a, b, c, t, u, v));
    CHECK_FALSE(hit_tri(ray{vec3(0.25f, 0.25f, 2), vec3(0, 0, nan)}, a, b, c, t, u, v));
    CHECK_FALSE(hit_tri(ray{vec3(0.25f, 0.25f, 2), vec3(nan)}, a, b, c, t, u, v));
    CHECK_FALSE(hit_tri(ray{vec3(0.25f, 0.25f, 2), vec3(0, 0, -1), nan, inf}, a, b, c, t, u, v));
    CHECK_FALSE(hit_tri(ray{vec3(0.25f, 0.25f, 2), vec3(0, 0, -1), 0.0f, nan}, a, b, c, t, u, v));
    CHECK_FALSE(hit_tri(down, vec3(nan), b, c, t, u, v));
}
