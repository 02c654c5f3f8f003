// Chapter 13 beyond the exercises (0 points): the collapses' trees (every triangle once, full nodes, the
// optimal collapse's SAH cost no higher than the greedy one's), and exactness against brute force for every
// width, block size and collapse on scenes and rays made to break them.
#include "strahl/ch05/sah.hpp"
#include "strahl/ch13/accel.hpp"
#include "strahl/procedural.hpp"
#include "bvh_rays.hpp"
#include "exactness.hpp"
#include "hand_tree.hpp"
#include "slab_cases.hpp"
#include "strahl/ch13/quantized_node.hpp"
#include "strahl/ch13/wide_traverse.hpp"
#include "test_support.hpp"
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstring>
#include <limits>
#include <tuple>

using namespace strahl;
using namespace strahl::ch13;

using test::copies;
using test::mesh_only;

namespace {

ch04::bvh binary(const triangle_mesh& m, int max_leaf = 8) {
    std::vector<aabb> boxes(m.triangle_count());
    std::vector<vec3> centroids(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const auto t = m.triangle(i);
        boxes[i] = aabb().grow(t[0]).grow(t[1]).grow(t[2]);
        centroids[i] = boxes[i].centroid();
    }
    ch05::sah_build_params p;
    p.max_leaf = max_leaf;
    return ch05::build_sah_bvh_fast(boxes, centroids, p);
}

// Every triangle of the binary tree exactly once in the wide tree's leaves; nodes not needlessly empty.
template <int N, int M>
void check_tree(const ch04::bvh& t, const triangle_mesh& m, collapse_method method) {
    collapse_config c;
    c.method = method;
    const wide_bvh<N, M> w = collapse<N, M>(t, m, c);
    INFO("BVH" << N << " blocks of " << M << ", " << to_string(method));
    // Each array allocated once, at its size (counted before the collapse writes it: huge_pages.hpp
    // faults in the whole allocation, so a bound would cost pages never used).
    CHECK(w.nodes.capacity() == w.nodes.size());
    CHECK(w.blocks.capacity() == w.blocks.size());
    std::vector<std::uint32_t> seen;
    const auto leaf_ids = [&](std::uint32_t ref) {
        std::vector<std::uint32_t> ids;
        for (std::uint32_t b = 0; b < leaf_blocks(ref); ++b)
            for (std::uint32_t id : w.blocks[leaf_first(ref) + b].id) ids.push_back(id);
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());  // (padding repeats the last triangle)
        seen.insert(seen.end(), ids.begin(), ids.end());
    };
    if (is_leaf(w.root_ref)) leaf_ids(w.root_ref);
    for (const wide_node<N>& n : w.nodes) {
        int used = 0;
        bool any_inner = false;
        for (int k = 0; k < N; ++k) {
            if (!n.used(k)) continue;
            ++used;
            if (is_leaf(n.child[k])) {
                leaf_ids(n.child[k]);
            } else {
                any_inner = true;
                CHECK(n.child[k] < w.nodes.size());
            }
        }
        CHECK(used >= 2);
        if (method == collapse_method::greedy && used < N) CHECK_FALSE(any_inner);  // greedy fills every node it can
    }
    std::vector<std::uint32_t> want = t.prim_ids;
    std::sort(want.begin(), want.end());
    std::sort(seen.begin(), seen.end());
    CHECK(seen == want);
    CHECK(w.stats.triangles == want.size());
}

