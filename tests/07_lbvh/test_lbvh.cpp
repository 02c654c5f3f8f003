// Chapter 07 beyond the exercises (0 points): both hierarchy builders give valid radix trees, the same
// one where no two codes are equal; every LBVH is a valid chapter 04 tree (each primitive once, boxes tight
// around their children, leaves within max_leaf, depth within the bound, also for equal codes, an outlier
// and deep codes); the SAH collapse lowers the cost; the build is the same on 1 and 2 threads; and chapter
// 05's fast walk over it gives brute force's answers bit for bit.
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch07/accel.hpp"
#include "strahl/ch07/morton.hpp"
#include "strahl/ch07/radix_sort.hpp"
#include "strahl/parallel.hpp"
#include "strahl/procedural.hpp"
#include "strahl/rng.hpp"
#include "bvh_rays.hpp"
#include "differences.hpp"
#include "flat_bvh_check.hpp"
#include "exactness.hpp"
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstring>
#include <limits>

using namespace strahl;
using namespace strahl::ch07;

using test::copies;
using test::first_difference;
using test::mesh_only;

namespace {

using inputs = builder_inputs;

// A radix tree over n leaves: the root covers [0, n-1]; each inner node's children cover [first, g] and
// [g+1, last] for some g, numbered g and g+1; parents match; every leaf is reached once. Returns the depth.
int check_radix_tree(const radix_tree& t, std::size_t n) {
    REQUIRE(t.leaves() == n);
    REQUIRE(t.left.size() == (n > 1 ? n - 1 : 0));
    if (n < 2) return 0;
    CHECK(t.first[0] == 0);
    CHECK(t.last[0] == n - 1);
    CHECK(t.parent[0] == radix_tree::none);
    std::vector<int> reached(n, 0);
    int depth = 0;
    std::vector<std::pair<std::uint32_t, int>> stack = {{0u, 0}};
    while (!stack.empty()) {
        const auto [i, d] = stack.back();
        stack.pop_back();
        depth = std::max(depth, d + 1);
        const std::uint32_t g = t.left[i] & ~leaf_bit;
        REQUIRE(t.first[i] <= g);
        REQUIRE(g < t.last[i]);
        REQUIRE((t.right[i] & ~leaf_bit) == g + 1);
        for (const std::uint32_t child : {t.left[i], t.right[i]}) {
            const std::uint32_t k = child & ~leaf_bit;
            const std::uint32_t lo = k == g ? t.first[i] : g + 1, hi = k == g ? g : t.last[i];
            if (is_leaf_ref(child)) {
                REQUIRE(lo == hi);
                ++reached[k];
                CHECK(t.leaf_parent[k] == i);
            } else {
                REQUIRE(lo < hi);
                CHECK(t.first[k] == lo);
                CHECK(t.last[k] == hi);
                CHECK(t.parent[k] == i);
                stack.push_back({k, d + 1});
            }
        }
    }
    CHECK(std::count(reached.begin(), reached.end(), 1) == std::ptrdiff_t(n));
    return depth;
}

}  // namespace

