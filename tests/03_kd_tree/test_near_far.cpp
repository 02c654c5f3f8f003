// Exercise 03.3 near/far and t-split (7 points). Only near_far, on hand-made rays and planes.
#include "strahl/ch03/traverse.hpp"
#include <catch2/catch.hpp>
#include <cmath>

using namespace strahl;
using namespace strahl::ch03;

namespace {
struct setup {
    ray r;
    vec3 inv;
};
setup along_x(float ox, float dx) {
    const ray r{vec3(ox, 0.25f, 0.5f), vec3(dx, 0.0f, 0.0f)};
    return {r, vec3(1.0f / dx, inf, inf)};
}
void check_child(const child_visit& v, int k, int child, float t0, float t1) {
    INFO("visit " << k << " (" << (k == 0 ? "first" : "second") << ") of " << v.count << ", expected: child "
                  << child << " (" << (child ? "right" : "left") << ") over t in [" << t0 << ", " << t1 << "]");
    CHECK(int(v.child[k]) == child);
    CHECK(v.t0[k] == Approx(t0));
    CHECK(v.t1[k] == Approx(t1));
}
}  // namespace

TEST_CASE("03.3 near/far and t-split: a ray crossing the plane visits near then far", "[ch03][pts:3]") {
    // Up the axis from x = 0 at speed 2, plane x = 1: t_split = 0.5, left first.
    const setup a = along_x(0.0f, 2.0f);
    const child_visit v = near_far(a.r, a.inv, 0, 1.0f, 0.0f, 2.0f, 0.0f);
    REQUIRE(v.count == 2);
    check_child(v, 0, 0, 0.0f, 0.5f);
    check_child(v, 1, 1, 0.5f, 2.0f);
    // Down the axis from x = 3, plane x = 1: t_split = 2, right first.
    const setup b = along_x(3.0f, -1.0f);
    const child_visit w = near_far(b.r, b.inv, 0, 1.0f, 0.5f, 5.0f, 0.0f);
    REQUIRE(w.count == 2);
    check_child(w, 0, 1, 0.5f, 2.0f);
    check_child(w, 1, 0, 2.0f, 5.0f);
    // The slack widens both ranges around t_split.
    const child_visit x = near_far(b.r, b.inv, 0, 1.0f, 0.5f, 5.0f, 0.25f);
    REQUIRE(x.count == 2);
    check_child(x, 0, 1, 0.5f, 2.25f);
    check_child(x, 1, 0, 1.75f, 5.0f);
    // An oblique ray on axis z: org z = 0.5, dir z = 0.25, plane z = 1.5: t_split = 4.
    const ray o{vec3(0.0f, 0.0f, 0.5f), vec3(1.0f, -1.0f, 0.25f)};
    const child_visit y = near_far(o, vec3(1.0f, -1.0f, 4.0f), 2, 1.5f, 1.0f, 6.0f, 0.0f);
    REQUIRE(y.count == 2);
    check_child(y, 0, 0, 1.0f, 4.0f);
    check_child(y, 1, 1, 4.0f, 6.0f);
}

TEST_CASE("03.3 near/far and t-split: a plane behind the ray or beyond the segment gives one child",
          "[ch03][pts:2]") {
    const setup up = along_x(2.0f, 1.0f);
    const child_visit behind = near_far(up.r, up.inv, 0, 1.0f, 0.0f, 3.0f, 0.0f);  // t_split = -1
    REQUIRE(behind.count == 1);
    check_child(behind, 0, 1, 0.0f, 3.0f);
    const child_visit beyond = near_far(up.r, up.inv, 0, 5.0f, 0.0f, 2.0f, 0.0f);  // t_split = 3 > t1
    REQUIRE(beyond.count == 1);
    check_child(beyond, 0, 0, 0.0f, 2.0f);
    const setup down = along_x(2.0f, -1.0f);
    const child_visit away = near_far(down.r, down.inv, 0, 5.0f, 1.0f, 4.0f, 0.0f);  // t_split = -3
    REQUIRE(away.count == 1);
    check_child(away, 0, 0, 1.0f, 4.0f);
    // The segment ends before the plane is reached: the near child only.
    const child_visit early = near_far(down.r, down.inv, 0, 0.5f, 0.0f, 1.0f, 0.0f);  // t_split = 1.5
    REQUIRE(early.count == 1);
    check_child(early, 0, 1, 0.0f, 1.0f);
}

TEST_CASE("03.3 near/far and t-split: directions of +0 and -0, origins on the plane, no NaN", "[ch03][pts:2]") {
    for (const float zero : {0.0f, -0.0f}) {
        INFO("the direction's x component is " << (std::signbit(zero) ? "-0" : "+0") << ", the plane x = 1");
        const ray below{vec3(0.5f, 0, 0), vec3(zero, 1, 0)}, above{vec3(1.5f, 0, 0), vec3(zero, 1, 0)},
            on{vec3(1.0f, 0, 0), vec3(zero, 1, 0)};
        const vec3 inv(1.0f / zero, 1.0f, inf);
        const child_visit a = near_far(below, inv, 0, 1.0f, 0.0f, 7.0f, 0.0f);
        REQUIRE(a.count == 1);
        check_child(a, 0, 0, 0.0f, 7.0f);
        const child_visit b = near_far(above, inv, 0, 1.0f, 0.0f, 7.0f, 0.0f);
        REQUIRE(b.count == 1);
        check_child(b, 0, 1, 0.0f, 7.0f);
        const child_visit c = near_far(on, inv, 0, 1.0f, 0.0f, 7.0f, 0.0f);  // in the plane: both, left first
        REQUIRE(c.count == 2);
        check_child(c, 0, 0, 0.0f, 7.0f);
        check_child(c, 1, 1, 0.0f, 7.0f);
    }
    // Starting on the plane with a tiny direction whose inverse is inf: t_split = 0, not 0 * inf = NaN.
    const ray tiny{vec3(1.0f, 0, 0), vec3(1e-40f, 1, 0)};
    const child_visit d = near_far(tiny, vec3(inf, 1, inf), 0, 1.0f, 0.0f, 3.0f, 0.0f);
    REQUIRE(d.count == 2);
    for (int k = 0; k < 2; ++k) {
        INFO("visit " << k << ": t in [" << d.t0[k] << ", " << d.t1[k] << "]");
        CHECK_FALSE(std::isnan(d.t0[k]));
        CHECK_FALSE(std::isnan(d.t1[k]));
    }
    check_child(d, 0, 0, 0.0f, 0.0f);
    check_child(d, 1, 1, 0.0f, 3.0f);
}