void check_exact(const scene& s, std::size_t n_rays) {
    for (const collapse_method method : {collapse_method::greedy, collapse_method::optimal})
        for (const auto& [width, block, order, quantized, octant] :
             {std::tuple{4, 4, child_order::collapsed, false, false}, {8, 4, child_order::collapsed, false, false},
              {8, 8, child_order::collapsed, false, false}, {8, 8, child_order::leaves_then_area, false, false},
              {8, 8, child_order::leaves_then_area, true, false}, {8, 4, child_order::collapsed, false, true},
              {8, 8, child_order::leaves_then_area, false, true}, {16, 4, child_order::collapsed, false, false},
              {16, 8, child_order::collapsed, false, false}}) {
            wide_config c;
            c.width = width, c.block = block, c.collapse.method = method, c.order = order, c.quantized = quantized;
            c.octant_order = octant;
            const auto a = make_accel("test", [](std::span<const aabb> b, std::span<const vec3> c) {
                return ch05::build_sah_bvh_fast(b, c);
            }, c);
            a->build(s);
            INFO("BVH" << width << ", blocks of " << block << ", " << to_string(method) << " collapse, order "
                       << int(order) << (quantized ? ", quantised" : "") << (octant ? ", octant order" : "") << ", "
                       << s.mesh.triangle_count() << " triangles");
            CHECK(test::disagreements_with_brute_force(*a, s.mesh, test::nasty_rays(binary(s.mesh), n_rays, 17)) == 0);
        }
}

}  // namespace

TEST_CASE("ch13 collapse: every triangle once, full nodes, on the teapot and a soup", "[ch13]") {
    for (const triangle_mesh& m : {teapot_scene(3).mesh, random_soup(2000, 5, 0.1f)}) {
        const ch04::bvh t = binary(m);
        check_tree<4, 4>(t, m, collapse_method::greedy);
        check_tree<8, 4>(t, m, collapse_method::greedy);
        check_tree<16, 8>(t, m, collapse_method::greedy);
        check_tree<4, 4>(t, m, collapse_method::optimal);
        check_tree<8, 4>(t, m, collapse_method::optimal);
        check_tree<8, 8>(t, m, collapse_method::optimal);
    }
}

TEST_CASE("ch13 collapse: the optimal collapse costs no more than the greedy one", "[ch13]") {
    const triangle_mesh m = teapot_scene(3).mesh;
    const ch04::bvh t = binary(m);
    collapse_config greedy, optimal;
    optimal.method = collapse_method::optimal;
    const wide_bvh<8, 4> g = collapse<8, 4>(t, m, greedy), o = collapse<8, 4>(t, m, optimal);
    CHECK(o.stats.sah <= g.stats.sah * (1 + 1e-5));
    CHECK(o.stats.sah > 0.0);
    // The same for 4 and 16 children, and with leaves of up to 16 triangles to gather.
    const wide_bvh<4, 4> g4 = collapse<4, 4>(t, m, greedy), o4 = collapse<4, 4>(t, m, optimal);
    CHECK(o4.stats.sah <= g4.stats.sah * (1 + 1e-5));
    optimal.max_leaf = 16;
    const wide_bvh<16, 8> g16 = collapse<16, 8>(t, m, greedy), o16 = collapse<16, 8>(t, m, optimal);
    CHECK(o16.stats.sah <= g16.stats.sah * (1 + 1e-5));
    WARN("teapot, BVH8 with blocks of 4: SAH cost " << g.stats.sah << " greedy, " << o.stats.sah << " optimal; "
         << g.nodes.size() << " and " << o.nodes.size() << " nodes");
}

TEST_CASE("ch13 collapse: the optimal collapse of the hand-made tree gathers B's three triangles into one leaf",
          "[ch13]") {
    // The chapter's worked example: {A1, 4, 5, B as one leaf}, cost (1536 + 6 + 6 + 6 + 72) / 1536, against
    // the greedy {A1, B, 4, 5} with B a node of two leaves, (1536 + 6 + 72 + 6 + 6 + 6 + 6) / 1536.
    collapse_config optimal;
    optimal.method = collapse_method::optimal;
    const wide_bvh<4, 4> o = collapse<4, 4>(test::hand_tree(), test::six_triangles(), optimal);
    const wide_bvh<4, 4> g = collapse<4, 4>(test::hand_tree(), test::six_triangles(), {});
    REQUIRE(o.nodes.size() == 1);
    const wide_node<4>& root = o.nodes[0];
    std::vector<std::size_t> leaf_triangles;
    for (int k = 0; k < 4; ++k) {
        REQUIRE(root.used(k));
        REQUIRE(is_leaf(root.child[k]));
        std::vector<std::uint32_t> ids;
        for (std::uint32_t id : o.blocks[leaf_first(root.child[k])].id) ids.push_back(id);
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        leaf_triangles.push_back(ids.size());
    }
    CHECK(leaf_triangles == std::vector<std::size_t>{1, 1, 1, 3});
    CHECK(o.stats.sah == Approx(1626.0 / 1536.0));
    CHECK(g.stats.sah == Approx(1638.0 / 1536.0));
}

