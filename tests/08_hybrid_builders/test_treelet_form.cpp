// Exercise 08.1 forming a treelet (8 points): form_treelet on hand-made trees, every expansion worked out
// by hand (boxes along x, so that areas are easy to add up), equal areas, primitives' leaves and small
// subtrees; and on LBVH trees, a valid treelet grown largest first, its leaves in the order the contract
// gives.
#include "strahl/ch07/lbvh.hpp"
#include "strahl/ch08/treelet.hpp"
#include "strahl/procedural.hpp"
#include <algorithm>
#include <catch2/catch.hpp>
#include <string>
#include <vector>

using namespace strahl;
using namespace strahl::ch08;

namespace {

using ids = std::vector<std::uint32_t>;

// A box along x: [x0, x1] x [0, 1] x [0, 1], of area 2 (2 (x1 - x0) + 1) = 4 (x1 - x0) + 2.
aabb along_x(float x0, float x1) { return {vec3(x0, 0, 0), vec3(x1, 1, 1)}; }

// The tree a nested list describes, "((0 1) 2)": numbers are primitives (boxes[id]), parentheses inner
// nodes. Nodes are numbered in pre-order (the root 0, then its left subtree, then its right); boxes fitted.
struct tree_parser {
    const std::string& s;
    std::span<const aabb> boxes;
    binary_tree t;
    std::size_t pos = 0;

    void skip() { while (pos < s.size() && s[pos] == ' ') ++pos; }
    std::uint32_t parse(std::uint32_t parent) {
        skip();
        const auto index = std::uint32_t(t.nodes.size());
        t.nodes.emplace_back();
        t.nodes[index].parent = parent;
        if (s[pos] == '(') {
            ++pos;
            const std::uint32_t l = parse(index);
            const std::uint32_t r = parse(index);
            skip();
            REQUIRE(s[pos] == ')');
            ++pos;
            t.nodes[index].left = l, t.nodes[index].right = r;
            t.nodes[index].box = unite(t.nodes[l].box, t.nodes[r].box);
        } else {
            std::size_t used = 0;
            t.nodes[index].prim = std::uint32_t(std::stoul(s.substr(pos), &used));
            pos += used;
            t.nodes[index].box = boxes[t.nodes[index].prim];
        }
        return index;
    }
};

binary_tree parse_tree(const std::string& s, std::span<const aabb> boxes) {
    tree_parser p{s, boxes, {}};
    p.t.root = p.parse(none);
    return std::move(p.t);
}

// Eight unit boxes at x = 0, 1, 4, 10, 11, 30, 31, 40 in the tree
//   0 root [0,41]
//     1 [0,12] area 50:   2 (p0 p1) [0,2] area 10: 3 p0, 4 p1
//                         5 [4,12] area 34:        6 p2, 7 (p3 p4) [10,12] area 10: 8 p3, 9 p4
//     10 [30,41] area 46: 11 (p5 p6) [30,32] area 10: 12 p5, 13 p6;  14 p7
const std::vector<aabb> eight = {along_x(0, 1),   along_x(1, 2),   along_x(4, 5),   along_x(10, 11),
                                 along_x(11, 12), along_x(30, 31), along_x(31, 32), along_x(40, 41)};
const std::string eight_tree = "(((0 1) (2 (3 4))) ((5 6) 7))";

void check_treelet(const treelet& got, std::uint32_t root, const ids& leaves, const ids& inner) {
    CHECK(got.root == root);
    CHECK(got.leaves == leaves);
    CHECK(got.inner == inner);
}

std::size_t primitives_below(const binary_tree& t, std::uint32_t i) {
    return t.nodes[i].is_leaf() ? 1 : primitives_below(t, t.nodes[i].left) + primitives_below(t, t.nodes[i].right);
}

}  // namespace

TEST_CASE("08.1 treelet: a hand-made tree, the largest leaf expanded each time, 2 to 5 and 8, 9 leaves",
          "[ch08][pts:3]") {
    const binary_tree t = parse_tree(eight_tree, eight);
    REQUIRE(t.nodes.size() == 15);
    REQUIRE(t.nodes[1].box.surface_area() == 50.0f);
    REQUIRE(t.nodes[10].box.surface_area() == 46.0f);
    // Two leaves: the root's children, nothing expanded.
    check_treelet(form_treelet(t, 0, 2), 0, {1, 10}, {0});
    // 1 (area 50) before 10 (46): 1 leaves, its children 2 and 5 come last.
    check_treelet(form_treelet(t, 0, 3), 0, {10, 2, 5}, {0, 1});
    // Of 10 (46), 2 (10), 5 (34): 10.
    check_treelet(form_treelet(t, 0, 4), 0, {2, 5, 11, 14}, {0, 1, 10});
    // Of 2 (10), 5 (34), 11 (10); 14 is a primitive: 5.
    check_treelet(form_treelet(t, 0, 5), 0, {2, 11, 14, 6, 7}, {0, 1, 10, 5});
    // Eight leaves: every primitive, inner nodes by area, equal areas by index (2, 7, 11).
    check_treelet(form_treelet(t, 0, 8), 0, {14, 6, 3, 4, 8, 9, 12, 13}, {0, 1, 10, 5, 2, 7, 11});
    // Nine asked for, eight primitives: the same treelet.
    check_treelet(form_treelet(t, 0, 9), 0, {14, 6, 3, 4, 8, 9, 12, 13}, {0, 1, 10, 5, 2, 7, 11});
}

