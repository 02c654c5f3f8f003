// The k-d tree builder: SAH splits over box-edge events, straddling references in both children,
// termination by cost and by depth, then flattening into 8-byte nodes.
//   I. Wald and V. Havran, "On building fast kd-trees for ray tracing, and on doing that in O(N log N)",
//   IEEE Symposium on Interactive Ray Tracing, 2006. We build their O(N log^2 N) variant: each node
//   generates and sorts its own events on each axis (section 4.2), instead of keeping them sorted.
//   J. D. MacDonald and K. S. Booth, "Heuristics for ray tracing using space subdivision", 1990 (the SAH).
#include "strahl/ch03/kd_tree.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <cmath>
#include <memory>
#include <tbb/parallel_invoke.h>

namespace strahl::ch03 {

int depth_limit(std::size_t n) {
    if (n < 2) return 1;
    return std::min(kd_max_depth, int(8.0 + 1.3 * std::log2(double(n))));
}

namespace {

// The pointer form: built first, flattened after.
struct build_node {
    int axis = 3;  // 3: leaf
    float split = 0.0f;
    std::unique_ptr<build_node> child[2];
    std::vector<std::uint32_t> refs;  // leaves only
};

struct builder {
    std::span<const aabb> boxes;
    kd_build_params params;
    int max_depth;

    // Step 1, the events of one axis: each reference's box clipped to the node's box gives a start and
    // an end, or one planar event where it has no extent on the axis.
    void make_events(const std::vector<std::uint32_t>& refs, const aabb& box, int axis, std::vector<event>& ev) const {
        ev.clear();
        for (const std::uint32_t id : refs) {
            const aabb& b = boxes[id];
            const float lo = std::max(b.min[axis], box.min[axis]);
            const float hi = std::max(lo, std::min(b.max[axis], box.max[axis]));
            if (lo == hi) {
                ev.push_back({lo, event_type::planar});
            } else {
                ev.push_back({lo, event_type::start});
                ev.push_back({hi, event_type::end});
            }
        }
        std::sort(ev.begin(), ev.end());
    }

    std::unique_ptr<build_node> build(std::vector<std::uint32_t> refs, const aabb& box, int depth) const {
        auto node = std::make_unique<build_node>();
        // Step 2, the cheapest plane over all three axes (the SAH event sweep, exercise 03.1).
        split_candidate best;
        if (!refs.empty() && depth < max_depth) {
            std::vector<event> ev;
            ev.reserve(refs.size() * 2);
            for (int axis = 0; axis < 3; ++axis) {
                if (!(box.max[axis] > box.min[axis])) continue;  // flat: no plane strictly inside
                make_events(refs, box, axis, ev);
                const split_candidate c = sah_sweep(ev, axis, box, refs.size(), params.sah);
                if (c.cost < best.cost) best = c;
            }
        }
        // Step 3, termination by cost: a leaf when no split is cheaper than testing every triangle.
        const float leaf_cost = params.sah.c_intersect * float(refs.size());
        if (!(best.cost < leaf_cost)) {
            node->refs = std::move(refs);
            return node;
        }
        // Step 4, classify each reference (exercise 03.2): straddling ones go to both children.
        std::vector<std::uint32_t> left, right;
        left.reserve(best.n_left + best.n_planar);
        right.reserve(best.n_right + best.n_planar);
        for (const std::uint32_t id : refs) {
            const side s = classify(boxes[id], best.axis, best.pos, best.planar_left);
            if (s != side::right) left.push_back(id);
            if (s != side::left) right.push_back(id);
        }
        refs = {};
        aabb left_box = box, right_box = box;
        left_box.max[best.axis] = best.pos;
        right_box.min[best.axis] = best.pos;
        node->axis = best.axis;
        node->split = best.pos;
        // Large subtrees are built in parallel (the result does not depend on it).
        if (left.size() + right.size() > 4096) {
            tbb::parallel_invoke([&] { node->child[0] = build(std::move(left), left_box, depth + 1); },
                                 [&] { node->child[1] = build(std::move(right), right_box, depth + 1); });
        } else {
            node->child[0] = build(std::move(left), left_box, depth + 1);
            node->child[1] = build(std::move(right), right_box, depth + 1);
        }
        return node;
    }
};

// Step 5, flattening: depth first, the two children of a node side by side.
void flatten(const build_node& b, std::uint32_t index, int depth, kd_tree& t) {
    t.stats.depth = std::max(t.stats.depth, depth);
    if (b.axis == 3) {
        t.nodes[index] = kd_node::leaf(std::uint32_t(t.prim_refs.size()), std::uint32_t(b.refs.size()));
        t.prim_refs.insert(t.prim_refs.end(), b.refs.begin(), b.refs.end());
        ++t.stats.leaves;
        t.stats.empty_leaves += b.refs.empty() ? 1 : 0;
        t.stats.references += b.refs.size();
        t.stats.max_leaf = std::max(t.stats.max_leaf, b.refs.size());
        return;
    }
    const auto left = std::uint32_t(t.nodes.size());
    t.nodes.resize(t.nodes.size() + 2);
    t.nodes[index] = kd_node::inner(b.axis, b.split, left);
    ++t.stats.inner;
    flatten(*b.child[0], left, depth + 1, t);
    flatten(*b.child[1], left + 1, depth + 1, t);
}

bool finite_box(const aabb& b) {
    return std::isfinite(b.min.x) && std::isfinite(b.min.y) && std::isfinite(b.min.z) &&
           std::isfinite(b.max.x) && std::isfinite(b.max.y) && std::isfinite(b.max.z) && !b.is_empty();
}

}  // namespace

kd_tree build_kd_tree(std::span<const aabb> boxes, const kd_build_params& params) {
    const timer clock;
    kd_tree t;
    t.sah = params.sah;
    std::vector<std::uint32_t> refs;
    refs.reserve(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        if (finite_box(boxes[i])) {
            refs.push_back(std::uint32_t(i));
            t.bounds.grow(boxes[i]);
        } else {
            t.loose.push_back(std::uint32_t(i));  // a non-finite triangle: tested by every ray instead
        }
    }
    t.stats.primitives = boxes.size();
    if (!refs.empty()) {
        const builder b{boxes, params, params.max_depth >= 0 ? std::min(params.max_depth, kd_max_depth)
                                                           : depth_limit(refs.size())};
        t.stats.depth_limit = b.max_depth;
        const std::unique_ptr<build_node> root = b.build(std::move(refs), t.bounds, 0);
        t.nodes.resize(1);
        flatten(*root, 0, 0, t);
    }
    t.stats.build_ms = clock.milliseconds();
    return t;
}

}  // namespace strahl::ch03
