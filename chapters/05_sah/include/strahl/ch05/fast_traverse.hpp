// A faster scalar traversal of chapter 04's flat BVH: the one chapter 05's speed figures against Embree
// are measured with. Same nodes, same leaf test, same answers; three changes to chapter 04's loop:
//   1. both children's boxes are tested at their parent, and the nearer child (by entry distance, not by
//      the split axis's sign) is visited first; a child whose box the ray misses is never fetched;
//   2. the far child goes on the stack with its entry distance, and is dropped when popped if a hit found
//      since lies before it;
//   3. the slab test is inline and branch-free (slab_test.hpp): the near and far planes per axis are chosen
//      once per ray from the direction's signs, so no swap and no NaN test per box; and where the ray allows
//      it a plane's t is one multiply and one subtract, its rounding bounded once per ray, not per box.
//   T. L. Kay and J. T. Kajiya, "Ray tracing complex scenes", SIGGRAPH 1986 (slabs);
//   T. Aila and S. Laine, "Understanding the efficiency of ray traversal on GPUs", HPG 2009 (children
//   tested at the parent, distance-ordered).
#pragma once
#include "strahl/ch04/traverse.hpp"
#include "strahl/ch05/slab_test.hpp"
#include "strahl/tree_query.hpp"
#include <cmath>
#include <optional>

namespace strahl::ch05 {

// The walk with either slab test (slab_test.hpp): s.entry(node, t0, t1) is the node box's entry distance
// for t in [t0, t1], or +inf for a miss.
template <class Slab, class Stats, class LeafTest>
void walk_with(const ch04::bvh& tree, const Slab& s, float slack, ray& r, Stats& stats, LeafTest&& leaf) {
    static_assert(offsetof(ch04::bvh_node, bmax) == 3 * sizeof(float), "bmin and bmax are adjacent");
    const ch04::bvh_node* nodes = tree.nodes.data();
    struct entry {
        std::uint32_t index;
        float t;
    };
    entry stack[ch04::bvh_max_depth + 2];
    int top = 0;
    stats.box_test();
    if (s.entry(nodes[0], r.tmin - slack, r.tmax + slack) == inf) return;
    std::uint32_t index = 0;
    for (;;) {
        const ch04::bvh_node& n = nodes[index];
        stats.node_visit();
        if (n.is_leaf()) {
            // The leaf: its primitives, through the set's test.
            if (leaf(n.offset, std::uint32_t(n.count))) return;
        } else {
            // Both children's boxes, here at the parent.
            const std::uint32_t left = index + 1, right = n.offset;
            const float lo = r.tmin - slack, hi = r.tmax + slack;
            const float t_left = s.entry(nodes[left], lo, hi);
            const float t_right = s.entry(nodes[right], lo, hi);
            stats.box_test(2);
            if (t_left != inf && t_right != inf) {
                // Both: the nearer now, the farther on the stack with its entry distance.
                const bool left_first = t_left <= t_right;
                stack[top++] = left_first ? entry{right, t_right} : entry{left, t_left};
                index = left_first ? left : right;
                continue;
            }
            if (t_left != inf || t_right != inf) {
                index = t_left != inf ? left : right;
                continue;
            }
        }
        // Pop the next far child whose entry still lies within the (shrunk) range.
        for (;;) {
            if (top == 0) return;
            const entry e = stack[--top];
            if (e.t <= r.tmax + slack) {
                index = e.index;
                break;
            }
        }
    }
}

// Visits the leaves whose boxes the ray meets, nearer child first; leaf(first, count) as in chapter 04. The
// fast slab test where the ray allows it, else the robust one on grown boxes: both conservative, so the
// answers are the same.
template <class Stats, class LeafTest>
void fast_traverse(const ch04::bvh& tree, ray& r, Stats& stats, LeafTest&& leaf) {
    if (tree.nodes.empty()) return;
    const float slack = ray_slack(r, tree.bounds);
    if (const std::optional<fast_slab> s = fast_slab::make(r, tree.bounds))
        walk_with(tree, *s, slack, r, stats, leaf);
    else
        walk_with(tree, robust_slab(r, space_slack(r, tree.bounds)), slack, r, stats, leaf);
}

// fast_traverse as chapter 04's bvh_accel_t's Walk.
struct fast_walk {
    template <class Stats, class Leaf>
    void operator()(const ch04::bvh& tree, ray& r, Stats& stats, Leaf&& leaf) const {
        fast_traverse(tree, r, stats, leaf);
    }
};

}  // namespace strahl::ch05