TEST_CASE("ch13 wide BVH: keeps its nodes and blocks and nothing else, loose triangles and all rays still "
          "answered", "[ch13][adversarial]") {
    // A teapot with two triangles reaching infinity (left out of the tree: loose) and rays no tree can place:
    // both are answered from the blocks (and the loose triangles' own blocks), not from a copy of the mesh.
    triangle_mesh m = teapot_scene(3).mesh;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const vec3 bad : {vec3(inf, 0, 0), vec3(1, -inf, 1)}) {
        const std::uint32_t at = std::uint32_t(m.positions.size());
        m.positions.insert(m.positions.end(), {bad, vec3(0, 0, 0), vec3(1, 1, 1)});
        m.indices.push_back(uvec3(at, at + 1, at + 2));
    }
    for (const auto& [width, block] : {std::pair{8, 8}, {16, 4}}) {
        wide_config c;
        c.width = width, c.block = block, c.collapse.method = collapse_method::optimal;
        const auto a = make_accel("test", [](std::span<const aabb> b, std::span<const vec3> c) {
            return ch05::build_sah_bvh_fast(b, c);
        }, c);
        a->build(mesh_only(m));
        const ch04::bvh t = binary(m);
        REQUIRE(t.loose.size() == 2);
        std::size_t tree_bytes = 0, block_bytes = 0;
        if (width == 8) {
            const wide_bvh<8, 8> w = collapse<8, 8>(t, m, c.collapse);
            tree_bytes = w.memory_bytes(), block_bytes = sizeof(triangle_block<8>);
        } else {
            const wide_bvh<16, 4> w = collapse<16, 4>(t, m, c.collapse);
            tree_bytes = w.memory_bytes(), block_bytes = sizeof(triangle_block<4>);
        }
        INFO("BVH" << width << ": " << a->memory_bytes() << " bytes held, the tree " << tree_bytes);
        CHECK(a->memory_bytes() == tree_bytes + 2 * (block_bytes + 8));  // the tree, and a block per loose triangle
        std::vector<ray> rays = test::nasty_rays(t, 400, 5);
        rays.push_back(ray{vec3(0.2f, 0.2f, -5.0f), vec3(0.0f, 0.0f, 0.0f)});                 // no direction
        rays.push_back(ray{vec3(nan, 0.0f, 0.0f), vec3(0.0f, 0.0f, 1.0f)});                  // no origin
        rays.push_back(ray{vec3(0.5f, 0.5f, -5.0f), vec3(0.0f, 0.0f, 1.0f), 0.0f, inf});     // through the loose ones
        CHECK(test::disagreements_with_brute_force(*a, m, rays) == 0);
    }
}

TEST_CASE("ch13 collapse: leaves too large for a leaf reference are refused", "[ch13]") {
    const triangle_mesh m = copies(300, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0));
    ch04::bvh t = binary(m);
    // One leaf of 300 triangles: more than 64 blocks of 4.
    t.nodes = {t.nodes[0]};
    t.nodes[0].offset = 0, t.nodes[0].count = 300;
    CHECK_THROWS_AS((collapse<8, 4>(t, m, {})), std::length_error);
    CHECK_NOTHROW(collapse<8, 8>(t, m, {}));  // 38 blocks of 8
    CHECK_THROWS_WITH(make_accel("x", {}, wide_config{8, 16, {}}), Catch::Contains("blocks of 16"));
}

TEST_CASE("ch13 wide BVH: every width equals brute force on the teapot and a soup", "[ch13][adversarial]") {
    check_exact(teapot_scene(3), 300);
    check_exact(mesh_only(random_soup(1200, 3, 0.1f)), 300);
}

