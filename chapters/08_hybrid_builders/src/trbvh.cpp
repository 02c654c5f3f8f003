// RESTRUCTURE-TRBVH: the rounds of bottom-up treelet restructuring that TRBVH and ATRBVH share, and
// TRBVH's optimiser, the subset DP's optimal topology.
//   T. Karras and T. Aila, "Fast parallel construction of high-quality bounding volume hierarchies",
//   HPG 2013 (section 4: treelets; section 5: the bottom-up traversal with atomic counters, gamma).
#include "strahl/ch08/treelet.hpp"
#include "strahl/parallel.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <atomic>
#include <bit>
#include <limits>

namespace strahl::ch08 {

namespace {

// Per node, recomputed bottom up in every round: the subtree's primitives and SAH cost (areas, not ratios).
struct subtree_sums {
    std::vector<std::uint32_t> count;
    std::vector<float> cost;
};

// Rewires the treelet into `shape`: shape inner node m takes the node index tl.inner[m] (m = 0: the
// treelet's root, whose parent keeps pointing at it); children before parents, so that boxes, counts and
// costs are refitted from below.
void rewire(binary_tree& t, const treelet& tl, const treelet_shape& shape, const ch05::sah_costs& c,
            subtree_sums& s) {
    const auto n = std::uint8_t(tl.leaves.size());
    const auto node_of = [&](std::uint8_t code) { return code < n ? tl.leaves[code] : tl.inner[code - n]; };
    // Shape inner nodes in an order where every child comes before its parent: the reverse of a pre-order.
    std::array<std::uint8_t, max_treelet_leaves - 1> order{};
    std::array<std::uint8_t, max_treelet_leaves> stack{};
    int top = 0, placed = 0;
    stack[top++] = 0;
    while (top > 0) {
        const std::uint8_t m = stack[--top];
        order[placed++] = m;
        for (const std::uint8_t child : shape.children[m])
            if (child >= n) stack[top++] = std::uint8_t(child - n);
    }
    for (int k = placed - 1; k >= 0; --k) {
        const std::uint8_t m = order[k];
        const std::uint32_t i = tl.inner[m], l = node_of(shape.children[m][0]), r = node_of(shape.children[m][1]);
        tree_node& node = t.nodes[i];
        node.left = l, node.right = r;
        t.nodes[l].parent = i, t.nodes[r].parent = i;
        node.box = unite(t.nodes[l].box, t.nodes[r].box);
        s.count[i] = s.count[l] + s.count[r];
        s.cost[i] = c.traversal * node.box.surface_area() + (s.cost[l] + s.cost[r]);
    }
}

// The shape that the partitions of the full set describe, numbered in pre-order from the root.
treelet_shape shape_from_partitions(const optimal_topology& best, int n) {
    treelet_shape shape;
    const auto full = std::uint8_t((1u << n) - 1);
    shape.cost = best.cost[full];
    struct pending { std::uint8_t set, inner; };
    std::array<pending, max_dp_leaves> stack{};
    int top = 0;
    std::uint8_t made = 1;
    stack[top++] = {full, 0};
    while (top > 0) {
        const pending p = stack[--top];
        const std::uint8_t part = best.partition[p.set];
        if (part == 0 || (part & ~p.set) != 0 || part == p.set) {  // not a split of the set: keep the treelet
            shape.cost = std::numeric_limits<float>::infinity();
            return shape;
        }
        const std::uint8_t halves[2] = {part, std::uint8_t(p.set ^ part)};
        for (int side = 0; side < 2; ++side) {
            if (std::has_single_bit(halves[side])) {
                shape.children[p.inner][side] = std::uint8_t(std::countr_zero(halves[side]));
            } else {
                shape.children[p.inner][side] = std::uint8_t(n + made);
                stack[top++] = {halves[side], made++};
            }
        }
    }
    return shape;
}

}  // namespace

void restructure_treelets(binary_tree& t, int n_leaves, int rounds, int gamma, const ch05::sah_costs& c,
                          const treelet_optimizer& optimize, treelet_report* report) {
    const timer clock;
    n_leaves = std::clamp(n_leaves, 3, max_treelet_leaves);
    gamma = std::max(gamma, 1);
    std::atomic<std::size_t> formed{0}, rewired{0};
    const std::size_t m = t.nodes.size();
    subtree_sums s{std::vector<std::uint32_t>(m, 1), std::vector<float>(m, 0.0f)};
    std::vector<std::uint32_t> arrivals(m), leaves;  // leaves stay leaves: listed once
    leaves.reserve(t.leaves());
    for (std::uint32_t i = 0; i < m; ++i)
        if (t.nodes[i].is_leaf()) leaves.push_back(i);
    for (int round = 0; round < rounds && t.leaves() >= 3 && t.root != none; ++round) {
        const std::uint64_t threshold = std::uint64_t(gamma) << std::min(round, 32);
        std::fill(arrivals.begin(), arrivals.end(), 0u);
        // The bottom-up pass (Karras and Aila, section 5): a task per leaf climbs towards the root; the
        // second child to arrive at a node finds both subtrees final and processes the node.
        parallel_for_chunks(leaves.size(), 1024, [&](std::size_t begin, std::size_t end) {
            std::vector<aabb> boxes;
            std::vector<float> costs;
            for (std::size_t k = begin; k < end; ++k) {
                const std::uint32_t leaf = leaves[k];
                s.count[leaf] = 1;
                s.cost[leaf] = c.intersection * t.nodes[leaf].box.surface_area();
                for (std::uint32_t i = t.nodes[leaf].parent; i != none; i = t.nodes[i].parent) {
                    if (std::atomic_ref<std::uint32_t>(arrivals[i]).fetch_add(1, std::memory_order_acq_rel) == 0)
                        break;
                    const tree_node& node = t.nodes[i];
                    s.count[i] = s.count[node.left] + s.count[node.right];
                    s.cost[i] = c.traversal * node.box.surface_area() + (s.cost[node.left] + s.cost[node.right]);
                    if (s.count[i] < threshold) continue;
                    // Form the treelet, optimise it, rewire it where that pays.
                    const treelet tl = form_treelet(t, i, n_leaves);
                    formed.fetch_add(1, std::memory_order_relaxed);
                    if (tl.leaves.size() < 3) continue;  // two leaves: one topology only
                    boxes.clear(), costs.clear();
                    for (const std::uint32_t l : tl.leaves) boxes.push_back(t.nodes[l].box), costs.push_back(s.cost[l]);
                    const treelet_shape shape = optimize(boxes, costs);
                    if (!(shape.cost < s.cost[i] * (1.0f - 1e-5f))) continue;
                    rewire(t, tl, shape, c, s);
                    rewired.fetch_add(1, std::memory_order_relaxed);
                }
            }
        });
    }
    if (report) {
        report->treelets += formed.load(), report->rewired += rewired.load();
        report->ms += clock.milliseconds();
    }
}

void restructure_trbvh(binary_tree& t, const trbvh_params& p, treelet_report* report) {
    const int n = std::clamp(p.treelet_leaves, 3, max_dp_leaves);
    const ch05::sah_costs c = p.costs;
    restructure_treelets(t, n, p.rounds, p.gamma, c, [c](std::span<const aabb> boxes, std::span<const float> costs) {
        return shape_from_partitions(subset_costs(boxes, costs, c), int(boxes.size()));
    }, report);
}

}  // namespace strahl::ch08
