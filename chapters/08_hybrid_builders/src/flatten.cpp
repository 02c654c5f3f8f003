// FLATTEN: the SAH collapse of a binary tree with one primitive per leaf, then chapter 04's depth-first
// nodes, in parallel where the depth bound allows (binary_tree.hpp states the contract).
//   T. Karras and T. Aila, "Fast parallel construction of high-quality bounding volume hierarchies",
//   HPG 2013 (the collapse after restructuring); T. Karras, HPG 2012, section 4 (the bottom-up pass with an
//   atomic counter per node).
#include "strahl/ch08/binary_tree.hpp"
#include "strahl/parallel.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <atomic>

namespace strahl::ch08 {

ch04::bvh flatten(const binary_tree& t, const flatten_params& params) {
    flatten_params p = params;
    p.max_leaf = std::clamp(p.max_leaf, 1, 255);
    p.max_depth = std::clamp(p.max_depth, 33, ch04::bvh_max_depth);
    const timer clock;
    ch04::bvh out;
    out.loose = t.loose;
    out.stats.primitives = t.leaves() * (t.root != none) + t.loose.size();
    if (t.root == none) return out;

    // 1. Bottom up: each subtree's primitive count, SAH cost (areas, not ratios), whether it becomes one
    //    leaf, its height as written (a collapsed subtree is a leaf: 0), its size in flat nodes and the
    //    largest leaf below. In parallel: a task per leaf climbs towards the root; at each inner node the
    //    first of its two children to arrive stops, the second prices the node and climbs on (chapter 07's
    //    bottom-up pass, with the parent links).
    const std::size_t m = t.nodes.size();
    std::vector<std::uint32_t> count(m, 1), height(m, 0), size(m, 1), largest(m, 1);
    std::vector<float> cost(m, 0.0f);
    std::vector<std::uint8_t> as_leaf(m, 1);
    std::vector<std::uint32_t> arrivals(m, 0);
    const auto price = [&](std::uint32_t i) {
        const tree_node& n = t.nodes[i];
        const float area = n.box.surface_area();
        count[i] = count[n.left] + count[n.right];
        const float split = p.costs.traversal * area + cost[n.left] + cost[n.right];
        const float leaf = p.costs.intersection * float(count[i]) * area;
        as_leaf[i] = count[i] <= std::uint32_t(p.max_leaf) && leaf <= split;
        cost[i] = as_leaf[i] ? leaf : split;
        height[i] = as_leaf[i] ? 0 : 1 + std::max(height[n.left], height[n.right]);
        size[i] = as_leaf[i] ? 1 : 1 + size[n.left] + size[n.right];
        largest[i] = as_leaf[i] ? count[i] : std::max(largest[n.left], largest[n.right]);
    };
    parallel_for_chunks(m, 2048, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
            if (!t.nodes[k].is_leaf()) continue;
            cost[k] = p.costs.intersection * t.nodes[k].box.surface_area();
            for (std::uint32_t i = t.nodes[k].parent; i != none; i = t.nodes[i].parent) {
                if (std::atomic_ref<std::uint32_t>(arrivals[i]).fetch_add(1, std::memory_order_acq_rel) == 0) break;
                price(i);
            }
        }
    });

    // 2'. Where no subtree reaches below max_depth, every subtree's place is known from the sizes: the left
    //     child at index + 1, the right after the left subtree's nodes, and its primitives after the left
    //     subtree's in prim_ids. Large subtrees are written in parallel, a node's two children as two tasks.
    if (height[t.root] <= std::uint32_t(p.max_depth)) {
        out.nodes.resize(size[t.root]);
        out.prim_ids.resize(count[t.root]);
        struct writer {
            const binary_tree& t;
            const std::vector<std::uint32_t>& count;
            const std::vector<std::uint32_t>& size;
            const std::vector<std::uint8_t>& as_leaf;
            ch04::bvh& out;
            void write(std::uint32_t i, std::uint32_t index, std::uint32_t first) const {
                const tree_node& n = t.nodes[i];
                ch04::bvh_node& node = out.nodes[index];
                for (int a = 0; a < 3; ++a) node.bmin[a] = n.box.min[a], node.bmax[a] = n.box.max[a];
                if (n.is_leaf() || as_leaf[i]) {
                    node.offset = first, node.count = std::uint16_t(count[i]);
                    std::uint32_t stack[256], top = 0, k = first;  // a collapsed subtree: at most 255 leaves
                    stack[top++] = i;
                    while (top > 0) {
                        const tree_node& x = t.nodes[stack[--top]];
                        if (x.is_leaf()) out.prim_ids[k++] = x.prim;
                        else stack[top++] = x.right, stack[top++] = x.left;
                    }
                    return;
                }
                const std::uint32_t right = index + 1 + size[n.left];
                node.offset = right;
                node.axis = std::uint8_t(n.box.largest_axis());
                const std::uint32_t right_first = first + count[n.left];
                if (size[i] >= 8192)
                    parallel_invoke([&] { write(n.left, index + 1, first); }, [&] { write(n.right, right, right_first); });
                else
                    write(n.left, index + 1, first), write(n.right, right, right_first);
            }
        };
        writer{t, count, size, as_leaf, out}.write(t.root, 0, 0);
        out.stats.depth = int(height[t.root]);
        out.stats.leaves = (out.nodes.size() + 1) / 2;
        out.stats.inner = out.nodes.size() - out.stats.leaves;
        out.stats.max_leaf = largest[t.root];
        out.bounds = out.nodes[0].box();
        out.stats.build_ms = clock.milliseconds();
        return out;
    }

    // 2. Depth first, left child next, into the flat array. A collapsed subtree's primitives go to
    //    prim_ids in tree order. At depth max_depth - 32 a subtree that would reach below max_depth is
    //    written by halving its primitives (in tree order) instead.
    out.nodes.reserve(2 * count[t.root] - 1);
    out.prim_ids.reserve(count[t.root]);
    const auto push = [&](const aabb& box, int depth) {
        ch04::bvh_node node{};
        for (int a = 0; a < 3; ++a) node.bmin[a] = box.min[a], node.bmax[a] = box.max[a];
        out.nodes.push_back(node);
        out.stats.depth = std::max(out.stats.depth, depth);
        return std::uint32_t(out.nodes.size() - 1);
    };
    const auto make_leaf = [&](std::uint32_t index, std::uint32_t first, std::uint32_t n) {
        out.nodes[index].offset = first, out.nodes[index].count = std::uint16_t(n);
        ++out.stats.leaves;
        out.stats.max_leaf = std::max<std::size_t>(out.stats.max_leaf, n);
    };
    const auto gather = [&](std::uint32_t sub) {  // the subtree's primitives, in tree order, into prim_ids
        std::vector<std::uint32_t> stack{sub};
        while (!stack.empty()) {
            const tree_node& n = t.nodes[stack.back()];
            stack.pop_back();
            if (n.is_leaf()) out.prim_ids.push_back(n.prim);
            else stack.push_back(n.right), stack.push_back(n.left);
        }
    };
    // A work item: write node `node` (or, halving, prim_ids [first, first + n)) at depth, and when it is a
    // right child, tell its parent's node where it landed.
    struct item {
        std::uint32_t node;        // tree node, or none when halving a range
        std::uint32_t first, n;    // the range of prim_ids when halving
        int depth;
        std::uint32_t parent_slot; // the flat parent whose offset this right child sets, or none
    };
    std::vector<item> stack{{t.root, 0, 0, 0, none}};
    std::vector<std::uint32_t> halve_ids;
    while (!stack.empty()) {
        const item w = stack.back();
        stack.pop_back();
        if (w.node == none) {  // halving: the range's box, a leaf, or two halves
            aabb box;
            for (std::uint32_t k = w.first; k < w.first + w.n; ++k) box.grow(t.nodes[halve_ids[k]].box);
            const std::uint32_t index = push(box, w.depth);
            if (w.parent_slot != none) out.nodes[w.parent_slot].offset = index;
            if (w.n <= std::uint32_t(p.max_leaf)) {
                make_leaf(index, std::uint32_t(out.prim_ids.size()), w.n);
                for (std::uint32_t k = w.first; k < w.first + w.n; ++k) out.prim_ids.push_back(t.nodes[halve_ids[k]].prim);
                continue;
            }
            const std::uint32_t half = w.n / 2;
            out.nodes[index].axis = std::uint8_t(box.largest_axis());
            ++out.stats.inner;
            stack.push_back({none, w.first + half, w.n - half, w.depth + 1, index});
            stack.push_back({none, w.first, half, w.depth + 1, none});
            continue;
        }
        const tree_node& n = t.nodes[w.node];
        if (!n.is_leaf() && !as_leaf[w.node] && w.depth == p.max_depth - 32 &&
            w.depth + int(height[w.node]) > p.max_depth) {
            // Too deep: its leaves (tree nodes holding one primitive each), in tree order, halved.
            const std::uint32_t first = std::uint32_t(halve_ids.size());
            std::vector<std::uint32_t> s{w.node};
            while (!s.empty()) {
                const tree_node& x = t.nodes[s.back()];
                const std::uint32_t xi = s.back();
                s.pop_back();
                if (x.is_leaf()) halve_ids.push_back(xi);
                else s.push_back(x.right), s.push_back(x.left);
            }
            stack.push_back({none, first, std::uint32_t(halve_ids.size()) - first, w.depth, w.parent_slot});
            continue;
        }
        const std::uint32_t index = push(n.box, w.depth);
        if (w.parent_slot != none) out.nodes[w.parent_slot].offset = index;
        if (n.is_leaf() || as_leaf[w.node]) {
            make_leaf(index, std::uint32_t(out.prim_ids.size()), count[w.node]);
            gather(w.node);
            continue;
        }
        out.nodes[index].axis = std::uint8_t(n.box.largest_axis());
        ++out.stats.inner;
        stack.push_back({n.right, 0, 0, w.depth + 1, index});  // after the whole left subtree
        stack.push_back({n.left, 0, 0, w.depth + 1, none});     // next: index + 1
    }
    out.bounds = out.nodes[0].box();
    out.stats.build_ms = clock.milliseconds();
    return out;
}

}  // namespace strahl::ch08