TEST_CASE("ch13 wide BVH: planar, one triangle, empty, identical and collinear triangles", "[ch13][adversarial]") {
    triangle_mesh flat = random_soup(600, 5, 0.1f);
    for (vec3& p : flat.positions) p.z = 0.5f;
    check_exact(mesh_only(flat), 300);
    check_exact(mesh_only(copies(1, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0))), 200);
    check_exact(mesh_only(triangle_mesh{}), 100);
    check_exact(mesh_only(copies(500, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0))), 100);  // every tie at once
}

TEST_CASE("ch13 wide BVH: equals brute force on a scene far from the origin", "[ch13][adversarial]") {
    triangle_mesh far = teapot_scene(3).mesh;
    for (vec3& p : far.positions) p += vec3(3e4f, -1e5f, 2e4f);
    check_exact(mesh_only(far), 300);
}

TEST_CASE("ch13 octant order: per octant a permutation of the slots, used children first, by their centres along "
          "the octant's diagonal", "[ch13]") {
    const triangle_mesh m = teapot_scene(3).mesh;
    wide_bvh<8, 8> w = collapse<8, 8>(binary(m), m, {collapse_method::optimal});
    order_by_octant(w);
    REQUIRE(w.nodes.size() > 10);
    int reordered = 0;
    for (const wide_node<8>& n : w.nodes)
        for (int o = 0; o < 8; ++o) {
            const std::uint32_t word = n.octant_word(o);
            CHECK(word < (1u << 24));
            unsigned seen = 0;
            float last = -inf;
            bool unused_seen = false;
            for (int j = 0; j < 8; ++j) {
                const int k = (word >> (3 * j)) & 7;
                seen |= 1u << k;
                if (j != k) ++reordered;
                if (!n.used(k)) {
                    unused_seen = true;
                    continue;
                }
                CHECK_FALSE(unused_seen);  // used children first
                float key = 0.0f;
                for (int a = 0; a < 3; ++a) key += (((o >> a) & 1) ? -1.0f : 1.0f) * (n.lo[a][k] + n.hi[a][k]);
                CHECK(key >= last);  // nearest centre first
                last = key;
            }
            CHECK(seen == 0xffu);  // a permutation
        }
    CHECK(reordered > 0);  // not the stored order everywhere
}

TEST_CASE("ch13 quantised nodes: each decoded box holds its child's box and lies in the tree's bounds, on a "
          "power-of-two grid, at every scale", "[ch13][adversarial]") {
    static_assert(sizeof(qnode<8>) == 128 && sizeof(qnode<16>) == 256);
    const auto check = [](const triangle_mesh& m) {
        const wide_bvh<8, 8> w = collapse<8, 8>(binary(m), m, {collapse_method::optimal});
        const wide_bvh<8, 8, qnode<8>> q = quantize(w);
        REQUIRE(q.nodes.size() == w.nodes.size());
        CHECK(q.root_ref == w.root_ref);
        CHECK(q.blocks.size() == w.blocks.size());
        CHECK(q.memory_bytes() < w.memory_bytes());
        std::size_t tight = 0, planes = 0;
        for (std::size_t i = 0; i < w.nodes.size(); ++i)
            for (int k = 0; k < 8; ++k) {
                CHECK(q.nodes[i].used(k) == w.nodes[i].used(k));
                if (!w.nodes[i].used(k)) continue;
                CHECK(q.nodes[i].child[k] == w.nodes[i].child[k]);
                const aabb d = q.nodes[i].box(k), b = w.nodes[i].box(k);
                for (int a = 0; a < 3; ++a) {
                    const float step = q.nodes[i].step[a];
                    int e = 0;
                    CHECK(std::frexp(step, &e) == 0.5f);  // a power of two ...
                    CHECK(step >= 0x1p-100f);             // ... no smaller than the grid's floor
                    CHECK(d.min[a] <= b.min[a]);          // outward: the decoded box holds the child's
                    CHECK(d.max[a] >= b.max[a]);
                    CHECK(d.min[a] >= q.bounds.min[a]);   // and lies in the bounds the slab test is set up with
                    CHECK(d.max[a] <= q.bounds.max[a]);
                    // The SIMD row decodes to the same planes as the scalar one.
                    CHECK(q.nodes[i].row(a)[k] == d.min[a]);
                    CHECK(q.nodes[i].row(3 + a)[k] == d.max[a]);
                    planes += 2;
                    // Within two steps of the box (in double: no rounding), but where the grid is at its floor.
                    const double two = 2.0 * double(step);
                    tight += step == 0x1p-100f ? 2 : (d.min[a] > b.min[a] - two) + (d.max[a] < b.max[a] + two);
                }
            }
        CHECK(tight == planes);  // and no looser than the grid needs
    };
    const triangle_mesh teapot = teapot_scene(3).mesh;
    check(teapot);
    // Beyond the course's range (max_coordinate, min_extent) where the builders still work: the grid's floor.
    for (const float scale : {1e-33f, 1e-20f, 1e-9f, 1e11f}) {
        INFO("the teapot scaled by " << scale);
        triangle_mesh m = teapot;
        for (vec3& p : m.positions) p *= scale;
        check(m);
    }
    triangle_mesh far = teapot;  // small boxes far from the origin: steps of a few units of rounding
    for (vec3& p : far.positions) p = p * 1e-3f + vec3(1e6f, -3e5f, 7e4f);
    check(far);
    triangle_mesh flat = random_soup(600, 5, 0.1f);
    for (vec3& p : flat.positions) p.z = -0.5f;
    check(flat);
}

