// Exercise 02.3 DDA step (5 points). Only dda_step is used here: the walk's states are made by hand.
#include "grid_cases.hpp"
#include "strahl/ch02/grid.hpp"
#include <catch2/catch.hpp>

using namespace strahl;
using namespace strahl::ch02;
using strahl::ch02::cases::make_grid;

namespace {
dda_state state(ivec3 cell, ivec3 step, vec3 t_max, vec3 t_delta) {
    dda_state s;
    s.cell = cell, s.step = step, s.t_max = t_max, s.t_delta = t_delta;
    return s;
}
}  // namespace

TEST_CASE("02.3 DDA step: steps along the axis of the nearest boundary, ties to the lower axis", "[ch02][pts:2]") {
    const grid_dims g = make_grid(vec3(0), vec3(4), ivec3(4));
    dda_state s = state(ivec3(0, 1, 0), ivec3(1, 1, 1), vec3(2, 3, 3), vec3(1, 2, 4));
    REQUIRE(dda_step(g, s));
    CHECK(s.cell == ivec3(1, 1, 0));
    CHECK(s.t_max == vec3(3, 3, 3));
    REQUIRE(dda_step(g, s));  // a three-way tie: x first
    CHECK(s.cell == ivec3(2, 1, 0));
    CHECK(s.t_max == vec3(4, 3, 3));
    REQUIRE(dda_step(g, s));  // y and z tie: y
    CHECK(s.cell == ivec3(2, 2, 0));
    CHECK(s.t_max == vec3(4, 5, 3));
    REQUIRE(dda_step(g, s));
    CHECK(s.cell == ivec3(2, 2, 1));
    CHECK(s.t_max == vec3(4, 5, 7));
    CHECK(s.step == ivec3(1, 1, 1));
    CHECK(s.t_delta == vec3(1, 2, 4));
}

TEST_CASE("02.3 DDA step: the walk ends when it leaves the grid on either side", "[ch02][pts:2]") {
    const grid_dims g = make_grid(vec3(0), vec3(4), ivec3(4));
    dda_state down = state(ivec3(1, 2, 2), ivec3(-1, 1, 0), vec3(1, 5, inf), vec3(1, 4, inf));
    REQUIRE(dda_step(g, down));
    CHECK(down.cell == ivec3(0, 2, 2));
    CHECK_FALSE(dda_step(g, down));  // x would be -1
    dda_state up = state(ivec3(2, 3, 1), ivec3(1, 1, -1), vec3(6, 2.5f, 4), vec3(1, 1, 1));
    CHECK_FALSE(dda_step(g, up));  // y would be 4
    // A longer walk along x: three steps inside, the fourth leaves.
    dda_state along = state(ivec3(0, 1, 1), ivec3(1, 0, 0), vec3(0.5f, inf, inf), vec3(1, inf, inf));
    int steps = 0;
    while (steps < 10 && dda_step(g, along)) ++steps;
    CHECK(steps == 3);
}

TEST_CASE("02.3 DDA step: no finite boundary, no step", "[ch02][pts:1]") {
    const grid_dims g = make_grid(vec3(0), vec3(4), ivec3(4));
    dda_state still = state(ivec3(1, 1, 1), ivec3(0, 0, 0), vec3(inf), vec3(inf));
    CHECK_FALSE(dda_step(g, still));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    dda_state bad = state(ivec3(1, 1, 1), ivec3(1, 1, 1), vec3(nan), vec3(1));
    CHECK_FALSE(dda_step(g, bad));
}
