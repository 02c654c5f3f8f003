// Exercise 06.1 the cost of one rotation (6 points). Only rotation_cost, on hand-made trees.
#include "strahl/ch06/refine.hpp"
#include "hand_trees.hpp"
#include <catch2/catch.hpp>
#include <cmath>

using namespace strahl;
using namespace strahl::ch06;

TEST_CASE("06.1 rotation cost: the four rotations at the root of a 4-leaf tree", "[ch06][pts:3]") {
    const test::tree2 k = test::make_tree2();
    CHECK(rotation_cost(k.t, k.n, rotation::left_right_left, 1.0f) == Approx(-48.0f));
    CHECK(rotation_cost(k.t, k.n, rotation::left_right_right, 1.0f) == Approx(-16.0f));
    CHECK(rotation_cost(k.t, k.n, rotation::right_left_left, 1.0f) == Approx(58.0f));
    CHECK(rotation_cost(k.t, k.n, rotation::right_left_right, 1.0f) == Approx(58.0f));
    // C_T scales the change.
    CHECK(rotation_cost(k.t, k.n, rotation::left_right_left, 0.5f) == Approx(-24.0f));
    CHECK(rotation_cost(k.t, k.n, rotation::right_left_right, 2.0f) == Approx(116.0f));
}

TEST_CASE("06.1 rotation cost: a leaf child cannot be rotated into, none costs nothing", "[ch06][pts:3]") {
    const test::tree1 k = test::make_tree1();
    CHECK(rotation_cost(k.t, k.n, rotation::left_right_left, 1.0f) == Approx(-40.0f));
    CHECK(rotation_cost(k.t, k.n, rotation::left_right_right, 1.0f) == Approx(-4.0f));
    CHECK(std::isinf(rotation_cost(k.t, k.n, rotation::right_left_left, 1.0f)));
    CHECK(rotation_cost(k.t, k.n, rotation::right_left_left, 1.0f) > 0.0f);
    CHECK(std::isinf(rotation_cost(k.t, k.n, rotation::right_left_right, 1.0f)));
    CHECK(rotation_cost(k.t, k.n, rotation::none, 1.0f) == 0.0f);
    // R's children are both leaves: nothing can be rotated at R.
    for (const rotation r : {rotation::left_right_left, rotation::left_right_right, rotation::right_left_left,
                             rotation::right_left_right}) {
        INFO("rotation " << to_string(r) << " at R, whose children are both leaves");
        CHECK(std::isinf(rotation_cost(k.t, k.r, r, 1.0f)));
    }
    // The tree is not changed by evaluating.
    CHECK(k.t.nodes[k.r].left == k.x);
    CHECK(k.t.nodes[k.n].left == k.a);
}
