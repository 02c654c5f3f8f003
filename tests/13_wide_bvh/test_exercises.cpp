// Chapter 13's graded exercises: 13.1 the greedy collapse's choice, 13.2 the node test on N boxes, 13.3 the
// ordered push, and the traversal they make, exact against brute force.
#include "strahl/ch05/sah.hpp"
#include "strahl/ch13/accel.hpp"
#include "strahl/ch13/wide_traverse.hpp"
#include "strahl/procedural.hpp"
#include "strahl/rng.hpp"
#include "bvh_rays.hpp"
#include "exactness.hpp"
#include "hand_tree.hpp"
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstring>
#include <limits>

using namespace strahl;
using namespace strahl::ch13;

namespace {



std::vector<std::uint32_t> triangles_of(const wide_bvh<4, 4>& w, std::uint32_t ref) {
    std::vector<std::uint32_t> ids;
    for (std::uint32_t b = 0; b < leaf_blocks(ref); ++b)
        for (std::uint32_t id : w.blocks[leaf_first(ref) + b].id) ids.push_back(id);
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
}

std::unique_ptr<wide_accel_base> optimal_bvh(int width, int block) {
    wide_config c;
    c.width = width, c.block = block;
    c.collapse.method = collapse_method::optimal;
    return make_accel("test", [](std::span<const aabb> b, std::span<const vec3> c) {
        return ch05::build_sah_bvh_fast(b, c);
    }, c);
}

// The binary tree optimal_bvh collapses (the same build on the same boxes), whose boxes nasty_rays aims at.
ch04::bvh source_tree(const triangle_mesh& m) {
    std::vector<aabb> boxes(m.triangle_count());
    std::vector<vec3> centroids(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const auto t = m.triangle(i);
        boxes[i] = aabb{}.grow(t[0]).grow(t[1]).grow(t[2]), centroids[i] = boxes[i].centroid();
    }
    return ch05::build_sah_bvh_fast(boxes, centroids);
}

}  // namespace

TEST_CASE("13.1 the child to open: the inner child of largest area, the lowest index among equals", "[ch13][pts:2]") {
    const float areas[] = {3.0f, 9.0f, 5.0f, 9.0f};
    const bool no_leaf[] = {false, false, false, false};
    CHECK(child_to_open(areas, no_leaf) == 1);
    const bool leaf1[] = {false, true, false, false};
    CHECK(child_to_open(areas, leaf1) == 3);  // the largest is a leaf: the next largest inner one
    const bool leaves_but_0[] = {false, true, true, true};
    CHECK(child_to_open(areas, leaves_but_0) == 0);
    const bool all_leaves[] = {true, true, true, true};
    CHECK(child_to_open(areas, all_leaves) == -1);
    const float flat[] = {0.0f, 0.0f};
    const bool inner2[] = {false, false};
    CHECK(child_to_open(flat, inner2) == 0);  // zero areas: still inner, still opened
    const float one_area[] = {2.0f};
    const bool one_leaf[] = {true};
    CHECK(child_to_open(one_area, one_leaf) == -1);
}

TEST_CASE("13.1 the child to open: the greedy collapse of a hand-made tree", "[ch13][pts:2]") {
    const ch04::bvh t = test::hand_tree();
    const triangle_mesh m = test::six_triangles();
    const wide_bvh<4, 4> w = collapse<4, 4>(t, m, {});
    // Root: {A, B} -> open A (384 > 72): {A1, A2, B} -> open A2 (294 > 72): {A1, B, 4, 5}: four children.
    REQUIRE_FALSE(is_leaf(w.root_ref));
    REQUIRE(w.nodes.size() == 2);  // the root and B (B's two leaves below it)
    const wide_node<4>& root = w.nodes[w.root_ref];
    std::vector<std::vector<std::uint32_t>> kids;
    int inner = 0;
    for (int k = 0; k < 4; ++k) {
        REQUIRE(root.used(k));
        if (is_leaf(root.child[k])) kids.push_back(triangles_of(w, root.child[k]));
        else ++inner, kids.push_back({});
    }
    CHECK(inner == 1);
    CHECK(kids[0] == std::vector<std::uint32_t>{0});  // A1 stays where A stood
    CHECK(kids[1].empty());                           // B, an inner node
    CHECK(kids[2] == std::vector<std::uint32_t>{1});  // A2's left where A2 stood
    CHECK(kids[3] == std::vector<std::uint32_t>{2});  // A2's right appended
    const wide_node<4>& b = w.nodes[root.child[1]];
    CHECK(triangles_of(w, b.child[0]) == std::vector<std::uint32_t>{3, 4});
    CHECK(triangles_of(w, b.child[1]) == std::vector<std::uint32_t>{5});
    CHECK_FALSE(b.used(2));
    CHECK_FALSE(b.used(3));
}

