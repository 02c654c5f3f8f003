// BUILD-HLBVH: Morton order, clusters by the codes' top bits, radix trees below them, the binned SAH above.
//   J. Pantaleoni and D. Luebke, "HLBVH: hierarchical LBVH construction for real-time ray tracing of
//   dynamic geometry", HPG 2010;
//   K. Garanzha, J. Pantaleoni and D. McAllister, "Simpler and faster HLBVH with work queues", HPG 2011.
#include "strahl/ch08/hlbvh.hpp"
#include "strahl/ch07/lbvh.hpp"
#include "strahl/ch07/morton.hpp"
#include "strahl/ch07/radix_sort.hpp"
#include "strahl/ch07/radix_tree.hpp"
#include "strahl/parallel.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <stdexcept>

namespace strahl::ch08 {

namespace {

// 4. The top level: the binned SAH over clusters, top down, to one cluster per leaf. The range [a, b) of
//    `order` (cluster ids) is partitioned in place; the inner node that splits it at position mid is node
//    inner_node[mid - 1] (every position 1..K-1 splits exactly one node), so the halves may be built in
//    parallel without sharing a counter.
struct top_builder {
    std::span<const aabb> box;                   // per cluster
    std::span<const vec3> centre;                // per cluster: its box's centre
    std::span<const std::uint32_t> count;        // per cluster: its primitives
    std::span<const std::uint32_t> root;         // per cluster: its subtree's root node
    std::span<const std::uint32_t> inner_node;   // K - 1 node numbers for the top tree's inner nodes
    std::span<std::uint32_t> order;              // cluster ids, partitioned in place
    int bins;
    ch05::sah_costs costs;
    binary_tree& t;

    // Splits [a, b) (b - a >= 2): the best bin boundary over the three axes, or the middle.
    std::size_t split(std::size_t a, std::size_t b, int depth) const {
        aabb cbox, pbox;
        for (std::size_t k = a; k < b; ++k) cbox.grow(centre[order[k]]), pbox.grow(box[order[k]]);
        int best_axis = -1;
        ch05::bin_split best;
        ch05::bin_mapping best_map;
        if (depth < ch04::spatial_depth_limit) {
            std::vector<ch05::bin> bin(static_cast<std::size_t>(bins));
            std::vector<float> right_area(static_cast<std::size_t>(bins));
            for (int axis = 0; axis < 3; ++axis) {
                if (!(cbox.max[axis] > cbox.min[axis])) continue;  // all centres in one plane: no boundary
                const ch05::bin_mapping map = ch05::make_bin_mapping(cbox.min[axis], cbox.max[axis], bins);
                std::fill(bin.begin(), bin.end(), ch05::bin{});
                for (std::size_t k = a; k < b; ++k) {
                    ch05::bin& into = bin[std::size_t(ch05::bin_index(map, centre[order[k]][axis]))];
                    into.box.grow(box[order[k]]);
                    into.count += count[order[k]];
                }
                const ch05::bin_split s = ch05::best_boundary(bin, right_area, costs, pbox.surface_area());
                if (s.cost < best.cost) best = s, best_axis = axis, best_map = map;
            }
        }
        if (best_axis >= 0) {
            const auto mid = std::partition(order.begin() + std::ptrdiff_t(a), order.begin() + std::ptrdiff_t(b),
                                            [&](std::uint32_t c) {
                                                return ch05::bin_index(best_map, centre[c][best_axis]) < best.index;
                                            });
            return std::size_t(mid - order.begin());
        }
        return a + (b - a) / 2;  // no boundary separates the centres, or too deep: the middle of the range
    }

