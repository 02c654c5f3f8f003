// A faster scalar traversal of chapter 04's flat BVH: the one chapter 05's speed figures against Embree
// are measured with. Same nodes, same leaf test, same answers; three changes to chapter 04's loop:
//   1. both children's boxes are tested at their parent, and the nearer child (by entry distance, not by
//      the split axis's sign) is visited first; a child whose box the ray misses is never fetched;
//   2. the far child goes on the stack with its entry distance, and is dropped when popped if a hit found
//      since lies before it;
//   3. the slab test is inline and branch-free: the near and far planes per axis are chosen once per ray
//      from the direction's signs (the ray's octant), so no swap and no NaN test per box.
//   T. L. Kay and J. T. Kajiya, "Ray tracing complex scenes", SIGGRAPH 1986 (slabs);
//   A. Williams, S. Barrus, R. K. Morley and P. Shirley, "An efficient and robust ray-box intersection
//   algorithm", Journal of Graphics Tools 10(1), 2005 (near and far planes from the direction's signs);
//   T. Ize, "Robust BVH ray traversal", Journal of Computer Graphics Techniques 2(2), 2013 (widening);
//   T. Aila and S. Laine, "Understanding the efficiency of ray traversal on GPUs", HPG 2009 (children
//   tested at the parent, distance-ordered).
#pragma once
#include "strahl/ch04/traverse.hpp"
#include "strahl/tree_query.hpp"
#include <cmath>

namespace strahl::ch05 {

// What the slab test needs of a ray, computed once: origin, 1 / direction, and per axis which of a node's
// six floats (bmin[0..2], bmax[0..2]) is the near plane (bmax when the direction's sign bit is set, -0
// included) and which the far one.
struct slab_ray {
    vec3 org, inv_dir;
    int near_plane[3], far_plane[3];

    explicit slab_ray(const ray& r) : org(r.org), inv_dir(1.0f / r.dir) {
        for (int a = 0; a < 3; ++a) {
            const bool down = std::signbit(r.dir[a]);
            near_plane[a] = down ? 3 + a : a;
            far_plane[a] = down ? a : 3 + a;
        }
    }
};

// The entry distance of node n's box for t in [tmin, tmax], or +inf when the ray misses it. Where the
// origin lies on a plane and the direction component is +-0, the plane's t is NaN (0 * inf); the
// comparisons below are written so that a NaN never wins (the ray runs in the plane: no constraint), as
// chapter 04's slab test skips such an axis. The exit is widened by 1 + 2 gamma(3) (conservative).
inline float entry_distance(const ch04::bvh_node& n, const slab_ray& s, float tmin, float tmax) {
    const float* planes = n.bmin;  // bmin[0..2] then bmax[0..2]: six consecutive floats (bvh.hpp)
    float t0 = tmin, t1 = tmax;
    for (int a = 0; a < 3; ++a) {
        const float near = (planes[s.near_plane[a]] - s.org[a]) * s.inv_dir[a];
        const float far = (planes[s.far_plane[a]] - s.org[a]) * s.inv_dir[a];
        t0 = near > t0 ? near : t0;
        t1 = far < t1 ? far : t1;
    }
    t1 *= t1 > 0.0f ? 1.0f + 2.0f * ch04::gamma(3) : 1.0f - 2.0f * ch04::gamma(3);
    return t0 <= t1 ? t0 : inf;
}

// Visits the leaves whose boxes the ray meets, nearer child first; leaf(first, count) as in chapter 04.
template <class Stats, class LeafTest>
void fast_traverse(const ch04::bvh& tree, ray& r, Stats& stats, LeafTest&& leaf) {
    if (tree.nodes.empty()) return;
    static_assert(offsetof(ch04::bvh_node, bmax) == 3 * sizeof(float), "bmin and bmax are adjacent");
    const slab_ray s(r);
    const float slack = ray_slack(r, tree.bounds);
    const ch04::bvh_node* nodes = tree.nodes.data();
    struct entry {
        std::uint32_t index;
        float t;
    };
    entry stack[ch04::bvh_max_depth + 2];
    int top = 0;
    stats.box_test();
    if (entry_distance(nodes[0], s, r.tmin - slack, r.tmax + slack) == inf) return;
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
            const float t_left = entry_distance(nodes[left], s, lo, hi);
            const float t_right = entry_distance(nodes[right], s, lo, hi);
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

// fast_traverse as chapter 04's bvh_accel_t's Walk.
struct fast_walk {
    template <class Stats, class Leaf>
    void operator()(const ch04::bvh& tree, ray& r, Stats& stats, Leaf&& leaf) const {
        fast_traverse(tree, r, stats, leaf);
    }
};

}  // namespace strahl::ch05
