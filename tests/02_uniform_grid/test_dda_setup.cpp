// Exercise 02.2 DDA set-up (6 points). Only dda_setup is used here, on grids and entry points made by hand.
#include "grid_cases.hpp"
#include "strahl/ch02/grid.hpp"
#include <catch2/catch.hpp>

using namespace strahl;
using namespace strahl::ch02;
using strahl::ch02::cases::make_grid;


TEST_CASE("02.2 DDA set-up: a ray with positive direction enters from outside", "[ch02][pts:2]") {
    const grid_dims g = make_grid(vec3(0), vec3(4), ivec3(4));
    const ray r{vec3(-1, 0.5f, 0.25f), vec3(1, 0.5f, 0.25f)};
    const dda_state s = dda_setup(g, r, 1.0f);  // enters at x = 0: p = (0, 1, 0.5)
    CHECK(s.cell == ivec3(0, 1, 0));
    CHECK(s.step == ivec3(1, 1, 1));
    CHECK(s.t_max.x == Approx(2.0f));
    CHECK(s.t_max.y == Approx(3.0f));
    CHECK(s.t_max.z == Approx(3.0f));
    CHECK(s.t_delta.x == Approx(1.0f));
    CHECK(s.t_delta.y == Approx(2.0f));
    CHECK(s.t_delta.z == Approx(4.0f));
}

TEST_CASE("02.2 DDA set-up: negative components step down, entry on the upper face is clamped", "[ch02][pts:2]") {
    const grid_dims g = make_grid(vec3(0), vec3(4), ivec3(4));
    const ray r{vec3(5, 3.5f, 2.5f), vec3(-2, -1, 0.5f)};
    const dda_state s = dda_setup(g, r, 0.5f);  // enters at x = 4: p = (4, 3, 2.75)
    CHECK(s.cell == ivec3(3, 3, 2));
    CHECK(s.step == ivec3(-1, -1, 1));
    CHECK(s.t_max.x == Approx(1.0f));   // x = 3
    CHECK(s.t_max.y == Approx(0.5f));   // y = 3, the entry itself: the cell is left at once
    CHECK(s.t_max.z == Approx(1.0f));   // z = 3
    CHECK(s.t_delta.x == Approx(0.5f));
    CHECK(s.t_delta.y == Approx(1.0f));
    CHECK(s.t_delta.z == Approx(2.0f));
}

TEST_CASE("02.2 DDA set-up: direction components of +0 and -0 never step", "[ch02][pts:1]") {
    const grid_dims g = make_grid(vec3(0), vec3(4), ivec3(4));
    const ray r{vec3(1.5f, 2.5f, -1), vec3(0.0f, -0.0f, 2)};
    const dda_state s = dda_setup(g, r, 0.5f);  // p = (1.5, 2.5, 0)
    CHECK(s.cell == ivec3(1, 2, 0));
    CHECK(s.step == ivec3(0, 0, 1));
    CHECK(s.t_max.x == inf);
    CHECK(s.t_max.y == inf);
    CHECK(s.t_delta.x == inf);
    CHECK(s.t_delta.y == inf);
    CHECK(s.t_max.z == Approx(1.0f));
    CHECK(s.t_delta.z == Approx(0.5f));
}

TEST_CASE("02.2 DDA set-up: an offset grid with unequal cells, the ray starting inside", "[ch02][pts:1]") {
    const grid_dims g = make_grid(vec3(-2, 10, 0), vec3(2, 13, 0.5f), ivec3(8, 3, 1));  // cells 0.5 x 1 x 0.5
    const ray r{vec3(-1.2f, 11.5f, 0.25f), vec3(1, -2, 0)};
    const dda_state s = dda_setup(g, r, 0.0f);
    CHECK(s.cell == ivec3(1, 1, 0));
    CHECK(s.step == ivec3(1, -1, 0));
    CHECK(s.t_max.x == Approx(0.2f));    // x = -1
    CHECK(s.t_max.y == Approx(0.25f));   // y = 11
    CHECK(s.t_max.z == inf);
    CHECK(s.t_delta.x == Approx(0.5f));
    CHECK(s.t_delta.y == Approx(0.5f));
}
