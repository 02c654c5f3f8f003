// Near-first, stack-based traversal of the flattened BVH, and the robust slab test it runs at every node.
//   T. L. Kay and J. T. Kajiya, "Ray tracing complex scenes", SIGGRAPH 1986 (the slab test);
//   M. Pharr, W. Jakob and G. Humphreys, pbrt-v4, 2023, sections 6.8 and 7.3 (the conservative slab test
//   with gamma(3), the ordered traversal over a flat node array).
// Traversal is separate from intersection: it is handed the leaf test.
#pragma once
#include "strahl/tree_query.hpp"
#include "strahl/ch04/bvh.hpp"
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

// Exercise 04.3 "near child first": the two children of the inner node `node` at index `index`, in the
// order the ray with direction dir visits them: the left child (index + 1) first when the direction's
// component on the node's axis has its sign bit clear (+0 included), the right child (node.offset) first
// when it is set (-0 included). The far child waits on the stack.
struct child_order {
    std::uint32_t near, far;
};
child_order ordered_children(std::uint32_t index, const bvh_node& node, const vec3& dir);

// Boxes are tested against [tmin - slack, tmax + slack], with ray_slack (strahl/tree_query.hpp): a
// triangle test's t carries its own rounding error, which the box's t need not share. And each box is
// grown by space_slack: its u and v carry one too, so a ray passing just beside a box can hit inside it.

// Visits the leaves whose boxes the ray meets, near child first. leaf(first, count) tests prim_ids
// [first, first + count) and returns true to stop (any hit). A closest-hit leaf test shrinks r.tmax to
// just above the best t (record_closest), so later boxes entered beyond it are skipped, while a box whose
// entry equals the best t is still visited: a tie there may hold a lower id.
template <class Stats, class LeafTest>
void traverse(const bvh& tree, ray& r, Stats& stats, LeafTest&& leaf) {
    if (tree.nodes.empty()) return;
    const vec3 inv_dir = 1.0f / r.dir;
    const float slack = ray_slack(r, tree.bounds), grow = space_slack(r, tree.bounds);
    std::uint32_t stack[bvh_max_depth + 2];
    int top = 0;
    std::uint32_t index = 0;
    for (;;) {
        const bvh_node& n = tree.nodes[index];
        stats.node_visit();
        stats.box_test();
        // Step 1, the box: skip the node unless the (widened) segment meets the (grown) box.
        if (slab_test(grown(n.box(), grow), r.org, inv_dir, r.tmin - slack, r.tmax + slack)) {
            if (n.is_leaf()) {
                // Step 2, the leaf: its primitives, through the set's test.
                if (leaf(n.offset, std::uint32_t(n.count))) return;
            } else {
                // Step 3, near child first: descend into it, the far child onto the stack.
                const child_order c = ordered_children(index, n, r.dir);
                stack[top++] = c.far;
                index = c.near;
                continue;
            }
        }
        if (top == 0) return;
        index = stack[--top];
    }
}

}  // namespace strahl::ch04