TEST_CASE("ch07 radix tree: both builders give valid trees, the same one where the codes are unique", "[ch07]") {
    for (const int bits : {30, 63}) {
        for (const std::size_t n : {2, 3, 5, 17, 1000, 40000}) {
            pcg32 g(n * 7 + std::size_t(bits));
            std::vector<std::uint64_t> codes(n);
            for (std::uint64_t& c : codes) c = ((std::uint64_t(g.next_u32()) << 32) | g.next_u32()) >> (64 - bits);
            std::sort(codes.begin(), codes.end());
            codes.erase(std::unique(codes.begin(), codes.end()), codes.end());
            radix_tree lecture, karras;
            build_radix_tree_lecture(codes, lecture);
            build_radix_tree_karras(codes, karras);
            INFO(codes.size() << " unique " << bits << "-bit codes");
            check_radix_tree(lecture, codes.size());
            check_radix_tree(karras, codes.size());
            CHECK(first_difference(lecture.left, karras.left) == -1);
            CHECK(first_difference(lecture.right, karras.right) == -1);
            CHECK(first_difference(lecture.parent, karras.parent) == -1);
            CHECK(first_difference(lecture.leaf_parent, karras.leaf_parent) == -1);
        }
    }
    // Equal codes: both valid, of logarithmic depth, and different (the middle against the index bits).
    const std::vector<std::uint64_t> same(3000, 5);
    radix_tree lecture, karras;
    build_radix_tree_lecture(same, lecture);
    build_radix_tree_karras(same, karras);
    CHECK(check_radix_tree(lecture, same.size()) == 12);  // ceil(log2 3000)
    CHECK(check_radix_tree(karras, same.size()) == 12);
    CHECK(first_difference(lecture.left, karras.left) != -1);
    // Runs of equal codes among distinct ones.
    std::vector<std::uint64_t> runs;
    for (std::uint64_t c = 0; c < 300; ++c) runs.insert(runs.end(), 1 + c % 7, c * c);
    build_radix_tree_lecture(runs, lecture);
    build_radix_tree_karras(runs, karras);
    check_radix_tree(lecture, runs.size());
    check_radix_tree(karras, runs.size());
    // One code and none.
    build_radix_tree_karras(std::vector<std::uint64_t>{1}, karras);
    CHECK(check_radix_tree(karras, 1) == 0);
    build_radix_tree_lecture(std::vector<std::uint64_t>{}, lecture);
    CHECK(check_radix_tree(lecture, 0) == 0);
}

TEST_CASE("ch07 LBVH: every builder's tree is valid on scenes and degenerate inputs", "[ch07]") {
    std::vector<std::pair<std::string, triangle_mesh>> meshes;
    meshes.emplace_back("teapot", teapot_scene(3).mesh);
    meshes.emplace_back("soup", random_soup(2000, 3, 0.1f));
    meshes.emplace_back("all centroids equal", copies(3000, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)));
    meshes.emplace_back("one triangle", copies(1, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)));
    meshes.emplace_back("empty", triangle_mesh{});
    triangle_mesh flat = random_soup(600, 5, 0.1f);
    for (vec3& p : flat.positions) p.z = 0.5f;
    meshes.emplace_back("flat", flat);
    // A far outlier squeezes every other centroid into one cell of the grid: all their codes are equal.
    triangle_mesh outlier = random_soup(2000, 6, 0.1f);
    const auto b = std::uint32_t(outlier.positions.size());
    outlier.positions.insert(outlier.positions.end(), {vec3(1e30f), vec3(1e30f, 0, 0), vec3(0, 1e30f, 0)});
    outlier.indices.push_back(uvec3(b, b + 1, b + 2));
    meshes.emplace_back("a 1e30 outlier", outlier);
    triangle_mesh odd = random_soup(300, 9, 0.1f);
    odd.positions[0].x = std::numeric_limits<float>::quiet_NaN();
    odd.positions[5].y = std::numeric_limits<float>::infinity();
    meshes.emplace_back("non-finite vertices", odd);
    for (const auto& [name, mesh] : meshes) {
        const inputs in(mesh);
        for (const lbvh_params& p : lbvh_variants()) {
            INFO(name << ", " << to_string(p));
            lbvh_report r;
            const ch04::bvh t = build_lbvh(in.boxes, in.centroids, p, &r);
            test::check_flat_bvh(t, in.boxes, in.centroids);
            CHECK(r.rebalanced == 0);
            if (name == "all centroids equal" || name == "a 1e30 outlier") {
                CHECK(r.duplicate_codes + 1 >= mesh.triangle_count() - 1);
                CHECK(t.stats.depth <= 12);  // the index splits halve: log2(3000 / 4) levels and a few
            }
        }
    }
}

