// Exercise 02.1 cell range (5 points). Only cells_of_box is used here, on grids made by hand.
#include "grid_cases.hpp"
#include "strahl/ch02/grid.hpp"
#include <catch2/catch.hpp>

using namespace strahl;
using namespace strahl::ch02;
using strahl::ch02::cases::make_grid;

namespace {
bool same(const cell_range& r, ivec3 lo, ivec3 hi) { return r.lo == lo && r.hi == hi; }
}  // namespace

TEST_CASE("02.1 cell range: a box inside the grid covers the cells of its corners", "[ch02][pts:2]") {
    const grid_dims g = make_grid(vec3(0), vec3(4, 2, 1), ivec3(4, 2, 1));  // unit cells
    CHECK(same(cells_of_box(g, aabb{vec3(0.5f, 0.2f, 0.1f), vec3(1.5f, 0.3f, 0.9f)}), ivec3(0, 0, 0), ivec3(1, 0, 0)));
    CHECK(same(cells_of_box(g, aabb{vec3(2.2f, 1.2f, 0.5f), vec3(2.3f, 1.4f, 0.5f)}), ivec3(2, 1, 0), ivec3(2, 1, 0)));
    // A face exactly on a boundary belongs to the cell above it (floor).
    CHECK(same(cells_of_box(g, aabb{vec3(1.0f, 0.5f, 0.5f), vec3(2.0f, 1.0f, 0.5f)}), ivec3(1, 0, 0), ivec3(2, 1, 0)));
    // The grid's own upper face: clamped into the last cell.
    CHECK(same(cells_of_box(g, aabb{vec3(3.5f, 1.5f, 0.0f), vec3(4.0f, 2.0f, 1.0f)}), ivec3(3, 1, 0), ivec3(3, 1, 0)));
    // A point.
    CHECK(same(cells_of_box(g, aabb{vec3(0.25f, 1.75f, 0.5f), vec3(0.25f, 1.75f, 0.5f)}), ivec3(0, 1, 0), ivec3(0, 1, 0)));
}

TEST_CASE("02.1 cell range: boxes reaching past the grid are clamped to its border cells", "[ch02][pts:2]") {
    const grid_dims g = make_grid(vec3(-2, 10, 0), vec3(2, 13, 0.5f), ivec3(8, 3, 1));  // cells 0.5 x 1 x 0.5
    CHECK(same(cells_of_box(g, aabb{vec3(-100), vec3(100)}), ivec3(0, 0, 0), ivec3(7, 2, 0)));
    CHECK(same(cells_of_box(g, aabb{vec3(-5, 11.5f, -1), vec3(-1.2f, 50, 0.2f)}), ivec3(0, 1, 0), ivec3(1, 2, 0)));
    CHECK(same(cells_of_box(g, aabb{vec3(0.7f, 9, 0.1f), vec3(9, 10.5f, 0.4f)}), ivec3(5, 0, 0), ivec3(7, 0, 0)));
}

TEST_CASE("02.1 cell range: empty boxes, boxes outside the grid and empty grids give no cells", "[ch02][pts:1]") {
    const grid_dims g = make_grid(vec3(0), vec3(4), ivec3(4));
    CHECK(cells_of_box(g, aabb::empty()).empty());
    CHECK(cells_of_box(g, aabb{vec3(5, 1, 1), vec3(6, 2, 2)}).empty());        // beyond +x
    CHECK(cells_of_box(g, aabb{vec3(1, -3, 1), vec3(2, -2, 2)}).empty());      // below -y
    CHECK(cells_of_box(g, aabb{vec3(1, 1, 4.5f), vec3(2, 2, 9)}).empty());     // beyond +z
    CHECK_FALSE(cells_of_box(g, aabb{vec3(1, 1, 3.5f), vec3(2, 2, 9)}).empty());
    CHECK(cells_of_box(grid_dims{}, aabb{vec3(0), vec3(1)}).empty());          // no cells at all
}