    std::uint32_t build(std::size_t a, std::size_t b, int depth) {
        if (b - a == 1) return root[order[a]];
        const std::size_t mid = split(a, b, depth);
        std::uint32_t left = 0, right = 0;
        if (b - a >= 512) {
            parallel_invoke([&] { left = build(a, mid, depth + 1); }, [&] { right = build(mid, b, depth + 1); });
        } else {
            left = build(a, mid, depth + 1), right = build(mid, b, depth + 1);
        }
        const std::uint32_t node = inner_node[mid - 1];
        tree_node& n = t.nodes[node];
        n.left = left, n.right = right;
        n.box = unite(t.nodes[left].box, t.nodes[right].box);
        t.nodes[left].parent = t.nodes[right].parent = node;
        return node;
    }
};

}  // namespace

std::string to_string(const hlbvh_params& p) {
    return "hlbvh" + std::to_string(p.cluster_bits) + (p.bits_per_axis == 21 ? "-63" : "");
}

binary_tree build_hlbvh(std::span<const aabb> boxes, std::span<const vec3> centroids, const hlbvh_params& params,
                        hlbvh_report* report) {
    if (boxes.size() != centroids.size()) throw std::invalid_argument("build_hlbvh: one centroid per box");
    if (params.bits_per_axis != 10 && params.bits_per_axis != 21)
        throw std::invalid_argument("build_hlbvh: bits_per_axis must be 10 or 21");
    const int code_bits = 3 * params.bits_per_axis;
    const int shift = code_bits - std::clamp(params.cluster_bits, 0, code_bits);  // a code's cluster: code >> shift
    hlbvh_report rep;
    timer phase;
    binary_tree t;

    // 1. Codes and sort (chapter 07): the loose primitives set aside, the others in Morton order.
    ch07::morton_codes codes = ch07::compute_morton_codes(boxes, centroids, params.bits_per_axis);
    ch07::radix_sort_params sort;
    sort.key_bits = code_bits;
    ch07::radix_sort(codes.keys, codes.ids, sort);
    t.loose = std::move(codes.loose);
    rep.codes_sort_ms = phase.milliseconds(), phase.restart();
    const std::size_t n = codes.ids.size();
    if (n == 0) {
        if (report) *report = rep;
        return t;
    }
    const std::vector<std::uint64_t>& key = codes.keys;
    const auto cluster_key = [&](std::size_t k) { return shift >= 64 ? 0 : key[k] >> shift; };

    // 2. Clusters: runs of equal top bits. cluster_of[k]: the cluster of sorted position k; last[c]: the
    //    last position of cluster c.
    std::vector<std::uint32_t> cluster_of(n), last;
    for (std::size_t k = 0; k < n; ++k) {
        if (k > 0 && cluster_key(k) != cluster_key(k - 1)) last.push_back(std::uint32_t(k - 1));
        cluster_of[k] = std::uint32_t(last.size());
    }
    last.push_back(std::uint32_t(n - 1));
    const std::size_t clusters = last.size();
    rep.clusters = clusters;

    // 3. Bottom: the radix tree over all codes and its boxes (chapter 07); each cluster the subtree over its
    //    range. Leaf k is node k; a radix node inside a cluster, split after position g, is node n + g; the
    //    subtree's root is the node whose parent lies outside the cluster (for a one-primitive cluster, the
    //    leaf itself).
    ch07::radix_tree rt;
    ch07::build_radix_tree_karras(key, rt);
    std::vector<aabb> leaf_boxes(n);
    parallel_for_chunks(n, 4096, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) leaf_boxes[k] = boxes[codes.ids[k]];
    });
    const std::vector<aabb> inner_boxes = ch07::fit_boxes(rt, leaf_boxes);
    t.nodes.resize(2 * n - 1);
    std::vector<std::uint32_t> cluster_root(clusters);
    const auto in_cluster = [&](std::uint32_t i) {  // radix inner node i lies within one cluster
        return i != ch07::radix_tree::none && cluster_key(rt.first[i]) == cluster_key(rt.last[i]);
    };
    const auto node_of = [&](std::uint32_t ref) {  // a radix child reference's node number
        return ch07::is_leaf_ref(ref) ? ref & ~ch07::leaf_bit : std::uint32_t(n) + (rt.left[ref] & ~ch07::leaf_bit);
    };
    parallel_for_chunks(n, 4096, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {  // leaf k, and radix inner node k where it is one
            tree_node& leaf = t.nodes[k];
            leaf.box = leaf_boxes[k], leaf.prim = codes.ids[k];
            if (in_cluster(rt.leaf_parent[k]))
                leaf.parent = node_of(rt.leaf_parent[k]);
            else
                cluster_root[cluster_of[k]] = std::uint32_t(k);
            if (k + 1 == n || !in_cluster(std::uint32_t(k))) continue;
            const std::uint32_t i = std::uint32_t(k), self = node_of(i);
            tree_node& inner = t.nodes[self];
            inner.box = inner_boxes[i];
            inner.left = node_of(rt.left[i]), inner.right = node_of(rt.right[i]);
            if (in_cluster(rt.parent[i]))
                inner.parent = node_of(rt.parent[i]);
            else
                cluster_root[cluster_of[rt.first[i]]] = self;
        }
    });
    rep.bottom_ms = phase.milliseconds(), phase.restart();

    // 4. Top: the binned SAH over the clusters, its inner nodes numbered n + last[c] for c < K - 1 (the
    //    positions where no radix node inside a cluster splits). 5. The clusters' subtrees hang under its
    //    leaves: a top leaf is the cluster's root node.
    if (clusters == 1) {
        t.root = cluster_root[0];
    } else {
        std::vector<aabb> cbox(clusters);
        std::vector<vec3> centre(clusters);
        std::vector<std::uint32_t> count(clusters), order(clusters), inner_node(clusters - 1);
        for (std::size_t c = 0; c < clusters; ++c) {
            cbox[c] = t.nodes[cluster_root[c]].box, centre[c] = cbox[c].centroid();
            count[c] = last[c] + 1 - (c == 0 ? 0 : last[c - 1] + 1);
            order[c] = std::uint32_t(c);
            if (c + 1 < clusters) inner_node[c] = std::uint32_t(n) + last[c];
        }
        top_builder top{cbox, centre, count, cluster_root, inner_node, order, std::clamp(params.bins, 2, 256),
                        params.costs, t};
        t.root = top.build(0, clusters, 0);
    }
    rep.top_ms = phase.milliseconds();
    if (report) *report = rep;
    return t;
}

}  // namespace strahl::ch08
