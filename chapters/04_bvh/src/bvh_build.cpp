// BUILD-HIERARCHY, top down, then the flattening into 32-byte nodes.
//   J. Goldsmith and J. Salmon, "Automatic creation of object hierarchies for ray tracing", IEEE CG&A 1987;
//   M. Pharr, W. Jakob and G. Humphreys, pbrt-v4, 2023, section 7.3 (median splits, flattening).
// Step 1 builds a simple pointer tree over one index array, partitioned in place per node (no copies);
// step 2 flattens it depth first, the left child right after its parent.
#include "strahl/ch04/bvh.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <memory>
#include <stdexcept>

namespace strahl::ch04 {

namespace {

// The pointer form: children own each other; a leaf holds its range [first, first + count) of prim_ids.
struct build_node {
    aabb box;
    std::unique_ptr<build_node> left, right;
    std::uint32_t first = 0, count = 0;
    int axis = 0;
};

struct builder {
    std::span<const aabb> boxes;
    std::span<const vec3> centroids;
    bvh_build_params params;
    std::vector<std::uint32_t>& ids;
    bvh_stats& stats;

    // BUILD-HIERARCHY(range): the range's box; a leaf if small enough; else split, recurse on both halves.
    std::unique_ptr<build_node> build(std::size_t begin, std::size_t end, int depth) {
        auto node = std::make_unique<build_node>();
        for (std::size_t k = begin; k < end; ++k) node->box.grow(boxes[ids[k]]);
        stats.depth = std::max(stats.depth, depth);
        const std::size_t n = end - begin;
        if (n <= std::size_t(params.leaf_size)) {
            node->first = std::uint32_t(begin);
            node->count = std::uint32_t(n);
            ++stats.leaves;
            stats.max_leaf = std::max(stats.max_leaf, n);
            return node;
        }
        // The split (exercise 04.2): deep down the spatial median gives way to the object median, which
        // halves the range, so the depth stays bounded whatever the centroids.
        const split_method m = depth >= spatial_depth_limit ? split_method::object_median : params.split;
        const split_result s = partition_split(std::span(ids).subspan(begin, n), centroids, m);
        if (s.mid == 0 || s.mid >= n) throw std::logic_error("partition_split must return 0 < mid < n");
        ++stats.inner;
        node->axis = s.axis;
        node->left = build(begin, begin + s.mid, depth + 1);
        node->right = build(begin + s.mid, end, depth + 1);
        return node;
    }
};

// Step 2, flattening: depth first, so an inner node's left child is the next node and only the right
// child's index needs storing.
std::uint32_t flatten(const build_node& b, std::vector<bvh_node>& out) {
    const auto index = std::uint32_t(out.size());
    bvh_node n{};
    for (int a = 0; a < 3; ++a) n.bmin[a] = b.box.min[a], n.bmax[a] = b.box.max[a];
    out.push_back(n);
    if (!b.left) {
        out[index].offset = b.first;
        out[index].count = std::uint16_t(b.count);
        return index;
    }
    out[index].axis = std::uint8_t(b.axis);
    flatten(*b.left, out);
    const std::uint32_t right = flatten(*b.right, out);
    out[index].offset = right;
    return index;
}

void collect(const bvh& t, std::uint32_t index, int level, int first, int last, std::vector<level_box>& out) {
    const bvh_node& n = t.nodes[index];
    if (level > last) return;
    if (level >= first) out.push_back({level, n.box()});
    if (n.is_leaf()) return;
    collect(t, index + 1, level + 1, first, last, out);
    collect(t, n.offset, level + 1, first, last, out);
}

}  // namespace

const char* to_string(split_method m) { return m == split_method::object_median ? "median" : "spatial"; }

bvh build_bvh(std::span<const aabb> boxes, std::span<const vec3> centroids, const bvh_build_params& params) {
    if (boxes.size() != centroids.size()) throw std::invalid_argument("build_bvh: one centroid per box");
    const timer clock;
    bvh t;
    t.stats.primitives = boxes.size();
    for (std::size_t i = 0; i < boxes.size(); ++i)
        (fits_in_tree(boxes[i], centroids[i]) ? t.prim_ids : t.loose).push_back(std::uint32_t(i));
    if (!t.prim_ids.empty()) {
        bvh_build_params p = params;
        p.leaf_size = std::clamp(p.leaf_size, 1, 255);
        builder b{boxes, centroids, p, t.prim_ids, t.stats};
        const std::unique_ptr<build_node> root = b.build(0, t.prim_ids.size(), 0);
        t.bounds = root->box;
        t.nodes.reserve(2 * t.prim_ids.size() - 1);  // N primitives: at most 2N - 1 nodes
        flatten(*root, t.nodes);
    }
    t.stats.build_ms = clock.milliseconds();
    return t;
}

double sah_tree_cost(const bvh& tree, float c_traversal, float c_intersection) {
    if (tree.nodes.empty()) return 0.0;
    const double root = tree.nodes[0].box().surface_area();
    double cost = 0.0;
    for (const bvh_node& n : tree.nodes) {
        const double p = root > 0.0 ? double(n.box().surface_area()) / root : 1.0;
        cost += n.is_leaf() ? double(c_intersection) * double(n.count) * p : double(c_traversal) * p;
    }
    return cost;
}

std::vector<level_box> level_boxes(const bvh& tree, int first_level, int last_level) {
    std::vector<level_box> out;
    if (!tree.nodes.empty()) collect(tree, 0, 0, first_level, last_level, out);
    return out;
}

}  // namespace strahl::ch04
