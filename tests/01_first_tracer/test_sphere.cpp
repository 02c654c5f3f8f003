// Exercise 01.2 ray/sphere (5 points). Only intersect_sphere is used here.
#include "strahl/ch01/shapes.hpp"
#include <catch2/catch.hpp>

using namespace strahl;

namespace {
bool hit_sphere(const ray& r, const vec3& c, float radius, float& t) {
    t = -12345.0f;
    return ch01::intersect_sphere(r, c, radius, t);
}
}  // namespace

TEST_CASE("01.2 ray/sphere: a hit in front gives the near root, for any direction length", "[ch01][pts:1]") {
    float t;
    REQUIRE(hit_sphere(ray{vec3(0, 0, 5), vec3(0, 0, -1)}, vec3(0), 1.0f, t));
    CHECK(t == Approx(4.0f).epsilon(1e-6));
    REQUIRE(hit_sphere(ray{vec3(0, 0, 5), vec3(0, 0, -2)}, vec3(0), 1.0f, t));  // t in units of |dir|
    CHECK(t == Approx(2.0f).epsilon(1e-6));
    REQUIRE(hit_sphere(ray{vec3(0.6f, 0, 5), vec3(0, 0, -1)}, vec3(0), 1.0f, t));
    CHECK(t == Approx(4.2f).epsilon(1e-5));
    // An off-centre sphere and an oblique ray: the hit point lies on the sphere, facing the origin.
    const vec3 c(1, 2, -3), o(-2, 1, 4);
    const ray r{o, glm::normalize(c + vec3(0.5f, -0.3f, 0.2f) - o) * 3.0f};
    REQUIRE(hit_sphere(r, c, 1.5f, t));
    CHECK(glm::length(r.at(t) - c) == Approx(1.5f).epsilon(1e-5));
    CHECK(glm::dot(r.at(t) - c, r.dir) < 0.0f);
}

TEST_CASE("01.2 ray/sphere: misses, spheres behind, tangents and NaN rays", "[ch01][pts:1]") {
    float t;
    CHECK_FALSE(hit_sphere(ray{vec3(0, 0, 5), vec3(0, 0, 1)}, vec3(0), 1.0f, t));     // pointing away
    CHECK_FALSE(hit_sphere(ray{vec3(1.5f, 0, 5), vec3(0, 0, -1)}, vec3(0), 1.0f, t));  // passing by
    CHECK_FALSE(hit_sphere(ray{vec3(1.001f, 0, 5), vec3(0, 0, -1)}, vec3(0), 1.0f, t));  // just outside
    REQUIRE(hit_sphere(ray{vec3(0.999f, 0, 5), vec3(0, 0, -1)}, vec3(0), 1.0f, t));      // just inside
    CHECK(t == Approx(5.0f - std::sqrt(1.0f - 0.999f * 0.999f)).epsilon(1e-4));
    REQUIRE(hit_sphere(ray{vec3(1, 0, 5), vec3(0, 0, -1)}, vec3(0), 1.0f, t));  // exactly tangent: one root
    CHECK(t == Approx(5.0f).epsilon(1e-5));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    CHECK_FALSE(hit_sphere(ray{vec3(nan, 0, 5), vec3(0, 0, -1)}, vec3(0), 1.0f, t));
    CHECK_FALSE(hit_sphere(ray{vec3(0, 0, 5), vec3(0, nan, -1)}, vec3(0), 1.0f, t));
    CHECK_FALSE(hit_sphere(ray{vec3(0, 0, 5), vec3(nan)}, vec3(0), 1.0f, t));
}

TEST_CASE("01.2 ray/sphere: origin inside returns the far root", "[ch01][pts:1]") {
    float t;
    REQUIRE(hit_sphere(ray{vec3(0), vec3(0, 0, 1)}, vec3(0), 2.0f, t));
    CHECK(t == Approx(2.0f).epsilon(1e-6));
    REQUIRE(hit_sphere(ray{vec3(0, 0, 0.5f), vec3(0, 0, 1)}, vec3(0), 1.0f, t));
    CHECK(t == Approx(0.5f).epsilon(1e-6));
    REQUIRE(hit_sphere(ray{vec3(0, 0, 0.5f), vec3(0, 0, -1)}, vec3(0), 1.0f, t));
    CHECK(t == Approx(1.5f).epsilon(1e-6));
    REQUIRE(hit_sphere(ray{vec3(3, 4, 5), vec3(1, 1, 0)}, vec3(3, 4, 5), 1.0f, t));  // |dir| = sqrt 2
    CHECK(t == Approx(1.0f / std::sqrt(2.0f)).epsilon(1e-6));
}

TEST_CASE("01.2 ray/sphere: only roots inside the open interval (tmin, tmax) count", "[ch01][pts:1]") {
    float t;
    const vec3 o(0, 0, 5), d(0, 0, -1);  // roots at t = 4 and t = 6
    CHECK_FALSE(hit_sphere(ray{o, d, 0.0f, 3.9f}, vec3(0), 1.0f, t));
    CHECK_FALSE(hit_sphere(ray{o, d, 0.0f, 4.0f}, vec3(0), 1.0f, t));  // tmax itself is outside
    REQUIRE(hit_sphere(ray{o, d, 0.0f, 4.1f}, vec3(0), 1.0f, t));
    CHECK(t == Approx(4.0f).epsilon(1e-6));
    REQUIRE(hit_sphere(ray{o, d, 4.0f, inf}, vec3(0), 1.0f, t));       // tmin itself is outside: far root
    CHECK(t == Approx(6.0f).epsilon(1e-6));
    REQUIRE(hit_sphere(ray{o, d, 4.5f, 10.0f}, vec3(0), 1.0f, t));
    CHECK(t == Approx(6.0f).epsilon(1e-6));
    CHECK_FALSE(hit_sphere(ray{o, d, 4.5f, 5.9f}, vec3(0), 1.0f, t));
    CHECK_FALSE(hit_sphere(ray{o, d, 6.0f, inf}, vec3(0), 1.0f, t));
    CHECK_FALSE(hit_sphere(ray{o, d, 6.5f, inf}, vec3(0), 1.0f, t));
}

// Far away, b^2 and a c are both about distance^4 and their difference drowns in rounding (Haines et al.).
TEST_CASE("01.2 ray/sphere: far-away spheres are hit precisely", "[ch01][pts:1]") {
    float t;
    for (const vec3 axis : {vec3(1, 2, 3), vec3(-3, 0.5f, 1), vec3(0.2f, -1, -0.7f)}) {
        const vec3 a = glm::normalize(axis);
        const vec3 side = glm::normalize(glm::cross(a, vec3(0.3f, 0.4f, 0.5f)));
        for (const float distance : {1.0e4f, 3.0e4f}) {
            INFO("axis " << a.x << " " << a.y << " " << a.z << ", distance " << distance);
            const vec3 c = a * distance;
            // A unit sphere, the ray half a radius off its centre: roots at distance -+ sqrt(0.75).
            const vec3 o = 0.5f * side;
            REQUIRE(hit_sphere(ray{o, a}, c, 1.0f, t));
            CHECK(std::abs(t - (glm::dot(c - o, a) - std::sqrt(0.75f))) < 0.02f);
            // A tiny sphere straight ahead must not be missed.
            REQUIRE(hit_sphere(ray{vec3(0), a}, c, 0.02f, t));
            CHECK(std::abs(t - (distance - 0.02f)) < 0.02f);
        }
    }
}
