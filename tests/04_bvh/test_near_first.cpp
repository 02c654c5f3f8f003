// Exercise 04.3 near-first traversal (10 points). Only near_first_traversal: on a hand-made tree (the
// order of the nodes visited, for every sign of the direction), and on a tree built here over a random soup
// (closest hits equal to brute force's, nodes visited equal to a recursive walk's). The box tests are the
// test's own, so that these points never depend on exercise 04.1, nor the tree on exercise 04.2.
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch04/traverse.hpp"
#include "strahl/rng.hpp"
#include "exactness.hpp"
#include <catch2/catch.hpp>
#include <algorithm>
#include <vector>

using namespace strahl;
using namespace strahl::ch04;

namespace {

bvh_node make_node(aabb box, std::uint32_t offset, std::uint16_t count, int axis) {
    bvh_node n{};
    for (int a = 0; a < 3; ++a) n.bmin[a] = box.min[a], n.bmax[a] = box.max[a];
    n.offset = offset;
    n.count = count;
    n.axis = std::uint8_t(axis);
    return n;
}

// The hand-made tree, depth-first:        0 (axis x, right child 4)
//                                       /                         .
//                         1 (axis y, right 3)          4 (axis z, right 6)
//                          /          .                 /          .
//               2 leaf, ids [0, 1)  3 leaf [1, 2)   5 leaf [2, 4)  6 leaf [4, 5)
bvh hand_tree() {
    bvh t;
    const aabb big{vec3(0.0f), vec3(8.0f, 2.0f, 2.0f)};
    const aabb left{vec3(0.0f), vec3(4.0f, 2.0f, 2.0f)}, right{vec3(4.0f, 0.0f, 0.0f), vec3(8.0f, 2.0f, 2.0f)};
    t.bounds = big;
    t.nodes = {make_node(big, 4, 0, 0),   make_node(left, 3, 0, 1),  make_node(left, 0, 1, 0),
               make_node(left, 1, 1, 0),  make_node(right, 6, 0, 2), make_node(right, 2, 2, 0),
               make_node(right, 4, 1, 0)};
    t.prim_ids = {0, 1, 2, 3, 4};
    return t;
}

struct visit_log {
    std::vector<std::uint32_t> nodes;   // node indices in the order box_hit saw them
    std::vector<std::uint32_t> leaves;  // the leaves' first entries, in the order handed over
};

// Walks the hand-made tree; box_hit accepts every node but `rejected`, leaf stops at first entry `stop_at`.
std::uint32_t walk(const bvh& t, vec3 dir, visit_log& log, std::uint32_t rejected = ~0u, std::uint32_t stop_at = ~0u) {
    const auto box = [&](const bvh_node& n) {
        log.nodes.push_back(std::uint32_t(&n - t.nodes.data()));
        return log.nodes.back() != rejected;
    };
    const auto leaf = [&](std::uint32_t first, std::uint32_t) {
        log.leaves.push_back(first);
        return first == stop_at;
    };
    return near_first_traversal(t, dir, box, leaf);
}

using ids = std::vector<std::uint32_t>;

}  // namespace

TEST_CASE("04.3 near-first traversal: the order of the nodes, for each sign of the direction", "[ch04][pts:3]") {
    const bvh t = hand_tree();
    struct expected {
        vec3 dir;
        ids nodes, leaves;
    };
    const expected cases[] = {
        {vec3(1, 1, 1), {0, 1, 2, 3, 4, 5, 6}, {0, 1, 2, 4}},
        {vec3(-1, -1, -1), {0, 4, 6, 5, 1, 3, 2}, {4, 2, 1, 0}},
        {vec3(1, -2, 0.5f), {0, 1, 3, 2, 4, 5, 6}, {1, 0, 2, 4}},
        {vec3(-0.5f, 3, -1), {0, 4, 6, 5, 1, 2, 3}, {4, 2, 0, 1}},
    };
    for (const expected& e : cases) {
        CAPTURE(e.dir);
        visit_log log;
        CHECK(walk(t, e.dir, log) == 7u);
        CHECK(log.nodes == e.nodes);
        CHECK(log.leaves == e.leaves);
    }
}

