// Chapter 08's base (0 points): the index-form binary tree's check finds what is wrong; chapter 07's LBVH
// before its collapse is a valid binary tree; FLATTEN writes a valid chapter 04 tree (each primitive once,
// tight boxes, leaves within max_leaf, the depth bound kept by halving a chain deeper than it), whose SAH
// collapse prices no higher than the binary tree, and which chapter 05's fast walk traverses with brute
// force's answers bit for bit.
#include "strahl/ch05/accel.hpp"
#include "strahl/ch07/lbvh.hpp"
#include "strahl/ch08/binary_tree.hpp"
#include "strahl/procedural.hpp"
#include "bvh_rays.hpp"
#include "exactness.hpp"
#include "flat_bvh_check.hpp"
#include <catch2/catch.hpp>
#include <limits>

using namespace strahl;
using namespace strahl::ch08;

namespace {

// A chain: primitive k's leaf hangs beside the subtree of all primitives after it (depth n - 1).
binary_tree chain(std::span<const aabb> boxes) {
    binary_tree t;
    const auto n = std::uint32_t(boxes.size());
    for (std::uint32_t k = 0; k < n; ++k) {
        tree_node leaf;
        leaf.box = boxes[k], leaf.prim = k;
        t.nodes.push_back(leaf);
    }
    std::uint32_t below = n - 1;
    for (std::uint32_t k = n - 1; k-- > 0;) {
        tree_node in;
        in.left = k, in.right = below;
        in.box = unite(t.nodes[k].box, t.nodes[below].box);
        t.nodes.push_back(in);
        const auto index = std::uint32_t(t.nodes.size() - 1);
        t.nodes[k].parent = t.nodes[below].parent = index;
        below = index;
    }
    t.root = below;
    return t;
}

std::unique_ptr<ch04::bvh_accel_base> lbvh_flattened() {
    return ch05::make_bvh_accel(false, "ch08-lbvh-flattened", [](std::span<const aabb> b, std::span<const vec3> c) {
        return flatten(lbvh_binary_tree(b, c));
    }, ch05::walk_kind::fast);
}

}  // namespace

TEST_CASE("ch08 binary tree: chapter 07's LBVH is a valid binary tree, and the check finds broken ones", "[ch08]") {
    for (const triangle_mesh& m : {teapot_scene(3).mesh, random_soup(3000, 4, 0.05f), triangle_mesh{},
                                   test::copies(1, vec3(0), vec3(1, 0, 0), vec3(0, 1, 0)),
                                   test::copies(700, vec3(0), vec3(1, 0, 0), vec3(0, 1, 0))}) {
        const ch07::builder_inputs in(m);
        const binary_tree t = lbvh_binary_tree(in.boxes, in.centroids);
        INFO(m.triangle_count() << " triangles");
        CHECK(check_tree(t, in.boxes) == "");
        CHECK(t.leaves() * (t.root != none) == in.boxes.size());
    }
    const ch07::builder_inputs in(random_soup(50, 2, 0.1f));
    binary_tree t = lbvh_binary_tree(in.boxes, in.centroids);
    REQUIRE(check_tree(t, in.boxes) == "");
    binary_tree wrong_box = t;
    wrong_box.nodes[t.root].box.max.x += 1.0f;
    CHECK(check_tree(wrong_box, in.boxes).find("union") != std::string::npos);
    binary_tree twice = t;
    twice.nodes[0].prim = twice.nodes[1].prim;
    CHECK(check_tree(twice, in.boxes) != "");
    binary_tree orphan = t;
    const std::uint32_t child = orphan.nodes[orphan.root].left;
    orphan.nodes[child].parent = child;
    CHECK(check_tree(orphan, in.boxes).find("parent") != std::string::npos);
    // refit repairs boxes that no longer hold their children's.
    binary_tree stale = t;
    for (tree_node& n : stale.nodes)
        if (!n.is_leaf()) n.box = aabb{};
    refit(stale);
    CHECK(check_tree(stale, in.boxes) == "");
}

TEST_CASE("ch08 FLATTEN: a valid flat tree, the collapse no dearer, the depth bound kept", "[ch08]") {
    const ch07::builder_inputs in(random_soup(5000, 9, 0.05f));
    const binary_tree t = lbvh_binary_tree(in.boxes, in.centroids);
    for (const int max_leaf : {1, 4, 8}) {
        flatten_params p;
        p.max_leaf = max_leaf;
        const ch04::bvh flat = flatten(t, p);
        INFO("max_leaf " << max_leaf);
        test::check_flat_bvh(flat, in.boxes, in.centroids, max_leaf);
        // The collapse only merges where the SAH prices a leaf no higher: the flat tree costs at most the
        // binary tree (the same constants, normalised by the same root box).
        CHECK(ch05::tree_cost(flat) <= binary_sah_cost(t) * (1.0 + 1e-5));
        if (max_leaf == 1) CHECK(ch05::tree_cost(flat) == Approx(binary_sah_cost(t)).epsilon(1e-5));
    }
    // A chain of 300 primitives is 299 levels deep: written from depth 50 by halving, it stays within the bound.
    const ch07::builder_inputs line(random_soup(300, 3, 0.05f));
    const binary_tree deep = chain(line.boxes);
    REQUIRE(check_tree(deep, line.boxes) == "");
    const ch04::bvh bounded = flatten(deep);
    test::check_flat_bvh(bounded, line.boxes, line.centroids, 4, ch04::bvh_max_depth);
    CHECK(bounded.stats.depth <= ch04::bvh_max_depth);
    // Non-finite primitives stay loose.
    triangle_mesh odd = random_soup(200, 5, 0.1f);
    odd.positions[3].y = std::numeric_limits<float>::infinity();
    const ch07::builder_inputs o(odd);
    const binary_tree with_loose = lbvh_binary_tree(o.boxes, o.centroids);
    CHECK(check_tree(with_loose, o.boxes) == "");
    CHECK(with_loose.loose.size() == 1);
    test::check_flat_bvh(flatten(with_loose), o.boxes, o.centroids);
}

TEST_CASE("ch08 FLATTEN: chapter 05's fast walk over the flattened LBVH equals brute force", "[ch08][adversarial]") {
    triangle_mesh flat = random_soup(400, 5, 0.1f);
    for (vec3& p : flat.positions) p.z = 0.5f;
    for (const triangle_mesh& m : {teapot_scene(3).mesh, random_soup(1200, 3, 0.1f), flat,
                                   test::copies(300, vec3(0), vec3(1, 0, 0), vec3(0, 1, 0))}) {
        const auto a = lbvh_flattened();
        a->build(test::mesh_only(m));
        INFO(m.triangle_count() << " triangles");
        CHECK(test::disagreements_with_brute_force(*a, m, test::nasty_rays(a->tree(), 400, 12)) == 0);
    }
}
