// The index-form binary tree: its checks, its SAH cost, its refit, and the LBVH that starts the
// restructuring builders (FLATTEN is in flatten.cpp). Every walk here is iterative: a tree of one primitive
// per leaf may be thousands of levels deep before the collapse bounds it.
#include "strahl/ch08/binary_tree.hpp"
#include "strahl/ch07/lbvh.hpp"
#include "strahl/ch07/morton.hpp"
#include "strahl/ch07/radix_sort.hpp"
#include "strahl/ch07/radix_tree.hpp"
#include <algorithm>
#include <stdexcept>

namespace strahl::ch08 {

namespace {

// The nodes of the tree below `root` in post-order (children before their parent).
std::vector<std::uint32_t> post_order(const binary_tree& t, std::uint32_t root) {
    std::vector<std::uint32_t> order, stack;
    if (root == none) return order;
    order.reserve(t.nodes.size());
    stack.push_back(root);
    while (!stack.empty()) {  // reverse of (node, right, left) pre-order is post-order
        const std::uint32_t i = stack.back();
        stack.pop_back();
        order.push_back(i);
        if (!t.nodes[i].is_leaf()) stack.push_back(t.nodes[i].left), stack.push_back(t.nodes[i].right);
    }
    std::reverse(order.begin(), order.end());
    return order;
}

bool same_box(const aabb& a, const aabb& b) {
    for (int k = 0; k < 3; ++k)
        if (!(a.min[k] == b.min[k] && a.max[k] == b.max[k])) return false;
    return true;
}

}  // namespace

std::string check_tree(const binary_tree& t, std::span<const aabb> boxes) {
    std::vector<std::uint8_t> seen(boxes.size(), 0);
    for (const std::uint32_t id : t.loose) {
        if (id >= boxes.size() || seen[id]) return "loose id " + std::to_string(id) + " out of range or twice";
        seen[id] = 1;
    }
    if (t.root == none) return t.nodes.empty() && t.loose.size() == boxes.size() ? "" : "no root, but nodes or primitives";
    if (t.root >= t.nodes.size() || t.nodes[t.root].parent != none) return "the root is out of range or has a parent";
    if (t.nodes.size() % 2 == 0) return "an even number of nodes: not a full binary tree";
    std::vector<std::uint8_t> visited(t.nodes.size(), 0);
    std::size_t leaves = 0;
    for (const std::uint32_t i : post_order(t, t.root)) {
        if (i >= t.nodes.size() || visited[i]++) return "node " + std::to_string(i) + " out of range or reached twice";
        const tree_node& n = t.nodes[i];
        if (n.is_leaf()) {
            if (n.right != none) return "leaf " + std::to_string(i) + " has a right child";
            if (n.prim >= boxes.size() || seen[n.prim]) return "leaf " + std::to_string(i) + ": primitive out of range or twice";
            seen[n.prim] = 1, ++leaves;
            if (!same_box(n.box, boxes[n.prim])) return "leaf " + std::to_string(i) + ": box is not its primitive's";
            continue;
        }
        if (n.right == none || n.prim != none) return "inner node " + std::to_string(i) + " malformed";
        if (n.left >= t.nodes.size() || n.right >= t.nodes.size()) return "inner node " + std::to_string(i) + ": child out of range";
        if (t.nodes[n.left].parent != i || t.nodes[n.right].parent != i)
            return "inner node " + std::to_string(i) + ": a child's parent link is not it";
        if (!same_box(n.box, unite(t.nodes[n.left].box, t.nodes[n.right].box)))
            return "inner node " + std::to_string(i) + ": box is not the union of its children's";
    }
    if (std::find(visited.begin(), visited.end(), 0) != visited.end()) return "nodes not reachable from the root";
    if (leaves + t.loose.size() != boxes.size()) return "not every primitive is in the tree or loose";
    return "";
}

double binary_sah_cost(const binary_tree& t, const ch05::sah_costs& c) {
    if (t.root == none) return 0.0;
    const double root_area = t.nodes[t.root].box.surface_area();
    double sum = 0.0;
    for (const tree_node& n : t.nodes) {
        const double ratio = root_area > 0.0 ? double(n.box.surface_area()) / root_area : 1.0;
        sum += (n.is_leaf() ? c.intersection : c.traversal) * ratio;
    }
    return sum;
}

void refit(binary_tree& t) {
    for (const std::uint32_t i : post_order(t, t.root)) {
        tree_node& n = t.nodes[i];
        if (!n.is_leaf()) n.box = unite(t.nodes[n.left].box, t.nodes[n.right].box);
    }
}

binary_tree lbvh_binary_tree(std::span<const aabb> boxes, std::span<const vec3> centroids, int bits_per_axis) {
    if (boxes.size() != centroids.size()) throw std::invalid_argument("lbvh_binary_tree: one centroid per box");
    binary_tree t;
    ch07::morton_codes codes = ch07::compute_morton_codes(boxes, centroids, bits_per_axis);
    ch07::radix_sort_params sort;
    sort.key_bits = 3 * bits_per_axis;
    ch07::radix_sort(codes.keys, codes.ids, sort);
    t.loose = std::move(codes.loose);
    const std::size_t n = codes.ids.size();
    if (n == 0) return t;
    // Leaves first (0..n-1, in Morton order), then the radix tree's inner nodes (n..2n-2).
    t.nodes.resize(2 * n - 1);
    for (std::size_t k = 0; k < n; ++k) t.nodes[k].prim = codes.ids[k], t.nodes[k].box = boxes[codes.ids[k]];
    if (n == 1) {
        t.root = 0;
        return t;
    }
    ch07::radix_tree r;
    ch07::build_radix_tree_karras(codes.keys, r);
    const auto node_of = [&](std::uint32_t ref) {
        return ch07::is_leaf_ref(ref) ? (ref & ~ch07::leaf_bit) : std::uint32_t(n) + ref;
    };
    for (std::uint32_t i = 0; i + 1 < n; ++i) {
        tree_node& in = t.nodes[n + i];
        in.left = node_of(r.left[i]), in.right = node_of(r.right[i]);
        t.nodes[in.left].parent = std::uint32_t(n) + i, t.nodes[in.right].parent = std::uint32_t(n) + i;
    }
    t.root = std::uint32_t(n);  // inner node 0
    t.nodes[t.root].parent = none;
    refit(t);
    return t;
}

}  // namespace strahl::ch08