TEST_CASE("ch13 quantised nodes: the walk equals brute force at tiny, huge and far scales", "[ch13][adversarial]") {
    for (const auto& [scale, offset] : {std::pair{1e-33f, 0.0f}, {1e-9f, 0.0f}, {1e11f, 0.0f}, {1e-3f, 1e6f}}) {
        INFO("the teapot scaled by " << scale << ", moved by " << offset);
        triangle_mesh m = teapot_scene(3).mesh;
        for (vec3& p : m.positions) p = p * scale + vec3(offset);
        wide_config c;
        c.width = 8, c.block = 8, c.collapse.method = collapse_method::optimal, c.quantized = true;
        const auto a = make_accel("test", [](std::span<const aabb> b, std::span<const vec3> c) {
            return ch05::build_sah_bvh_fast(b, c);
        }, c);
        a->build(mesh_only(m));
        CHECK(test::disagreements_with_brute_force(*a, m, test::nasty_rays(binary(m), 300, 5)) == 0);
    }
}

TEST_CASE("ch13 wide BVH: the walk's float set-up of the fast test misses no box, near and far from the origin",
          "[ch13][adversarial]") {
    // The walk sets the fast test up in float from the ray and the tree's box (wide_traverse.hpp), not through
    // chapter 05's fast_slab::make in double: every lane must still meet each box the exact ray meets, and no
    // later than exactly (the long-double test of tests/05_sah, on a node holding the box in one slot).
    const auto float_setup = [](float widen) {
        return [widen](const ch04::bvh_node& b, const ray& r, float lo, float hi) -> std::optional<float> {
            wide_node<8> n{};
            for (int a = 0; a < 3; ++a)
                for (int k = 0; k < 8; ++k) n.lo[a][k] = k == 3 ? b.bmin[a] : inf, n.hi[a][k] = k == 3 ? b.bmax[a] : -inf;
            bool ok = false;
            const wide_fast_slab<8> s(r, b.box(), ok, widen);
            if (!ok) return std::nullopt;
            simd::vmask<8> hit;
            alignas(32) float t[8];
            node_entry_out_of_line(n, s, lo, hi, hit).store(t);
            return (simd::movemask(hit) >> 3 & 1) ? t[3] : inf;
        };
    };
    int lost_without_widening = 0;
    for (const float offset : {0.0f, 1.0f, 1e3f, 1e5f, 1e7f})
        for (const float size : {1e-3f, 1.0f, 1e3f}) {
            const auto cases = test::grazing_cases(offset, size, 23, 3000);
            INFO("box of size " << size << " at " << offset << " from the origin");
            const test::tally t = test::check_against_exact(cases, float_setup(0x1p-19f));
            if (size >= offset * 0x1p-16f) CHECK(t.tested > 800);
            CHECK(t.missed == 0);
            CHECK(t.late == 0);
            const test::tally bare = test::check_against_exact(cases, float_setup(0.0f));
            lost_without_widening += bare.missed + bare.late;
        }
    CHECK(lost_without_widening > 0);  // the widening is what the checks above test
}

