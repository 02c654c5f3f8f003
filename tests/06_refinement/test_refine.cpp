// Chapter 06 beyond the exercises (0 points): refinement never raises the SAH cost and lowers it on a
// median tree; the refined tree keeps every invariant of chapter 04's (boxes contain their children, each
// primitive in one leaf, at most 2N - 1 nodes, bounded depth); and it gives brute force's answers bit for
// bit on scenes and rays made to break it.
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch06/accel.hpp"
#include "strahl/procedural.hpp"
#include "bvh_rays.hpp"
#include "exactness.hpp"
#include "hand_trees.hpp"
#include <algorithm>
#include <catch2/catch.hpp>
#include <numeric>
#include <string>

using namespace strahl;
using namespace strahl::ch06;

using test::copies;
using test::mesh_only;
using test::nasty_rays;

namespace {

struct inputs {
    std::vector<aabb> boxes;
    std::vector<vec3> centroids;
};
inputs boxes_of(const triangle_mesh& m) {
    const ch01::triangle_set tris(m);
    inputs in;
    for (std::uint32_t i = 0; i < tris.size(); ++i) in.boxes.push_back(tris.bounds(i)), in.centroids.push_back(in.boxes.back().centroid());
    return in;
}

bool contains(const aabb& outer, const aabb& inner) {
    return glm::all(glm::lessThanEqual(outer.min, inner.min)) && glm::all(glm::greaterThanEqual(outer.max, inner.max));
}

// Returns the depth below index; checks boxes and counts on the way.
int check_node(const ch04::bvh& t, std::uint32_t i, const std::vector<aabb>& boxes, std::vector<int>& seen) {
    const ch04::bvh_node& n = t.nodes[i];
    const aabb b = n.box();
    if (n.is_leaf()) {
        for (std::uint32_t k = n.offset; k < n.offset + n.count; ++k) {
            INFO("leaf node " << i << "'s box against its primitive " << t.prim_ids[k] << "'s (prim_ids[" << k << "])");
            CHECK(contains(b, boxes[t.prim_ids[k]]));
            ++seen[t.prim_ids[k]];
        }
        return 0;
    }
    {
        INFO("inner node " << i << ", children nodes " << i + 1 << " and " << n.offset);
        CHECK(n.axis < 3);
        CHECK(contains(b, t.nodes[i + 1].box()));
        CHECK(contains(b, t.nodes[n.offset].box()));
    }
    return 1 + std::max(check_node(t, i + 1, boxes, seen), check_node(t, n.offset, boxes, seen));
}

// The invariants of chapter 04's flat tree, after refinement.
void check_structure(const ch04::bvh& t, const inputs& in, int max_depth) {
    const std::size_t n = t.prim_ids.size();
    CHECK(t.stats.primitives == in.boxes.size());
    CHECK(n + t.loose.size() == in.boxes.size());
    if (n == 0) {
        CHECK(t.nodes.empty());
        return;
    }
    CHECK(t.nodes.size() <= 2 * n - 1);
    CHECK(t.nodes.size() == t.stats.inner + t.stats.leaves);
    CHECK(t.stats.leaves == t.stats.inner + 1);
    std::vector<int> seen(in.boxes.size(), 0);
    const int depth = check_node(t, 0, in.boxes, seen);
    CHECK(depth == t.stats.depth);
    CHECK(depth <= max_depth);
    CHECK(test::same_box(t.bounds, t.nodes[0].box()));
    for (const std::uint32_t l : t.loose) ++seen[l];
    const auto odd = std::find_if(seen.begin(), seen.end(), [](int s) { return s != 1; });
    INFO("every primitive in exactly one leaf or loose; the first that is not: "
         << (odd == seen.end() ? std::string("none") : "primitive " + std::to_string(odd - seen.begin()) + ", seen " +
                                                           std::to_string(*odd) + " times"));
    CHECK(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
}

// Every refinement of both start trees; returns the costs before and after per combination.
void check_refinement(const triangle_mesh& m, bool must_improve_median) {
    const inputs in = boxes_of(m);
    for (const start_tree s : {start_tree::median, start_tree::binned16})
        for (const refine_method meth : {refine_method::rotations, refine_method::reinsertion}) {
            ch04::bvh t = s == start_tree::median ? ch04::build_bvh(in.boxes, in.centroids)
                                                  : ch05::build_sah_bvh(in.boxes, in.centroids);
            refine_params p;
            p.method = meth;
            const refine_stats st = refine(t, p);
            INFO(to_string(s) << " " << to_string(meth) << ": " << st.before << " -> " << st.after << ", "
                              << st.moves << " moves in " << st.iterations << " iterations");
            CHECK(st.after <= st.before);
            CHECK(ch05::tree_cost(t) == Approx(st.after));
            if (must_improve_median && s == start_tree::median) {
                CHECK(st.after < st.before);
                CHECK(st.moves > 0);
            }
            CHECK(st.iterations <= p.max_iterations);
            check_structure(t, in, ch04::bvh_max_depth);
        }
}

void check_exact(const scene& s, std::size_t n_rays) {
    for (const start_tree st : {start_tree::median, start_tree::binned16})
        for (const refine_method m : {refine_method::rotations, refine_method::reinsertion})
            for (const bool is_virtual : {false, true}) {
                refine_params p;
                p.start = st;
                p.method = m;
                const auto a = make_accel(is_virtual, p);
                a->build(s);
                INFO(a->name() << " on " << s.mesh.triangle_count() << " triangles");
                const ch04::bvh& t = a->tree();
                CHECK(t.nodes.size() <= std::max<std::size_t>(1, 2 * t.prim_ids.size()) - 1);
                CHECK(t.stats.depth <= ch04::bvh_max_depth);
                CHECK(test::disagreements_with_brute_force(*a, s.mesh, nasty_rays(t, n_rays, 11)) == 0);
            }
}

}  // namespace

TEST_CASE("ch06 refinement: the index form round-trips a tree unchanged in cost and shape", "[ch06]") {
    const inputs in = boxes_of(teapot_scene(4).mesh);
    const ch04::bvh t = ch04::build_bvh(in.boxes, in.centroids);
    const ch04::bvh back = to_bvh(to_refine_tree(t), t);
    CHECK(back.nodes.size() == t.nodes.size());
    CHECK(back.stats.depth == t.stats.depth);
    CHECK(back.stats.leaves == t.stats.leaves);
    CHECK(back.stats.max_leaf == t.stats.max_leaf);
    CHECK(ch05::tree_cost(back) == Approx(ch05::tree_cost(t)).epsilon(1e-12));
    check_structure(back, in, ch04::bvh_max_depth);
}

TEST_CASE("ch06 refinement: never raises the SAH cost, lowers it on the teapot's median tree", "[ch06]") {
    check_refinement(teapot_scene(4).mesh, true);
    check_refinement(random_soup(2000, 3, 0.1f), true);
}

TEST_CASE("ch06 refinement: rotations beat nothing, reinsertion beats rotations on the median tree", "[ch06]") {
    const inputs in = boxes_of(teapot_scene(4).mesh);
    const ch04::bvh start = ch04::build_bvh(in.boxes, in.centroids);
    ch04::bvh rotated = start, reinserted = start;
    refine_params p;
    const refine_stats r = refine(rotated, p);
    p.method = refine_method::reinsertion;
    const refine_stats i = refine(reinserted, p);
    CHECK(r.after < r.before);
    CHECK(i.after < r.after);
}

TEST_CASE("ch06 refinement: the depth bound holds when it is tight", "[ch06]") {
    const inputs in = boxes_of(teapot_scene(4).mesh);
    for (const refine_method m : {refine_method::rotations, refine_method::reinsertion}) {
        ch04::bvh t = ch04::build_bvh(in.boxes, in.centroids);
        const int depth = t.stats.depth;
        INFO(to_string(m) << " on the teapot's median tree, max_depth " << depth + 1 << " (its depth + 1)");
        refine_params p;
        p.method = m;
        p.max_depth = depth + 1;
        const refine_stats st = refine(t, p);
        CHECK(st.after < st.before);
        CHECK(t.stats.depth <= depth + 1);
        check_structure(t, in, depth + 1);
    }
}

TEST_CASE("ch06 refinement: degenerate input terminates and keeps the structure", "[ch06][adversarial]") {
    // All centroids equal (every box the same): no move lowers the cost.
    check_refinement(copies(3000, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)), false);
    triangle_mesh flat = random_soup(800, 5, 0.1f);
    for (vec3& v : flat.positions) v.z = 0.5f;  // every box flat
    check_refinement(flat, false);
    check_refinement(copies(1, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)), false);
    check_refinement(copies(2, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)), false);
    check_refinement(triangle_mesh{}, false);
}

TEST_CASE("ch06 refined BVHs: both primitive sets equal brute force on the teapot", "[ch06][adversarial]") {
    check_exact(teapot_scene(4), 800);
}

TEST_CASE("ch06 refined BVHs: a random soup and all triangles in one place", "[ch06][adversarial]") {
    check_exact(mesh_only(random_soup(1500, 3, 0.1f)), 800);
    triangle_mesh clump = random_soup(400, 4, 0.01f);
    for (vec3& p : clump.positions) p = 0.001f * p;
    check_exact(mesh_only(clump), 500);
}

TEST_CASE("ch06 refined BVHs: identical triangles, a planar scene, one triangle, an empty scene",
          "[ch06][adversarial]") {
    check_exact(mesh_only(copies(1000, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0))), 150);
    triangle_mesh flat = random_soup(800, 5, 0.1f);
    for (vec3& p : flat.positions) p.z = 0.5f;
    check_exact(mesh_only(flat), 500);
    check_exact(mesh_only(copies(1, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0))), 300);
    check_exact(mesh_only(triangle_mesh{}), 100);
}
