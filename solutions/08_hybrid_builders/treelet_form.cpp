// Exercise 08.1 forming a treelet (8 points). Read: treelet.hpp; T. Karras and T. Aila, "Fast parallel
// construction of high-quality bounding volume hierarchies", HPG 2013, section 4.1.
#include "strahl/ch08/treelet.hpp"

namespace strahl::ch08 {

// 08.1: the treelet of `root`, grown by expanding its largest expandable leaf until it has n_leaves.
treelet form_treelet(const binary_tree& t, std::uint32_t root, int n_leaves) {
    treelet out;
    out.root = root;
    const tree_node& r = t.nodes[root];
    if (r.is_leaf()) {
        out.leaves.push_back(root);
        return out;
    }
    out.inner.push_back(root);
    out.leaves = {r.left, r.right};
    while (out.leaves.size() < std::size_t(n_leaves)) {
        // The treelet leaf of largest area that is an inner node of t; equal areas: the lower index.
        std::size_t best = out.leaves.size();
        float best_area = 0.0f;
        for (std::size_t k = 0; k < out.leaves.size(); ++k) {
            const tree_node& n = t.nodes[out.leaves[k]];
            if (n.is_leaf()) continue;
            const float area = n.box.surface_area();
            if (best == out.leaves.size() || area > best_area ||
                (area == best_area && out.leaves[k] < out.leaves[best]))
                best = k, best_area = area;
        }
        if (best == out.leaves.size()) break;  // only primitives' leaves left
        const std::uint32_t expanded = out.leaves[best];
        out.leaves.erase(out.leaves.begin() + std::ptrdiff_t(best));
        out.leaves.push_back(t.nodes[expanded].left);
        out.leaves.push_back(t.nodes[expanded].right);
        out.inner.push_back(expanded);
    }
    return out;
}

}  // namespace strahl::ch08