TEST_CASE("04.3 near-first traversal: a box missed skips its whole subtree", "[ch04][pts:1]") {
    const bvh t = hand_tree();
    visit_log a;
    CHECK(walk(t, vec3(1), a, /*rejected*/ 1) == 5u);
    CHECK(a.nodes == ids{0, 1, 4, 5, 6});
    CHECK(a.leaves == ids{2, 4});
    visit_log root;
    CHECK(walk(t, vec3(1), root, /*rejected*/ 0) == 1u);
    CHECK(root.leaves.empty());
}

TEST_CASE("04.3 near-first traversal: a leaf answering true ends the walk at once", "[ch04][pts:1]") {
    const bvh t = hand_tree();
    visit_log log;
    CHECK(walk(t, vec3(1), log, ~0u, /*stop_at*/ 2) == 6u);
    CHECK(log.nodes == ids{0, 1, 2, 3, 4, 5});
    CHECK(log.leaves == ids{0, 1, 2});
    visit_log down;
    CHECK(walk(t, vec3(-1), down, ~0u, /*stop_at*/ 4) == 3u);
    CHECK(down.leaves == ids{4});
}

TEST_CASE("04.3 near-first traversal: +0 takes the left child first, -0 the right one", "[ch04][pts:1]") {
    const bvh t = hand_tree();
    visit_log plus, minus;
    walk(t, vec3(0.0f, 0.0f, 0.0f), plus);
    walk(t, vec3(-0.0f, -0.0f, -0.0f), minus);
    CHECK(plus.nodes == ids{0, 1, 2, 3, 4, 5, 6});
    CHECK(minus.nodes == ids{0, 4, 6, 5, 1, 3, 2});
}

TEST_CASE("04.3 near-first traversal: an empty tree visits nothing, a lone leaf itself", "[ch04][pts:1]") {
    bvh empty;
    int calls = 0;
    const auto box = [&](const bvh_node&) { return ++calls, true; };
    const auto leaf = [&](std::uint32_t, std::uint32_t) { return ++calls, false; };
    CHECK(near_first_traversal(empty, vec3(1), box, leaf) == 0u);
    CHECK(calls == 0);
    bvh lone;
    lone.nodes = {make_node(aabb{vec3(0.0f), vec3(1.0f)}, 0, 3, 0)};
    lone.prim_ids = {0, 1, 2};
    std::uint32_t got_first = 9, got_count = 0;
    const auto record = [&](std::uint32_t first, std::uint32_t count) { return got_first = first, got_count = count, false; };
    CHECK(near_first_traversal(lone, vec3(1), box, record) == 1u);
    CHECK(got_first == 0u);
    CHECK(got_count == 3u);
    const auto never = [&](const bvh_node&) { return false; };
    got_count = 0;
    CHECK(near_first_traversal(lone, vec3(1), never, record) == 1u);
    CHECK(got_count == 0u);
}

namespace {

// A median-split tree built here (leaves of at most 2), in chapter 04's flat layout.
std::uint32_t build(bvh& t, const std::vector<aabb>& boxes, std::uint32_t begin, std::uint32_t end) {
    const std::uint32_t index = std::uint32_t(t.nodes.size());
    aabb box, centres;
    for (std::uint32_t k = begin; k < end; ++k) box.grow(boxes[t.prim_ids[k]]), centres.grow(boxes[t.prim_ids[k]].centroid());
    t.nodes.push_back(make_node(box, begin, std::uint16_t(end - begin), 0));
    if (end - begin <= 2) return index;
    const vec3 extent = centres.max - centres.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(t.prim_ids.begin() + begin, t.prim_ids.begin() + mid, t.prim_ids.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) { return boxes[a].centroid()[axis] < boxes[b].centroid()[axis]; });
    build(t, boxes, begin, mid);
    const std::uint32_t right = build(t, boxes, mid, end);
    t.nodes[index] = make_node(box, right, 0, axis);
    return index;
}

