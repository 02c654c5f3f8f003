// Front-to-back traversal of the k-d tree with the t-split rule and a small fixed stack (V. Havran,
// "Heuristic Ray Shooting Algorithms", PhD thesis, 2000, the "recursive" TA_B variant; Wald and Havran 2006).
// Traversal is separate from intersection: it is handed the leaf test.
#pragma once
#include "strahl/tree_query.hpp"
#include "strahl/ch03/kd_tree.hpp"
#include "strahl/ray.hpp"
#include <algorithm>

namespace strahl::ch03 {

// Which children of an inner node a ray segment [t0, t1] enters, in the order it enters them.
// child[k] is 0 (left, below the plane) or 1 (right); [t0[k], t1[k]] is the segment's part in child[k].
struct child_visit {
    int count = 0;
    std::uint8_t child[2] = {0, 0};
    float t0[2] = {0.0f, 0.0f};
    float t1[2] = {0.0f, 0.0f};
};

// Exercise 03.3 "near/far and t-split": for the ray's segment [t0, t1] inside a node split at `split` on
// `axis`, which children it visits and with which t-ranges (inv_dir = 1 / r.dir). `slack` widens the split:
// the near child's range ends at t_split + slack and the far child's starts at t_split - slack, so that a
// hit whose computed t lies a rounding error beyond the plane is still found.
child_visit near_far(const ray& r, const vec3& inv_dir, int axis, float split, float t0, float t1, float slack);

// The root box clip: the ray's parametric range inside the tree's box, widened by the slack, clamped to
// (tmin, tmax); false when it misses. Direction components of +-0 are handled without 0 * inf.
bool clip_to_box(const ray& r, const vec3& inv_dir, const aabb& box, float slack, float& t0, float& t1);

// (The slack of a ray, ray_slack, is strahl/tree_query.hpp's, shared with every tree.)

// near_far with the split plane widened in space by `grow` (space_slack): a ray within grow of the plane
// may hit triangles on both sides through the triangle test's rounding. A ray parallel to the plane that
// close visits both children; any other gets at least grow / |d| of t-slack on this axis.
inline child_visit split_visit(const ray& r, const vec3& inv_dir, int axis, float split, float t0, float t1,
                               float slack, float grow) {
    if (r.dir[axis] == 0.0f && std::abs(r.org[axis] - split) <= grow) {
        child_visit v;
        if (!(t0 <= t1)) return v;
        for (std::uint8_t c = 0; c < 2; ++c) v.child[v.count] = c, v.t0[v.count] = t0, v.t1[v.count] = t1, ++v.count;
        return v;
    }
    return near_far(r, inv_dir, axis, split, t0, t1, std::max(slack, grow * std::abs(inv_dir[axis])));
}

// Visits the leaves the ray's segment enters, front to back. leaf(first, count, t0, t1) tests the leaf's
// references and returns true to stop (any hit). A closest-hit leaf test shrinks r.tmax (record_closest);
// a node whose range starts beyond r.tmax is skipped, so traversal stops only when no farther node can
// hold a closer hit (or an equal one with a lower id): the cell-exit rule.
template <class Stats, class LeafTest>
void traverse(const kd_tree& tree, ray& r, Stats& stats, LeafTest&& leaf) {
    if (tree.nodes.empty()) return;
    const vec3 inv_dir = 1.0f / r.dir;
    const float slack = ray_slack(r, tree.bounds), grow = space_slack(r, tree.bounds);
    float t0, t1;
    stats.box_test();
    if (!clip_to_box(r, inv_dir, grown(tree.bounds, grow), slack, t0, t1)) return;
    struct entry { std::uint32_t node; float t0, t1; };
    entry stack[kd_max_depth + 2];
    int top = 0;
    std::uint32_t node = 0;
    for (;;) {
        // Step 1, the cell-exit rule: skip a node that starts beyond the best hit so far.
        if (t0 < r.tmax) {
            const kd_node& n = tree.nodes[node];
            stats.node_visit();
            if (n.is_leaf()) {
                if (leaf(n.first(), n.count, t0, t1)) return;
            } else {
                // Step 2, the t-split rule: near child first, far child onto the stack.
                const child_visit v = split_visit(r, inv_dir, n.axis(), n.split, t0, std::min(t1, r.tmax), slack, grow);
                if (v.count > 0) {
                    if (v.count == 2) stack[top++] = {n.left() + v.child[1], v.t0[1], v.t1[1]};
                    node = n.left() + v.child[0];
                    t0 = v.t0[0];
                    t1 = v.t1[0];
                    continue;
                }
            }
        }
        if (top == 0) return;
        --top;
        node = stack[top].node;
        t0 = stack[top].t0;
        t1 = stack[top].t1;
    }
}

}  // namespace strahl::ch03