TEST_CASE("ch07 LBVH: deep codes stay within the depth bound, rebuilt by halving where they would not",
          "[ch07]") {
    // Centroids at exactly 2^-k on each axis (triangles in the plane z = c.z, their boxes centred on c): the
    // codes 2^m for every bit m, a chain as deep as the code has bits, and 200 more at its bottom.
    triangle_mesh m;
    for (int k = 0; k < 40; ++k)
        for (int a = 0; a < 3; ++a)
            for (int copy = 0; copy < 1 + (k == 39) * 200; ++copy) {
                vec3 c(0.0f);
                c[a] = std::ldexp(1.0f, -k);
                const float w = std::ldexp(1.0f, -k - 7);
                const auto b = std::uint32_t(m.positions.size());
                m.positions.insert(m.positions.end(), {c + vec3(w, w, 0), c - vec3(w, w, 0), c + vec3(w, -w, 0)});
                m.indices.push_back(uvec3(b, b + 1, b + 2));
            }
    const inputs in(m);
    for (lbvh_params p : lbvh_variants()) {
        INFO(to_string(p));
        lbvh_report r;
        const ch04::bvh natural = build_lbvh(in.boxes, in.centroids, p, &r);
        test::check_flat_bvh(natural, in.boxes, in.centroids);
        CHECK(r.rebalanced == 0);
        if (p.bits_per_axis == 21) CHECK(natural.stats.depth >= 50);  // deeper than any median tree here
        p.max_depth = 40;
        const ch04::bvh bounded = build_lbvh(in.boxes, in.centroids, p, &r);
        test::check_flat_bvh(bounded, in.boxes, in.centroids, p.max_leaf, 40);
        CHECK(r.rebalanced >= (p.bits_per_axis == 21 ? 1u : 0u));
        const auto a = make_accel(p);
        a->build(mesh_only(m));
        CHECK(test::disagreements_with_brute_force(*a, m, test::nasty_rays(a->tree(), 200, 3)) == 0);
    }
}

TEST_CASE("ch07 LBVH: the SAH collapse lowers the cost, and the tree is the same on 1 and 2 threads", "[ch07]") {
    const inputs in(teapot_scene(4).mesh);
    for (const lbvh_params& p : lbvh_variants()) {
        INFO(to_string(p));
        lbvh_params single = p;
        single.max_leaf = 1;
        const ch04::bvh collapsed = build_lbvh(in.boxes, in.centroids, p);
        const ch04::bvh singles = build_lbvh(in.boxes, in.centroids, single);
        test::check_flat_bvh(singles, in.boxes, in.centroids, 1);
        CHECK(singles.stats.leaves == in.boxes.size());
        CHECK(collapsed.stats.leaves < in.boxes.size() * 3 / 4);
        CHECK(ch05::tree_cost(collapsed) < ch05::tree_cost(singles));
        // Determinism: the chunks and the bottom-up pass give the same bytes whatever the thread count.
        ch04::bvh one, two;
        {
            const thread_limit limit(1);
            one = build_lbvh(in.boxes, in.centroids, p);
        }
        {
            const thread_limit limit(2);
            two = build_lbvh(in.boxes, in.centroids, p);
        }
        REQUIRE(one.nodes.size() == two.nodes.size());
        CHECK(std::memcmp(one.nodes.data(), two.nodes.data(), one.nodes.size() * sizeof(ch04::bvh_node)) == 0);
        CHECK(first_difference(one.prim_ids, two.prim_ids) == -1);
        // The pdep codes build the same tree.
        lbvh_params pdep = p;
        pdep.use_pdep = true;
        const ch04::bvh with_pdep = build_lbvh(in.boxes, in.centroids, pdep);
        CHECK(first_difference(with_pdep.prim_ids, collapsed.prim_ids) == -1);
        CHECK(with_pdep.nodes.size() == collapsed.nodes.size());
    }
}

TEST_CASE("ch07 LBVH: chapter 05's fast walk over every LBVH equals brute force", "[ch07][adversarial]") {
    std::vector<triangle_mesh> meshes = {teapot_scene(3).mesh, random_soup(1200, 3, 0.1f),
                                         copies(500, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0))};
    triangle_mesh flat = random_soup(400, 5, 0.1f);
    for (vec3& p : flat.positions) p.z = 0.5f;
    meshes.push_back(flat);
    for (const triangle_mesh& m : meshes)
        for (const lbvh_params& p : lbvh_variants()) {
            const auto a = make_accel(p);
            a->build(mesh_only(m));
            INFO(a->name() << " on " << m.triangle_count() << " triangles");
            CHECK(a->tree().stats.depth <= ch04::bvh_max_depth);
            CHECK(test::disagreements_with_brute_force(*a, m, test::nasty_rays(a->tree(), 400, 11)) == 0);
        }
}
