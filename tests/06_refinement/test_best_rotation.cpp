// Exercise 06.2 the best rotation at a node, applied (10 points). Only apply_best_rotation, on hand-made trees.
#include "strahl/ch06/refine.hpp"
#include "hand_trees.hpp"
#include <catch2/catch.hpp>

using namespace strahl;
using namespace strahl::ch06;
using test::bar;
using test::box;
using test::same_box;

// A rotation prints by name in a failing check ("left_right_left == none"), not as its number.
namespace Catch {
template <>
struct StringMaker<strahl::ch06::rotation> {
    static std::string convert(strahl::ch06::rotation r) { return strahl::ch06::to_string(r); }
};
}  // namespace Catch

namespace {
// Every link agrees with its back link, and every inner node's box and height with its children's.
void check_consistent(const refine_tree& t) {
    for (std::uint32_t i = 0; i < t.nodes.size(); ++i) {
        const refine_node& n = t.nodes[i];
        INFO((n.is_leaf() ? "leaf " : "inner node ") << i);
        if (n.is_leaf()) {
            CHECK(n.height == 0);
            continue;
        }
        CHECK(t.nodes[n.left].parent == i);
        CHECK(t.nodes[n.right].parent == i);
        CHECK(same_box(n.box, unite(t.nodes[n.left].box, t.nodes[n.right].box)));
        CHECK(n.height == 1 + std::max(t.nodes[n.left].height, t.nodes[n.right].height));
    }
}
}  // namespace

TEST_CASE("06.2 best rotation: the lowest cost change is chosen and the tree rewired", "[ch06][pts:4]") {
    test::tree2 k = test::make_tree2();
    const rotation_choice c = apply_best_rotation(k.t, k.n, 0, 10, 1.0f);
    CHECK(c.r == rotation::left_right_left);
    CHECK(c.delta == Approx(-48.0f));
    // L and RL traded places: N = (RL, R), R = (L, RR), L = (LL, LR) untouched.
    CHECK(k.t.nodes[k.n].left == k.rl);
    CHECK(k.t.nodes[k.n].right == k.r);
    CHECK(k.t.nodes[k.r].left == k.l);
    CHECK(k.t.nodes[k.r].right == k.rr);
    CHECK(k.t.nodes[k.l].left == k.ll);
    CHECK(k.t.nodes[k.rl].parent == k.n);
    CHECK(k.t.nodes[k.l].parent == k.r);
    CHECK(same_box(k.t.nodes[k.r].box, box(vec3(0, 0, 0), vec3(6, 2, 3))));
    CHECK(same_box(k.t.nodes[k.n].box, box(vec3(0, 0, 0), vec3(6, 2, 6))));
    CHECK(k.t.nodes[k.r].height == 2);
    CHECK(k.t.nodes[k.n].height == 3);
    check_consistent(k.t);
    // With C_T = 0.5 the same choice, half the change.
    test::tree2 h = test::make_tree2();
    CHECK(apply_best_rotation(h.t, h.n, 0, 10, 0.5f).delta == Approx(-24.0f));
}

TEST_CASE("06.2 best rotation: a leaf child, below the root", "[ch06][pts:3]") {
    // Tree 1 hung below a root G = (tree 1, leaf F), so N lies at depth 1.
    test::tree1 k = test::make_tree1();
    const std::uint32_t f = test::add_leaf(k.t, bar(-5, -4));
    const std::uint32_t g = test::add_inner(k.t, k.n, f);
    k.t.root = g;
    const aabb g_box = k.t.nodes[g].box;
    const rotation_choice c = apply_best_rotation(k.t, k.n, 1, 10, 1.0f);
    CHECK(c.r == rotation::left_right_left);
    CHECK(c.delta == Approx(-40.0f));
    // A and X traded places: N = (X, R), R = (A, Y) = bar(10, 12).
    CHECK(k.t.nodes[k.n].left == k.x);
    CHECK(k.t.nodes[k.r].left == k.a);
    CHECK(k.t.nodes[k.r].right == k.y);
    CHECK(same_box(k.t.nodes[k.r].box, bar(10, 12)));
    CHECK(k.t.nodes[k.n].height == 2);
    // N keeps its box, so its parent is untouched.
    CHECK(same_box(k.t.nodes[k.n].box, bar(0, 12)));
    CHECK(same_box(k.t.nodes[g].box, g_box));
    CHECK(k.t.nodes[k.n].parent == g);
    check_consistent(k.t);
}

TEST_CASE("06.2 best rotation: no gain, or too deep: nothing changes", "[ch06][pts:3]") {
    // Tree 3: the best changes are 0, which is no gain.
    refine_tree t3 = test::make_tree3();
    const refine_tree before = t3;
    const rotation_choice c3 = apply_best_rotation(t3, t3.root, 0, 10, 1.0f);
    CHECK(c3.r == rotation::none);
    CHECK(c3.delta == 0.0f);
    for (std::size_t i = 0; i < t3.nodes.size(); ++i) {
        INFO("tree 3's node " << i << ": its children must not change");
        CHECK(t3.nodes[i].left == before.nodes[i].left);
        CHECK(t3.nodes[i].right == before.nodes[i].right);
    }
    // Tree 2 with max_depth 2: both gains would move L (height 1) to depth 2, its leaves to depth 3.
    test::tree2 k2 = test::make_tree2();
    CHECK(apply_best_rotation(k2.t, k2.n, 0, 2, 1.0f).r == rotation::none);
    CHECK(k2.t.nodes[k2.n].left == k2.l);
    CHECK(k2.t.nodes[k2.r].left == k2.rl);
    // With max_depth 3 they fit.
    CHECK(apply_best_rotation(k2.t, k2.n, 0, 3, 1.0f).r == rotation::left_right_left);
    // Tree 1 at depth 5 with max_depth 6: A would land at depth 7.
    test::tree1 k1 = test::make_tree1();
    CHECK(apply_best_rotation(k1.t, k1.n, 5, 6, 1.0f).r == rotation::none);
    CHECK(k1.t.nodes[k1.n].left == k1.a);
    CHECK(apply_best_rotation(k1.t, k1.n, 5, 7, 1.0f).r == rotation::left_right_left);
}
