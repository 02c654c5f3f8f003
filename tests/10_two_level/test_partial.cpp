// The partial rebuild (refit.hpp): after a refit, the worst subtrees of the cut rebuilt in place leave a
// valid tree (chapter 04's invariants, tight boxes, every triangle once), cheaper than the refit tree, with
// its baseline costs kept in step; repeated, it rebuilds other subtrees; degenerate parameters do nothing.
#include "flat_bvh_check.hpp"
#include "strahl/ch05/sah.hpp"
#include "mesh_boxes.hpp"
#include "strahl/ch10/refit.hpp"
#include "strahl/procedural.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

using namespace strahl;
using namespace strahl::ch10;
using test::boxes_of;
using test::centroids_of;

namespace {
ch04::bvh binned(std::span<const aabb> b, std::span<const vec3> c) { return ch05::build_sah_bvh_fast(b, c); }

// The boxes' tree refit by hand (the solution's refit may not be compiled in: this test has no points).
void refit_by_hand(ch04::bvh& t, std::span<const aabb> boxes) {
    for (std::size_t i = t.nodes.size(); i-- > 0;) {
        ch04::bvh_node& n = t.nodes[i];
        aabb box;
        if (n.is_leaf())
            for (std::uint32_t k = 0; k < n.count; ++k) box.grow(boxes[t.prim_ids[n.offset + k]]);
        else
            box = unite(t.nodes[i + 1].box(), t.nodes[n.offset].box());
        for (int a = 0; a < 3; ++a) n.bmin[a] = box.min[a], n.bmax[a] = box.max[a];
    }
    t.bounds = t.nodes[0].box();
}
}  // namespace

TEST_CASE("ch10 partial rebuild: a valid, cheaper tree, the baseline kept in step, other subtrees next time", "[ch10]") {
    triangle_mesh m = teapot_mesh(8);
    const std::vector<aabb> start = boxes_of(m);
    ch04::bvh t = binned(start, centroids_of(start));
    std::vector<float> baseline = subtree_costs(t);
    for (vec3& p : m.positions) p = vec3(p.x + 0.6f * std::sin(3.0f * p.y), p.y, p.z + 0.6f * std::cos(2.0f * p.x));
    const std::vector<aabb> moved = boxes_of(m);
    refit_by_hand(t, moved);
    const double refit_cost = ch05::tree_cost(t);
    partial_params params;
    params.cut_fraction = 1.0f / 16.0f, params.subtrees = 3;
    const partial_result r = partial_rebuild(t, baseline, moved, binned, params);
    CHECK(r.rebuilt == 3);
    CHECK_FALSE(r.full);
    CHECK(r.primitives > 0);
    CHECK(r.primitives <= 3 * moved.size() / 16);
    test::check_flat_bvh(t, moved, centroids_of(moved), 8);
    CHECK(baseline.size() == t.nodes.size());
    const double partial_cost = ch05::tree_cost(t);
    CHECK(partial_cost < refit_cost);
    // The baseline of every node equals its cost now only where it was rebuilt: the rebuilt nodes' growth is 0.
    const std::vector<float> now = subtree_costs(t);
    std::size_t fresh = 0;
    for (std::size_t i = 0; i < now.size(); ++i) fresh += now[i] == baseline[i];
    CHECK(fresh >= 3);
    // Again: the rebuilt subtrees have grown least now, so others are chosen, and the cost falls further.
    const partial_result again = partial_rebuild(t, baseline, moved, binned, params);
    CHECK(again.rebuilt == 3);
    test::check_flat_bvh(t, moved, centroids_of(moved), 8);
    CHECK(ch05::tree_cost(t) < partial_cost);
}

TEST_CASE("ch10 partial rebuild: no subtrees, a NaN fraction, a mismatched baseline: nothing changes", "[ch10]") {
    const triangle_mesh m = teapot_mesh(4);
    const std::vector<aabb> b = boxes_of(m);
    ch04::bvh t = binned(b, centroids_of(b));
    const std::size_t nodes = t.nodes.size();
    std::vector<float> baseline = subtree_costs(t);
    partial_params none;
    none.subtrees = 0;
    CHECK(partial_rebuild(t, baseline, b, binned, none).rebuilt == 0);
    partial_params nan;
    nan.cut_fraction = std::numeric_limits<float>::quiet_NaN();
    const partial_result r = partial_rebuild(t, baseline, b, binned, nan);  // a cut of 2: small subtrees
    test::check_flat_bvh(t, b, centroids_of(b), 8);
    CHECK(r.primitives <= 4 * 2);
    std::vector<float> wrong(3);
    CHECK(partial_rebuild(t, wrong, b, binned).rebuilt == 0);
    CHECK(t.nodes.size() >= nodes / 2);
}