TEST_CASE("ch13 child order: leaves first, then larger boxes, same children, same answers, and any-hit rays in a "
          "room meet a wall sooner", "[ch13]") {
    // A room of large walls (the Cornell box's) around a teapot of small triangles: rays from inside the room,
    // in every direction, unbounded; nearly all are blocked, most by a wall.
    triangle_mesh room = cornell_box(false).mesh;
    triangle_mesh pot = teapot_mesh(8);
    for (vec3& p : pot.positions) p = p * 0.12f + vec3(0.5f, 0.1f, 0.5f);
    room.append(pot);
    std::vector<ray> rays;
    std::uint64_t state = 7;
    const auto next = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return float(state >> 40) / float(1u << 24);
    };
    for (int i = 0; i < 3000; ++i) {
        const vec3 o(0.1f + 0.8f * next(), 0.05f + 0.9f * next(), 0.1f + 0.8f * next());
        const vec3 d(next() - 0.5f, next() - 0.5f, next() - 0.5f);
        rays.push_back(ray{o, d});
    }
    const scene s = mesh_only(room);
    std::vector<std::uint8_t> blocked(rays.size());
    std::uint64_t box_tests[2] = {};
    for (const child_order order : {child_order::collapsed, child_order::leaves_then_area}) {
        wide_config c;
        c.width = 8, c.block = 8, c.collapse.method = collapse_method::optimal, c.order = order;
        const auto a = make_accel("test", [](std::span<const aabb> b, std::span<const vec3> c) {
            return ch05::build_sah_bvh_fast(b, c);
        }, c);
        a->build(s);
        CHECK(test::disagreements_with_brute_force(*a, s.mesh, rays) == 0);
        box_tests[order == child_order::leaves_then_area] = a->occluded_counted(rays, blocked)->box_tests;
    }
    INFO(box_tests[0] << " box tests in the collapse's order, " << box_tests[1] << " leaves first, larger first");
    CHECK(box_tests[1] * 20 < box_tests[0] * 17);  // (0.79 of them when written)

    // The order itself: every node keeps its children in their slots, and lists each slot once, in rank order
    // (leaves first, then larger boxes); the collapse's order is 0, 1, ..., 7.
    const ch04::bvh t = binary(s.mesh);
    const wide_bvh<8, 8> before = collapse<8, 8>(t, s.mesh, {collapse_method::optimal});
    wide_bvh<8, 8> after = before;
    order_children(after, child_order::leaves_then_area);
    REQUIRE(after.nodes.size() == before.nodes.size());
    REQUIRE(after.nodes.size() > 10);
    std::size_t moved = 0;
    for (std::size_t i = 0; i < after.nodes.size(); ++i) {
        const wide_node<8>& a = after.nodes[i];
        const wide_node<8>& b = before.nodes[i];
        CHECK(std::memcmp(a.lo, b.lo, sizeof a.lo) == 0);
        CHECK(std::memcmp(a.hi, b.hi, sizeof a.hi) == 0);
        CHECK(std::memcmp(a.child, b.child, sizeof a.child) == 0);
        unsigned seen = 0;
        for (int j = 0; j < 8; ++j) {
            CHECK(b.order[j] == j);
            REQUIRE(a.order[j] < 8);
            seen |= 1u << a.order[j];
            moved += a.order[j] != j;
        }
        CHECK(seen == 0xffu);
        for (int j = 0; j + 1 < 8; ++j) CHECK(any_hit_rank(a, a.order[j]) >= any_hit_rank(a, a.order[j + 1]));
    }
    CHECK(moved > 0);
}
