// Near-first, stack-based traversal of the flattened BVH, and the robust slab test it runs at every node.
//   T. L. Kay and J. T. Kajiya, "Ray tracing complex scenes", SIGGRAPH 1986 (the slab test);
//   M. Pharr, W. Jakob and G. Humphreys, pbrt-v4, 2023, sections 6.8 and 7.3 (the conservative slab test
//   with gamma(3), the ordered traversal over a flat node array).
// Traversal is separate from intersection: it is handed the leaf test.
#pragma once
#include "strahl/tree_query.hpp"
#include "strahl/ch04/bvh.hpp"
#include "strahl/function_ref.hpp"
#include "strahl/ray.hpp"
#include <limits>

namespace strahl::ch04 {

// pbrt's gamma(n) = n u / (1 - n u), u = 2^-24 the unit roundoff: a bound on the relative error of n
// floating-point operations.
constexpr float gamma(int n) {
    constexpr float u = std::numeric_limits<float>::epsilon() * 0.5f;
    return float(n) * u / (1.0f - float(n) * u);
}

// Exercise 04.1 "slab test": whether the ray org + t d (inv_dir = 1 / d, componentwise) meets box for some
// t in [tmin, tmax], conservatively: per axis, the slab's entry and exit t, ordered; the exit widened away
// from zero by the factor 1 +- 2 gamma(3) (so that rounding never loses a box the ray touches); then
// entry = max(tmin, entries), exit = min(tmax, exits), hit iff entry <= exit. A direction component of +0
// or -0 gives inv_dir = +inf or -inf: the slab's t are then +-inf (the ray runs beside the slab, inside or
// outside it), or NaN where the origin lies exactly on the slab's plane (0 * inf); such an axis is skipped
// (the ray runs in the plane: inside the closed slab for every t). Boxes are closed: touching a face counts.
bool slab_test(const aabb& box, const vec3& org, const vec3& inv_dir, float tmin, float tmax);

// Exercise 04.3 "near-first traversal": walks the flat tree from the root with a stack, and returns the
// number of nodes visited (each one box test). At each node, box_hit(node) says whether the ray still meets
// its box; if not, the node is skipped. A leaf is handed to leaf(offset, count), its range of prim_ids; a
// true answer ends the walk at once (any hit). An inner node's children are taken near child first: the
// left one (index + 1) first when dir's component on the node's axis has its sign bit clear (+0
// included), the right one (offset) first when it is set (-0 included); the far child waits on the stack.
// An empty tree visits nothing. The box test and the leaf test are the caller's: traversal only orders.
using box_hit_test = function_ref<bool(const bvh_node& node)>;
using leaf_visit = function_ref<bool(std::uint32_t first, std::uint32_t count)>;
std::uint32_t near_first_traversal(const bvh& tree, const vec3& dir, box_hit_test box_hit, leaf_visit leaf);

// Boxes are tested against [tmin - slack, tmax + slack], with ray_slack (strahl/tree_query.hpp): a
// triangle test's t carries its own rounding error, which the box's t need not share. And each box is
// grown by space_slack: its u and v carry one too, so a ray passing just beside a box can hit inside it.

// Visits the leaves whose boxes the ray meets, near child first. leaf(first, count) tests prim_ids
// [first, first + count) and returns true to stop (any hit). A closest-hit leaf test shrinks r.tmax to
// just above the best t (record_closest), so later boxes entered beyond it are skipped (the box test reads
// r.tmax as it is when the node comes up), while a box whose entry equals the best t is still visited: a
// tie there may hold a lower id.
template <class Stats, class LeafTest>
void traverse(const bvh& tree, ray& r, Stats& stats, LeafTest&& leaf) {
    if (tree.nodes.empty()) return;
    const vec3 inv_dir = 1.0f / r.dir;
    const float slack = ray_slack(r, tree.bounds), grow = space_slack(r, tree.bounds);
    // The box: the (widened) segment against the (grown) box, with r.tmax as the leaves have left it.
    const auto box_hit = [&](const bvh_node& n) {
        return slab_test(grown(n.box(), grow), r.org, inv_dir, r.tmin - slack, r.tmax + slack);
    };
    const std::uint32_t visited = near_first_traversal(tree, r.dir, box_hit, leaf);
    stats.node_visit(visited);
    stats.box_test(visited);
}

}  // namespace strahl::ch04
