// Subtree costs and the partial rebuild (refit.hpp).
#include "strahl/ch10/refit.hpp"
#include <algorithm>
#include <numeric>

namespace strahl::ch10 {

std::vector<float> subtree_costs(const ch04::bvh& tree) {
    std::vector<float> cost(tree.nodes.size());
    for (std::size_t i = tree.nodes.size(); i-- > 0;) {
        const ch04::bvh_node& n = tree.nodes[i];
        const float area = n.box().surface_area();
        cost[i] = n.is_leaf() ? area * float(n.count) : area + cost[i + 1] + cost[n.offset];
    }
    return cost;
}

namespace {
struct subtree {
    std::uint32_t node = 0;
    std::uint32_t first = 0, count = 0;  // its range of prim_ids
    int depth = 0;
    float growth = 0.0f;
};

// Per node: its primitives' range in prim_ids (first leaf offset, total count) and its depth.
struct ranges {
    std::vector<std::uint32_t> first, count;
    std::vector<int> depth;
    bool contiguous = true;
};
ranges node_ranges(const ch04::bvh& tree) {
    const std::size_t n = tree.nodes.size();
    ranges r{std::vector<std::uint32_t>(n), std::vector<std::uint32_t>(n), std::vector<int>(n, 0)};
    for (std::size_t i = 0; i < n; ++i)
        if (!tree.nodes[i].is_leaf()) r.depth[i + 1] = r.depth[tree.nodes[i].offset] = r.depth[i] + 1;
    for (std::size_t i = n; i-- > 0;) {
        const ch04::bvh_node& node = tree.nodes[i];
        if (node.is_leaf()) {
            r.first[i] = node.offset, r.count[i] = node.count;
        } else {
            const std::uint32_t l = std::uint32_t(i + 1), rt = node.offset;
            r.first[i] = std::min(r.first[l], r.first[rt]);
            r.count[i] = r.count[l] + r.count[rt];
            // The right subtree's primitives must follow the left's, or the left's the right's.
            if (r.first[rt] != r.first[l] + r.count[l] && r.first[l] != r.first[rt] + r.count[rt]) r.contiguous = false;
        }
    }
    return r;
}
int tree_depth(const ch04::bvh& tree) {
    std::vector<int> d(tree.nodes.size(), 0);
    int deepest = 0;
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        deepest = std::max(deepest, d[i]);
        if (!tree.nodes[i].is_leaf()) d[i + 1] = d[tree.nodes[i].offset] = d[i] + 1;
    }
    return deepest;
}
}  // namespace

partial_result partial_rebuild(ch04::bvh& tree, std::vector<float>& baseline, std::span<const aabb> boxes,
                               const ch04::bvh_builder& builder, const partial_params& params) {
    partial_result result;
    if (tree.nodes.size() < 3 || baseline.size() != tree.nodes.size() || params.subtrees <= 0) return result;
    const ranges r = node_ranges(tree);
    const auto rebuild_all = [&] {
        std::vector<aabb> all(boxes.begin(), boxes.end());
        std::vector<vec3> c(all.size());
        for (std::size_t i = 0; i < all.size(); ++i) c[i] = all[i].centroid();
        tree = builder(all, c);
        baseline = subtree_costs(tree);
        result.full = true, result.primitives = boxes.size();
        return result;
    };
    if (!r.contiguous) return rebuild_all();

    // 1. The cut: the highest nodes holding at most cut_fraction of the primitives (inner nodes only: a leaf
    //    has nothing to rebuild), each ranked by its cost's growth since its last build.
    const std::vector<float> now = subtree_costs(tree);
    const float fraction = params.cut_fraction > 0.0f ? std::min(params.cut_fraction, 1.0f) : 0.0f;  // NaN: 0
    const auto cut_size = std::max<std::uint32_t>(2, std::uint32_t(fraction * float(r.count[0])));
    std::vector<subtree> cut;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
        const std::uint32_t i = stack.back();
        stack.pop_back();
        const ch04::bvh_node& n = tree.nodes[i];
        if (n.is_leaf()) continue;
        if (r.count[i] <= cut_size) {
            cut.push_back({i, r.first[i], r.count[i], r.depth[i], now[i] - baseline[i]});
            continue;
        }
        stack.push_back(n.offset), stack.push_back(i + 1);
    }
    // 2. The worst: the largest growths (ties by node index, so the choice is deterministic).
    const std::size_t k = std::min<std::size_t>(std::size_t(params.subtrees), cut.size());
    std::partial_sort(cut.begin(), cut.begin() + std::ptrdiff_t(k), cut.end(), [](const subtree& a, const subtree& b) {
        return a.growth > b.growth || (a.growth == b.growth && a.node < b.node);
    });
    cut.resize(k);
    std::sort(cut.begin(), cut.end(), [](const subtree& a, const subtree& b) { return a.node < b.node; });

    // 3. Each rebuilt over its primitives' boxes; ids mapped back into its range of prim_ids.
    std::vector<ch04::bvh> fresh(k);
    for (std::size_t j = 0; j < k; ++j) {
        const subtree& s = cut[j];
        std::vector<aabb> b(s.count);
        std::vector<vec3> c(s.count);
        for (std::uint32_t q = 0; q < s.count; ++q) b[q] = boxes[tree.prim_ids[s.first + q]], c[q] = b[q].centroid();
        fresh[j] = builder(b, c);
        if (!fresh[j].loose.empty() || s.depth + fresh[j].stats.depth > ch04::bvh_max_depth - 2) return rebuild_all();
        std::vector<std::uint32_t> ids(tree.prim_ids.begin() + s.first, tree.prim_ids.begin() + s.first + s.count);
        for (std::uint32_t q = 0; q < s.count; ++q) tree.prim_ids[s.first + q] = ids[fresh[j].prim_ids[q]];
        result.primitives += s.count;
    }
    result.rebuilt = int(k);

    // 4. Re-flatten: the old nodes in depth-first order, each chosen subtree replaced by its new nodes; the
    //    baseline travels with the kept nodes and is the new cost for the rebuilt ones.
    std::vector<ch04::bvh_node> nodes;
    std::vector<float> base;
    nodes.reserve(tree.nodes.size());
    base.reserve(tree.nodes.size());
    std::size_t next_cut = 0;
    // emit(i): copies node i's subtree (or its replacement), returns its index in the new array.
    const auto emit = [&](auto&& self, std::uint32_t i) -> std::uint32_t {
        const auto at = std::uint32_t(nodes.size());
        if (next_cut < k && cut[next_cut].node == i) {
            const ch04::bvh& f = fresh[next_cut];
            const std::uint32_t first = cut[next_cut].first;
            ++next_cut;
            const std::vector<float> c = subtree_costs(f);
            for (std::size_t q = 0; q < f.nodes.size(); ++q) {
                ch04::bvh_node n = f.nodes[q];
                n.offset += n.is_leaf() ? first : at;
                nodes.push_back(n);
                base.push_back(c[q]);
            }
            return at;
        }
        const ch04::bvh_node n = tree.nodes[i];
        nodes.push_back(n);
        base.push_back(baseline[i]);
        if (!n.is_leaf()) {
            self(self, i + 1);
            nodes[at].offset = self(self, n.offset);
        }
        return at;
    };
    emit(emit, 0);
    tree.nodes = std::move(nodes);
    baseline = std::move(base);
    tree.stats.inner = tree.stats.leaves = 0;
    for (const ch04::bvh_node& n : tree.nodes) (n.is_leaf() ? tree.stats.leaves : tree.stats.inner)++;
    tree.stats.depth = tree_depth(tree);
    return result;
}

}  // namespace strahl::ch10
