// Exercise 05.1 the SAH cost of a split (2 points). Only split_cost, on hand-computed numbers.
#include "strahl/ch05/sah.hpp"
#include <catch2/catch.hpp>

using namespace strahl;
using namespace strahl::ch05;

TEST_CASE("05.1 SAH cost: the lecture's equation on hand-computed splits", "[ch05][pts:1]") {
    const sah_costs unit{1.0f, 1.0f};
    // P = [0,2]x[0,1]x[0,1] (area 10) into two unit cubes (area 6 each), 1 and 2 primitives:
    // 1 + (6/10 * 1 + 6/10 * 2) = 2.8.
    CHECK(split_cost(unit, 10.0f, 6.0f, 1, 6.0f, 2) == Approx(2.8f));
    // C_T = 2, C_I = 3: 2 + 3 * (0.6 + 1.2) = 7.4.
    CHECK(split_cost({2.0f, 3.0f}, 10.0f, 6.0f, 1, 6.0f, 2) == Approx(7.4f));
    // A child as large as the parent: every ray through P meets it.
    CHECK(split_cost(unit, 8.0f, 8.0f, 5, 2.0f, 4) == Approx(1.0f + 5.0f + 1.0f));
    // Only the ratio of areas counts.
    CHECK(split_cost(unit, 1000.0f, 250.0f, 8, 500.0f, 4) == Approx(split_cost(unit, 4.0f, 1.0f, 8, 2.0f, 4)));
}

TEST_CASE("05.1 SAH cost: traversal cost alone for empty children, linear in the counts", "[ch05][pts:1]") {
    CHECK(split_cost({1.5f, 1.0f}, 6.0f, 3.0f, 0, 3.0f, 0) == Approx(1.5f));
    const float one = split_cost({1.0f, 2.0f}, 6.0f, 3.0f, 10, 1.5f, 0);
    const float two = split_cost({1.0f, 2.0f}, 6.0f, 3.0f, 20, 1.5f, 0);
    CHECK(one == Approx(1.0f + 2.0f * 0.5f * 10.0f));
    CHECK(two - 1.0f == Approx(2.0f * (one - 1.0f)));
}
