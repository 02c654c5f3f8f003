// A built flat BVH (chapter 04's layout) checked against its builder's inputs, for the builders of chapters
// 07 and 08: every primitive once (in a leaf, or loose where its box or centroid is not finite), 2 L - 1
// nodes, boxes tight around their contents, leaves within max_leaf, depth within the bound.
#pragma once
#include "strahl/ch04/bvh.hpp"
#include <algorithm>
#include <catch2/catch.hpp>
#include <span>
#include <vector>

namespace strahl::test {

inline bool same_box(const aabb& a, const aabb& b) { return a.min == b.min && a.max == b.max; }

// Chapter 04's invariants, and tight boxes: a leaf's box is its primitives' boxes' union, an inner node's
// its children's union (so each child lies inside its parent). Counts the nodes that break them in `wrong`
// (one CHECK for the tree, not one per node). Returns the depth below node i.
inline int check_node(const ch04::bvh& t, std::uint32_t i, std::span<const aabb> boxes, int max_leaf,
                      std::vector<int>& seen, std::size_t& wrong) {
    const ch04::bvh_node& n = t.nodes[i];
    aabb tight;
    int depth = 0;
    if (n.is_leaf()) {
        wrong += n.count > max_leaf;
        for (std::uint32_t k = n.offset; k < n.offset + n.count; ++k) tight.grow(boxes[t.prim_ids[k]]), ++seen[t.prim_ids[k]];
    } else {
        REQUIRE(n.offset > i + 1);
        wrong += n.axis >= 3;
        tight = unite(t.nodes[i + 1].box(), t.nodes[n.offset].box());
        depth = 1 + std::max(check_node(t, i + 1, boxes, max_leaf, seen, wrong), check_node(t, n.offset, boxes, max_leaf, seen, wrong));
    }
    wrong += !same_box(tight, n.box());
    return depth;
}

// The whole tree: chapter 04's invariants (every primitive once, in a leaf or loose; 2 L - 1 nodes; tight
// boxes; leaves within max_leaf; depth within max_depth, as stats.depth says).
inline void check_flat_bvh(const ch04::bvh& t, std::span<const aabb> boxes, std::span<const vec3> centroids,
                           int max_leaf = 4, int max_depth = ch04::bvh_max_depth) {
    CHECK(t.stats.primitives == boxes.size());
    std::vector<int> seen(boxes.size(), 0);
    for (const std::uint32_t id : t.loose) {
        CHECK_FALSE(ch04::fits_in_tree(boxes[id], centroids[id]));
        ++seen[id];
    }
    CHECK(t.prim_ids.size() + t.loose.size() == boxes.size());
    if (t.prim_ids.empty()) {
        CHECK(t.nodes.empty());
    } else {
        REQUIRE(!t.nodes.empty());
        CHECK(t.nodes.size() == 2 * t.stats.leaves - 1);
        CHECK(t.stats.inner + t.stats.leaves == t.nodes.size());
        CHECK(same_box(t.bounds, t.nodes[0].box()));
        std::size_t wrong_nodes = 0;  // boxes not tight, leaves above max_leaf, axes beyond 2
        const int depth = check_node(t, 0, boxes, max_leaf, seen, wrong_nodes);
        CHECK(wrong_nodes == 0);
        CHECK(depth == t.stats.depth);
        CHECK(depth <= max_depth);
    }
    CHECK(std::count(seen.begin(), seen.end(), 1) == std::ptrdiff_t(seen.size()));  // each primitive exactly once
}

}  // namespace strahl::test