// A box test that never misses a box the ray touches: double precision, boxes grown by 1e-3.
bool loose_box_hit(const bvh_node& n, const ray& r) {
    double t0 = r.tmin, t1 = r.tmax;
    for (int a = 0; a < 3; ++a) {
        const double lo = n.bmin[a] - 1e-3, hi = n.bmax[a] + 1e-3, o = r.org[a], d = r.dir[a];
        if (d == 0.0) {
            if (o < lo || o > hi) return false;
            continue;
        }
        double tn = (lo - o) / d, tf = (hi - o) / d;
        if (tn > tf) std::swap(tn, tf);
        t0 = std::max(t0, tn);
        t1 = std::min(t1, tf);
    }
    return t0 <= t1;
}

// The same walk written recursively, near child first: the count of nodes a correct stack walk visits.
void recursive_walk(const bvh& t, std::uint32_t index, ray& r, const ch01::triangle_set& tris, hit& best,
                    std::uint32_t& visited) {
    const bvh_node& n = t.nodes[index];
    ++visited;
    if (!loose_box_hit(n, r)) return;
    if (n.is_leaf()) {
        for (std::uint32_t k = 0; k < n.count; ++k) tris.intersect(t.prim_ids[n.offset + k], r, best);
        return;
    }
    const bool down = std::signbit(r.dir[n.axis]);
    recursive_walk(t, down ? n.offset : index + 1, r, tris, best, visited);
    recursive_walk(t, down ? index + 1 : n.offset, r, tris, best, visited);
}

}  // namespace

TEST_CASE("04.3 near-first traversal: closest hits as brute force's, nodes visited as the recursive walk's",
          "[ch04][pts:3]") {
    pcg32 rng(404);
    triangle_mesh mesh;
    for (std::uint32_t i = 0; i < 400; ++i) {
        const vec3 c(rng.next_float(), rng.next_float(), rng.next_float());
        for (int k = 0; k < 3; ++k)
            mesh.positions.push_back(c + 0.06f * vec3(rng.next_float(), rng.next_float(), rng.next_float()));
        mesh.indices.push_back(uvec3(3 * i, 3 * i + 1, 3 * i + 2));
    }
    const ch01::triangle_set tris(mesh);
    std::vector<aabb> boxes;
    for (const uvec3& f : mesh.indices) {
        aabb b;
        for (int k = 0; k < 3; ++k) b.grow(mesh.positions[f[k]]);
        boxes.push_back(b);
    }
    bvh t;
    for (std::uint32_t i = 0; i < boxes.size(); ++i) t.prim_ids.push_back(i);
    build(t, boxes, 0, std::uint32_t(boxes.size()));
    t.bounds = t.nodes[0].box();

    int wrong_hits = 0, wrong_counts = 0;
    for (int i = 0; i < 500; ++i) {
        ray q;
        q.org = vec3(rng.next_float(), rng.next_float(), rng.next_float()) * 3.0f - vec3(1.0f);
        const vec3 target(rng.next_float(), rng.next_float(), rng.next_float());
        q.dir = target - q.org;
        if (i % 5 == 0) q.dir[i % 3] = (i % 2) ? 0.0f : -0.0f;  // some directions in a coordinate plane
        hit brute;
        ray rb = q;
        for (std::uint32_t k = 0; k < tris.size(); ++k) tris.intersect(k, rb, brute);
        hit mine, theirs;
        ray rm = q, rr = q;
        const auto box = [&](const bvh_node& n) { return loose_box_hit(n, rm); };
        const auto leaf = [&](std::uint32_t first, std::uint32_t count) {
            for (std::uint32_t k = 0; k < count; ++k) tris.intersect(t.prim_ids[first + k], rm, mine);
            return false;
        };
        const std::uint32_t visited = near_first_traversal(t, q.dir, box, leaf);
        std::uint32_t expected = 0;
        recursive_walk(t, 0, rr, tris, theirs, expected);
        if (!test::bit_equal(mine, brute)) {
            if (++wrong_hits <= 3) UNSCOPED_INFO("ray " << i << ": org " << q.org << " dir " << q.dir << ": prim " << mine.prim
                                                        << " at t " << mine.t << ", brute force prim " << brute.prim << " at t " << brute.t);
        }
        if (visited != expected) {
            if (++wrong_counts <= 3) UNSCOPED_INFO("ray " << i << ": " << visited << " nodes visited, the recursive near-first walk visits " << expected);
        }
    }
    CHECK(wrong_hits == 0);
    CHECK(wrong_counts == 0);
}