TEST_CASE("13.2 the node test: each lane equals chapter 05's fast slab test on its box, bit for bit", "[ch13][pts:3]") {
    pcg32 g(13, 2);
    const auto check = [&](auto width, auto fused) {
        constexpr int N = decltype(width)::value;
        constexpr bool Fused = decltype(fused)::value;
        const aabb bounds{vec3(-4), vec3(4)};
        std::size_t hits = 0, misses = 0;
        for (int trial = 0; trial < 400; ++trial) {
            wide_node<N> n{};
            for (int k = 0; k < N; ++k) {
                const bool unused = g.next_float() < 0.15f;
                for (int a = 0; a < 3; ++a) {
                    float x = g.next_float() * 8 - 4, y = g.next_float() * 8 - 4;
                    if (trial % 7 == 0) y = x;  // flat boxes
                    n.lo[a][k] = unused ? inf : std::min(x, y);
                    n.hi[a][k] = unused ? -inf : std::max(x, y);
                }
            }
            // From around the boxes towards a point among them, so that about half the boxes are hit.
            const vec3 from(g.next_float() * 10 - 5, g.next_float() * 10 - 5, g.next_float() * 10 - 5);
            const vec3 to(g.next_float() * 6 - 3, g.next_float() * 6 - 3, g.next_float() * 6 - 3);
            ray r{from, to - from, 0.0f, inf};
            const auto s = ch05::fast_slab::make(r, bounds);
            if (!s) continue;
            const float t0 = trial % 3 == 0 ? -1.0f : 0.0f, t1 = trial % 5 == 0 ? 2.0f : inf;
            simd::vmask<N> hit;
            const simd::vfloat<N> t = node_entry_out_of_line<N, Fused>(n, wide_fast_slab<N, Fused>(r, *s), t0, t1, hit);
            for (int k = 0; k < N; ++k) {
                ch04::bvh_node box{};
                for (int a = 0; a < 3; ++a) box.bmin[a] = n.lo[a][k], box.bmax[a] = n.hi[a][k];
                const float want = s->entry<Fused>(box, t0, t1);
                INFO("width " << N << ", fused " << Fused << ", trial " << trial << ", lane " << k);
                REQUIRE(hit[k] == (want != inf));
                if (hit[k]) {
                    const float got = t[k];
                    CHECK(std::memcmp(&got, &want, 4) == 0);
                    ++hits;
                } else {
                    ++misses;
                }
                if (!n.used(k)) CHECK_FALSE(hit[k]);
            }
        }
        CHECK(hits > 100);
        CHECK(misses > 100);
    };
    check(std::integral_constant<int, 4>{}, std::true_type{});
    check(std::integral_constant<int, 8>{}, std::true_type{});
    check(std::integral_constant<int, 16>{}, std::true_type{});
    check(std::integral_constant<int, 8>{}, std::false_type{});
}

TEST_CASE("13.3 the ordered push: nearest returned, the others pushed farthest first", "[ch13][pts:2]") {
    const std::uint32_t child[8] = {10, 11, 12, 13, 14, 15, 16, 17};
    const float t[8] = {5.0f, 1.0f, 9.0f, 3.0f, 3.0f, 0.5f, 7.0f, 2.0f};
    stack_entry stack[16];
    int top = 1;
    stack[0] = {99, -1.0f};
    // Children 0, 2, 3, 4 and 6: distances 5, 9, 3, 3, 7 -> nearest 3 (child 3, the lower index of the tie).
    const std::uint32_t next = push_ordered_out_of_line<8>(0b1011101u, t, child, stack, top);
    CHECK(next == 13);
    REQUIRE(top == 5);
    CHECK(stack[0].ref == 99);  // what was there stays
    CHECK(stack[1].ref == 12);  // 9
    CHECK(stack[2].ref == 16);  // 7
    CHECK(stack[3].ref == 10);  // 5
    CHECK(stack[4].ref == 14);  // 3, the higher index of the tie: visited after 13
    CHECK(stack[4].t == 3.0f);
    // Two children.
    top = 0;
    CHECK(push_ordered_out_of_line<8>(0b10100000u, t, child, stack, top) == 15);
    REQUIRE(top == 1);
    CHECK(stack[0].ref == 17);
    CHECK(stack[0].t == 2.0f);
    // Four wide, all four.
    top = 0;
    CHECK(push_ordered_out_of_line<4>(0b1111u, t, child, stack, top) == 11);
    REQUIRE(top == 3);
    CHECK((stack[0].ref == 12 && stack[1].ref == 10 && stack[2].ref == 13));
}

TEST_CASE("13.3 the ordered push: the wide BVH equals brute force on rays made to break it",
          "[ch13][pts:3]") {
    const scene s = teapot_scene(3);
    for (const auto& [width, block] : {std::pair{4, 4}, {8, 4}, {8, 8}, {16, 4}}) {
        const auto a = optimal_bvh(width, block);
        a->build(s);
        INFO("BVH" << width << ", blocks of " << block);
        CHECK(test::disagreements_with_brute_force(*a, s.mesh, test::nasty_rays(source_tree(s.mesh), 500, 13)) == 0);
    }
}
