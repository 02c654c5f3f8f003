// Exercise 02.4 hit in cell (4 points). Only hit_in_cell is used here, with candidates made by hand.
#include "strahl/ch02/grid.hpp"
#include <catch2/catch.hpp>
#include <cmath>

using namespace strahl;
using namespace strahl::ch02;

TEST_CASE("02.4 hit in cell: a hit well before the cell's exit ends the search", "[ch02][pts:2]") {
    CHECK(hit_in_cell(1.0f, 2.0f));
    CHECK(hit_in_cell(1.99f, 2.0f));
    CHECK(hit_in_cell(0.0f, 0.5f));
    CHECK(hit_in_cell(-3.0f, -1.0f));  // negative t (a ray with tmin < 0): the margin uses |exit|
    CHECK_FALSE(hit_in_cell(2.5f, 2.0f));  // beyond the cell: a nearer triangle may wait in the next cell
    CHECK_FALSE(hit_in_cell(100.0f, 2.0f));
}

TEST_CASE("02.4 hit in cell: a hit at the exit, or within the margin, does not end it (ties)", "[ch02][pts:1]") {
    CHECK_FALSE(hit_in_cell(2.0f, 2.0f));
    CHECK_FALSE(hit_in_cell(std::nextafter(2.0f, 0.0f), 2.0f));
    CHECK_FALSE(hit_in_cell(1.9999f, 2.0f));  // 1e-4 relative: inside the margin
    CHECK(hit_in_cell(1.999f, 2.0f));
    CHECK_FALSE(hit_in_cell(1000.0f, 1000.05f));
    CHECK(hit_in_cell(1000.0f, 1000.2f));
}

TEST_CASE("02.4 hit in cell: NaN and infinities keep the walk going", "[ch02][pts:1]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    CHECK_FALSE(hit_in_cell(nan, 2.0f));
    CHECK_FALSE(hit_in_cell(1.0f, nan));
    CHECK_FALSE(hit_in_cell(1.0f, inf));
    CHECK_FALSE(hit_in_cell(inf, inf));
    CHECK_FALSE(hit_in_cell(inf, 5.0f));
}
