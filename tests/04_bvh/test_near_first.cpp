// Exercise 04.3 near child first (5 points). Only ordered_children, on hand-made nodes.
#include "strahl/ch04/traverse.hpp"
#include <catch2/catch.hpp>

using namespace strahl;
using namespace strahl::ch04;

namespace {
bvh_node inner(int axis, std::uint32_t right) {
    bvh_node n{};
    n.axis = std::uint8_t(axis);
    n.offset = right;
    return n;
}
}  // namespace

TEST_CASE("04.3 near child first: the direction's sign on the split axis orders the children", "[ch04][pts:3]") {
    for (int axis = 0; axis < 3; ++axis) {
        INFO("split axis " << axis);
        const bvh_node n = inner(axis, 9);
        vec3 up(0.3f), down(0.3f);
        up[axis] = 2.0f;
        down[axis] = -0.5f;
        const child_order a = ordered_children(4, n, up);
        CHECK(a.near == 5u);
        CHECK(a.far == 9u);
        const child_order b = ordered_children(4, n, down);
        CHECK(b.near == 9u);
        CHECK(b.far == 5u);
        // Only the node's axis counts: the other components point the other way.
        vec3 mixed(-1.0f);
        mixed[axis] = 1.0f;
        CHECK(ordered_children(0, inner(axis, 100), mixed).near == 1u);
    }
}

TEST_CASE("04.3 near child first: +0 goes left first, -0 right first", "[ch04][pts:2]") {
    const bvh_node n = inner(1, 17);
    const child_order p = ordered_children(10, n, vec3(1, 0.0f, 1));
    CHECK(p.near == 11u);
    CHECK(p.far == 17u);
    const child_order m = ordered_children(10, n, vec3(1, -0.0f, 1));
    CHECK(m.near == 17u);
    CHECK(m.far == 11u);
}
