// Exercise 10.1 the ray's object-space transform (4 points): identity, translation, scale and rotation by
// hand; t keeps its meaning (the object point at t is the world point at t seen through the inverse) for
// random invertible transforms; tmin and tmax carried over.
#include "strahl/ch10/object_ray.hpp"
#include "strahl/rng.hpp"
#include <catch2/catch.hpp>
#include <cstring>

using namespace strahl;
using namespace strahl::ch10;

namespace {
bool same_bits(const ray& a, const ray& b) { return std::memcmp(&a, &b, sizeof(ray)) == 0; }
}  // namespace

TEST_CASE("10.1 object ray: the identity changes nothing, a translation moves the origin only", "[ch10][pts:1]") {
    const ray r{vec3(1.5f, -2.0f, 3.25f), vec3(0.25f, 0.5f, -1.0f), 0.125f, 7.5f};
    CHECK(same_bits(to_object(r, affine{}), r));
    const ray o = to_object(r, affine::translate({-1.0f, 2.0f, 0.75f}));
    CHECK(o.org == vec3(0.5f, 0.0f, 4.0f));
    CHECK(o.dir == r.dir);  // a direction is never moved
    CHECK(o.tmin == r.tmin);
    CHECK(o.tmax == r.tmax);
}

TEST_CASE("10.1 object ray: a scale scales origin and direction, and the direction stays unnormalised",
          "[ch10][pts:1]") {
    const ray r{vec3(2.0f, 4.0f, -8.0f), vec3(1.0f, 0.0f, 2.0f), 0.0f, 10.0f};
    const ray o = to_object(r, affine::scale({0.5f, 0.25f, 2.0f}));
    CHECK(o.org == vec3(1.0f, 1.0f, -16.0f));
    CHECK(o.dir == vec3(0.5f, 0.0f, 4.0f));
    CHECK(o.tmax == 10.0f);
}

TEST_CASE("10.1 object ray: a quarter turn about z maps x to y", "[ch10][pts:1]") {
    const ray r{vec3(1.0f, 0.0f, 0.0f), vec3(1.0f, 0.0f, 0.0f), 0.0f, inf};
    const ray o = to_object(r, affine::rotate(2, 90.0f) * affine::translate({0.0f, 0.0f, 3.0f}));
    CHECK(o.org.x == Approx(0.0f).margin(1e-6));
    CHECK(o.org.y == Approx(1.0f));
    CHECK(o.org.z == Approx(3.0f));
    CHECK(o.dir.x == Approx(0.0f).margin(1e-6));
    CHECK(o.dir.y == Approx(1.0f));
    CHECK(o.tmax == inf);
}

TEST_CASE("10.1 object ray: the object point at t is the world point at t, for random transforms",
          "[ch10][pts:1]") {
    pcg32 g(10);
    const auto u = [&] { return g.next_float() * 2.0f - 1.0f; };
    for (int k = 0; k < 200; ++k) {
        affine to_world = affine::translate({10 * u(), 10 * u(), 10 * u()}) * affine::rotate(k % 3, 360 * u()) *
                          affine::scale({0.5f + g.next_float(), 0.5f + g.next_float(), 0.5f + g.next_float()}) *
                          affine::rotate((k + 1) % 3, 360 * u());
        const affine inv = *inverse(to_world);
        const ray r{vec3(u(), u(), u()) * 5.0f, vec3(u(), u(), u()), 0.5f * g.next_float(), 1.0f + g.next_float()};
        const ray o = to_object(r, inv);
        REQUIRE(o.tmin == r.tmin);
        REQUIRE(o.tmax == r.tmax);
        for (const float t : {0.0f, 0.5f, 2.0f}) {
            const vec3 back = to_world.point(o.at(t)), want = r.at(t);
            REQUIRE(glm::length(back - want) < 1e-4f * (1.0f + glm::length(want)));
        }
    }
}
