// Walks over a built k-d tree: its SAH cost (MacDonald and Booth, "Heuristics for ray tracing using space
// subdivision", 1990) and the split planes of its first levels, for drawing.
#include "strahl/ch03/kd_tree.hpp"

namespace strahl::ch03 {

namespace {

double cost_below(const kd_tree& t, std::uint32_t index, const aabb& box) {
    const kd_node& n = t.nodes[index];
    const double area = box.surface_area();
    if (n.is_leaf()) return double(t.sah.c_intersect) * double(n.count) * area;
    aabb left = box, right = box;
    left.max[n.axis()] = n.split;
    right.min[n.axis()] = n.split;
    return double(t.sah.c_traversal) * area + cost_below(t, n.left(), left) + cost_below(t, n.left() + 1, right);
}

void planes_below(const kd_tree& t, std::uint32_t index, const aabb& box, int level, int levels,
                  std::vector<kd_plane>& out) {
    const kd_node& n = t.nodes[index];
    if (n.is_leaf() || level >= levels) return;
    const int a = n.axis(), u = (a + 1) % 3, v = (a + 2) % 3;
    kd_plane p{level, a, {}};
    for (int k = 0; k < 4; ++k) {
        vec3 c;
        c[a] = n.split;
        c[u] = (k == 1 || k == 2) ? box.max[u] : box.min[u];
        c[v] = (k >= 2) ? box.max[v] : box.min[v];
        p.corners[k] = c;
    }
    out.push_back(p);
    aabb left = box, right = box;
    left.max[a] = n.split;
    right.min[a] = n.split;
    planes_below(t, n.left(), left, level + 1, levels, out);
    planes_below(t, n.left() + 1, right, level + 1, levels, out);
}

}  // namespace

double kd_tree::sah_cost() const {
    if (nodes.empty()) return 0.0;
    const double root_area = bounds.surface_area();
    if (!(root_area > 0.0)) return double(sah.c_intersect) * double(stats.references);
    return cost_below(*this, 0, bounds) / root_area;
}

std::vector<kd_plane> split_planes(const kd_tree& tree, int levels) {
    std::vector<kd_plane> out;
    if (!tree.nodes.empty()) planes_below(tree, 0, tree.bounds, 0, levels, out);
    return out;
}

}  // namespace strahl::ch03