TEST_CASE("08.1 treelet: equal areas go to the lower node index, wherever it stands in the list",
          "[ch08][pts:2]") {
    const binary_tree t = parse_tree(eight_tree, eight);
    // Six leaves: 2, 11 and 7 all have area 10; 2 is the lowest index (and first in the list).
    check_treelet(form_treelet(t, 0, 6), 0, {11, 14, 6, 7, 3, 4}, {0, 1, 10, 5, 2});
    // Seven: 11 and 7 have area 10; 11 stands first in the list, but 7 is the lower index.
    check_treelet(form_treelet(t, 0, 7), 0, {11, 14, 6, 3, 4, 8, 9}, {0, 1, 10, 5, 2, 7});
    // The same tree mirrored (right subtrees first): the ties now stand in the other order in the list.
    const std::string mirrored = "((7 (6 5)) (((4 3) 2) (1 0)))";
    const binary_tree m = parse_tree(mirrored, eight);
    // 0 root; 1 [30,41] (46): 2 p7, 3 (p6 p5) [30,32] (10): 4, 5; 6 [0,12] (50): 7 [4,12] (34):
    // 8 (p4 p3) [10,12] (10): 9, 10; 11 p2; 12 (p1 p0) [0,2] (10): 13, 14.
    // Five: 12, 3 and 8 all have area 10 afterwards, 12 first in the list.
    check_treelet(form_treelet(m, 0, 5), 0, {12, 2, 3, 8, 11}, {0, 6, 1, 7});
    check_treelet(form_treelet(m, 0, 6), 0, {12, 2, 8, 11, 4, 5}, {0, 6, 1, 7, 3});
    check_treelet(form_treelet(m, 0, 7), 0, {12, 2, 11, 4, 5, 9, 10}, {0, 6, 1, 7, 3, 8});
}

TEST_CASE("08.1 treelet: a primitive's leaf is never expanded, and small subtrees stop early, and a leaf root",
          "[ch08][pts:1]") {
    // A huge triangle (area 402) beside a small pair (area 10): only the pair can be expanded.
    const std::vector<aabb> boxes = {along_x(0, 100), along_x(0, 1), along_x(1, 2)};
    const binary_tree t = parse_tree("(0 (1 2))", boxes);
    check_treelet(form_treelet(t, 0, 3), 0, {1, 3, 4}, {0, 2});
    check_treelet(form_treelet(t, 0, 7), 0, {1, 3, 4}, {0, 2});
    // A treelet below the root, and one at a primitive's leaf.
    const binary_tree e = parse_tree(eight_tree, eight);
    check_treelet(form_treelet(e, 5, 3), 5, {6, 8, 9}, {5, 7});
    check_treelet(form_treelet(e, 5, 7), 5, {6, 8, 9}, {5, 7});
    check_treelet(form_treelet(e, 3, 4), 3, {3}, {});
}

TEST_CASE("08.1 treelet: on LBVH trees, a valid treelet grown largest first, leaves in the contract's order",
          "[ch08][pts:2]") {
    const ch07::builder_inputs in(random_soup(600, 17, 0.1f));
    const binary_tree t = lbvh_binary_tree(in.boxes, in.centroids);
    REQUIRE(t.root != none);
    std::size_t checked = 0;
    for (std::uint32_t root = 0; root < t.nodes.size(); root += 7) {
        for (int n = 2; n <= max_treelet_leaves; ++n) {
            INFO("root " << root << ", " << n << " leaves");
            const treelet tl = form_treelet(t, root, n);
            REQUIRE(tl.root == root);
            if (t.nodes[root].is_leaf()) {
                CHECK(tl.leaves == ids{root});
                CHECK(tl.inner.empty());
                continue;
            }
            ++checked;
            // As many leaves as asked for, or every primitive below.
            CHECK(tl.leaves.size() == std::min<std::size_t>(std::size_t(n), primitives_below(t, root)));
            REQUIRE(tl.inner.size() + 1 == tl.leaves.size());
            REQUIRE(tl.inner[0] == root);
            // The expansions, replayed in the order of `inner`: each expands a current leaf that is an inner
            // node of t, and the leaves come out in exactly the contract's order.
            ids leaves = {t.nodes[root].left, t.nodes[root].right};
            float previous = t.nodes[root].box.surface_area();
            for (std::size_t k = 1; k < tl.inner.size(); ++k) {
                const std::uint32_t e = tl.inner[k];
                const auto at = std::find(leaves.begin(), leaves.end(), e);
                REQUIRE(at != leaves.end());
                REQUIRE(!t.nodes[e].is_leaf());
                // Largest first: no expandable leaf at that moment was larger.
                for (const std::uint32_t l : leaves)
                    if (!t.nodes[l].is_leaf()) CHECK(t.nodes[l].box.surface_area() <= t.nodes[e].box.surface_area());
                CHECK(t.nodes[e].box.surface_area() <= previous);
                previous = t.nodes[e].box.surface_area();
                leaves.erase(at);
                leaves.push_back(t.nodes[e].left), leaves.push_back(t.nodes[e].right);
            }
            CHECK(tl.leaves == leaves);
            // Stopped for a reason: n leaves, or none left to expand.
            if (tl.leaves.size() < std::size_t(n))
                for (const std::uint32_t l : tl.leaves) CHECK(t.nodes[l].is_leaf());
        }
    }
    CHECK(checked > 500);
}
