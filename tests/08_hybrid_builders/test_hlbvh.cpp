// Chapter 08's HLBVH (0 points): a valid binary tree on scenes and degenerate inputs (none, one, two and
// three primitives, copies, equal centroids, a far outlier, non-finite vertices) for cluster bits from 0 to
// every bit; with 0 cluster bits it is chapter 07's LBVH; the same tree on 1 and 2 threads; a binary SAH
// cost below the LBVH's; and chapter 05's fast walk over its flattened tree with brute force's answers bit
// for bit.
#include "strahl/ch05/accel.hpp"
#include "strahl/ch07/lbvh.hpp"
#include "strahl/ch08/hlbvh.hpp"
#include "strahl/parallel.hpp"
#include "strahl/procedural.hpp"
#include "bvh_rays.hpp"
#include "exactness.hpp"
#include "flat_bvh_check.hpp"
#include "test_support.hpp"
#include "builder_inputs.hpp"
#include <catch2/catch.hpp>
#include <limits>

using namespace strahl;
using namespace strahl::ch08;

namespace {

using test::hard_meshes;
using test::same_tree;

std::unique_ptr<ch04::bvh_accel_base> hlbvh_accel(const hlbvh_params& p) {
    return ch05::make_bvh_accel(false, "ch08-" + to_string(p) + "-fast", [p](std::span<const aabb> b, std::span<const vec3> c) {
        return flatten(build_hlbvh(b, c, p));
    }, ch05::walk_kind::fast);
}

hlbvh_params with_bits(int bits_per_axis, int cluster_bits) {
    hlbvh_params p;
    p.bits_per_axis = bits_per_axis, p.cluster_bits = cluster_bits;
    return p;
}

}  // namespace

TEST_CASE("ch08 HLBVH: a valid binary tree on scenes and degenerate inputs", "[ch08]") {
    for (const auto& [name, mesh] : hard_meshes()) {
        const ch07::builder_inputs in(mesh);
        std::size_t loose = 0;
        for (std::size_t i = 0; i < in.boxes.size(); ++i) loose += !ch04::fits_in_tree(in.boxes[i], in.centroids[i]);
        for (const hlbvh_params& p : {with_bits(10, 15), with_bits(10, 0), with_bits(10, 30), with_bits(21, 36)}) {
            INFO(name << ", " << to_string(p));
            hlbvh_report r;
            const binary_tree t = build_hlbvh(in.boxes, in.centroids, p, &r);
            CHECK(check_tree(t, in.boxes) == "");
            CHECK(t.leaves() * (t.root != none) + t.loose.size() == in.boxes.size());
            test::check_flat_bvh(flatten(t), in.boxes, in.centroids);
            CHECK(t.loose.size() == loose);
            if (name == "non-finite vertices") CHECK(loose >= 1);
            if (p.cluster_bits == 0) CHECK(r.clusters == (t.root != none));
        }
    }
}

TEST_CASE("ch08 HLBVH: with no cluster bits it is chapter 07's LBVH", "[ch08]") {
    for (const triangle_mesh& m : {builtin_scene("teapot").mesh, random_soup(5000, 8, 0.05f)}) {
        const ch07::builder_inputs in(m);
        const binary_tree h = build_hlbvh(in.boxes, in.centroids, with_bits(10, 0));
        const binary_tree l = lbvh_binary_tree(in.boxes, in.centroids);
        INFO(m.triangle_count() << " triangles");
        CHECK(binary_sah_cost(h) == Approx(binary_sah_cost(l)).epsilon(1e-6));
        CHECK(ch05::tree_cost(flatten(h)) == Approx(ch05::tree_cost(flatten(l))).epsilon(1e-6));
    }
}

TEST_CASE("ch08 HLBVH: the same tree on 1 and 2 threads", "[ch08]") {
    for (const triangle_mesh& m : {builtin_scene("teapot_stadium").mesh, random_soup(20000, 5, 0.02f)}) {
        const ch07::builder_inputs in(m);
        binary_tree one, two;
        hlbvh_report r;
        {
            const thread_limit limit(1);
            one = build_hlbvh(in.boxes, in.centroids, {}, &r);
        }
        {
            const thread_limit limit(2);
            two = build_hlbvh(in.boxes, in.centroids);
        }
        INFO(m.triangle_count() << " triangles, " << r.clusters << " clusters");
        REQUIRE(check_tree(one, in.boxes) == "");
        CHECK(same_tree(one, two));
    }
}

// Measured (release build, 15 cluster bits): the binary SAH cost of HLBVH against chapter 07's LBVH
//   teapot in a stadium  22.80 (1,748 clusters) against 25.64
//   soup (10,000)        79.97 (8,604 clusters) against 86.39
//   bunny                35.21 (3,754 clusters) against 37.90
// 7 to 11% lower; asserted: 3% or more.
TEST_CASE("ch08 HLBVH: the SAH above the clusters prices the tree below the LBVH", "[ch08]") {
    std::vector<std::pair<std::string, triangle_mesh>> meshes = {{"teapot in a stadium", builtin_scene("teapot_stadium").mesh},
                                                                 {"soup", builtin_scene("soup").mesh}};
    const std::filesystem::path bunny = test::shared_scene("bunny.ply");
    if (bunny.empty())
        WARN("skipped the bunny: ../shared/scenes/bunny.ply is not beside this clone");
    else
        meshes.emplace_back("bunny", load_mesh(bunny));
    for (const auto& [name, m] : meshes) {
        const ch07::builder_inputs in(m);
        hlbvh_report r;
        const double hlbvh = binary_sah_cost(build_hlbvh(in.boxes, in.centroids, {}, &r));
        const double lbvh = binary_sah_cost(lbvh_binary_tree(in.boxes, in.centroids));
        WARN(name << ": binary SAH cost, HLBVH (" << r.clusters << " clusters) " << hlbvh << ", LBVH " << lbvh);
        INFO(name);
        CHECK(hlbvh < lbvh * 0.97);
    }
}

TEST_CASE("ch08 HLBVH: chapter 05's fast walk over the flattened tree equals brute force", "[ch08][adversarial]") {
    // The bunny with fewer rays: brute force over its 69,451 triangles costs 1.5 s per 1000 rays here.
    const auto meshes = test::exactness_meshes();
    for (const auto& [name, m] : meshes) {
        const auto a = hlbvh_accel({});
        a->build(test::mesh_only(m));
        INFO(a->name() << " on " << name);
        CHECK(test::disagreements_with_brute_force(*a, m, test::nasty_rays(a->tree(), name == "bunny" ? 600 : 2000, 22)) == 0);
    }
}
