// The chapter's figure, computed by the chapter's own code (`ch08 --diagrams DIR`):
//   treelet.svg: ten primitives in three clusters, the middle one straddling the line where the Morton
//   codes' highest bit flips; chapter 07's LBVH over them (lbvh_binary_tree), the root's treelet of five
//   leaves (form_treelet, exercise 08.1) as the LBVH built it, and rewired into the topology of least SAH
//   cost found by the subset DP (subset_costs, 08.2), with every node's surface area and both costs;
//   ploc.svg: one round of PLOC over fourteen boxes in the plane: their Morton order (chapter 07's codes,
//   radix sorted, as build_ploc sorts them), each cluster's nearest neighbour within r = 2 positions
//   along the curve (ploc_nearest_neighbours, the builder's own step 3a), the mutual pairs that merge,
//   and the cluster list after the merge and compaction.
#include "strahl/ch07/morton.hpp"
#include "strahl/ch07/radix_sort.hpp"
#include "strahl/ch08/binary_tree.hpp"
#include "strahl/ch08/ploc.hpp"
#include "strahl/ch08/treelet.hpp"
#include "strahl/diagram.hpp"
#include <algorithm>
#include <cstdio>
#include <bit>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace strahl::ch08 {

namespace {

// C_T * inner areas + C_I * leaf areas below node n: the cost the DP gives a treelet leaf (C_T = C_I = 1).
double subtree_cost(const binary_tree& t, std::uint32_t n) {
    const tree_node& x = t.nodes[n];
    if (x.is_leaf()) return x.box.surface_area();
    return x.box.surface_area() + subtree_cost(t, x.left) + subtree_cost(t, x.right);
}

// A drawn tree: nodes with a label and an area, children by index; leaves are drawn side by side in
// depth-first order, each inner node above the middle of its children.
struct drawn_node {
    std::string label;
    double area = 0;
    int left = -1, right = -1;
    const char* colour = ink::black;
};

void draw_tree(diagram& d, const std::vector<drawn_node>& nodes, int root, double left, double top, double width,
               int leaves) {
    std::map<int, point2> at;
    int next_leaf = 0;
    const std::function<double(int, int)> place = [&](int n, int depth) {
        const drawn_node& x = nodes[std::size_t(n)];
        double cx;
        if (x.left < 0) cx = left + 30 + (width - 60) * next_leaf++ / double(leaves - 1);
        else cx = 0.5 * (place(x.left, depth + 1) + place(x.right, depth + 1));
        at[n] = {cx, top + 62.0 * depth};
        return cx;
    };
    place(root, 0);
    for (const auto& [n, p] : at) {
        const drawn_node& x = nodes[std::size_t(n)];
        if (x.left < 0) continue;
        for (const int c : {x.left, x.right}) d.line(p.x, p.y + 18, at[c].x, at[c].y - 18, {ink::grey, "none", 1.5});
    }
    for (const auto& [n, p] : at) {
        const drawn_node& x = nodes[std::size_t(n)];
        const bool leaf = x.left < 0;
        d.rect(p.x - 27, p.y - 18, p.x + 27, p.y + 18, {x.colour, leaf ? ink::pale_grey : ink::pale_blue, 1.5});
        d.text(p.x, p.y - 3, x.label, {13, "middle", ink::black, true});
        d.text(p.x, p.y + 12, number_text(x.area), {11, "middle"});
    }
}

diagram treelet_figure() {
    // Three clusters of thin boxes in the plane (z from 0 to 0.1): left, right, and one in the middle.
    std::vector<aabb> boxes;
    const auto add = [&](float x, float y, float w, float h) { boxes.push_back({vec3(x, y, 0), vec3(x + w, y + h, 0.1f)}); };
    add(0.2f, 6.0f, 0.8f, 0.6f), add(0.9f, 6.8f, 0.7f, 0.7f), add(0.4f, 7.3f, 0.6f, 0.5f);
    add(3.0f, 1.0f, 0.6f, 0.8f), add(3.5f, 1.6f, 0.6f, 0.6f), add(4.1f, 1.1f, 0.6f, 0.7f), add(4.6f, 1.7f, 0.6f, 0.6f);
    add(7.0f, 6.1f, 0.7f, 0.6f), add(7.4f, 6.9f, 0.5f, 0.7f), add(6.8f, 7.4f, 0.7f, 0.5f);
    std::vector<vec3> centroids;
    for (const aabb& b : boxes) centroids.push_back(b.centroid());
    const binary_tree t = lbvh_binary_tree(boxes, centroids);
    const treelet tl = form_treelet(t, t.root, 5);
    const int n = int(tl.leaves.size());

    // The treelet's leaves: their boxes and subtree costs, named A, B, ... in the treelet's order.
    std::vector<aabb> leaf_boxes;
    std::vector<float> leaf_costs;
    for (const std::uint32_t l : tl.leaves) {
        leaf_boxes.push_back(t.nodes[l].box);
        leaf_costs.push_back(float(subtree_cost(t, l)));
    }
    const char* colours[] = {ink::blue, ink::red, ink::green, ink::orange, ink::purple};
    const auto leaf_label = [](int k) { return std::string(1, char('A' + k)); };

    // Before: the treelet as the LBVH built it, its inner nodes as they are in t.
    std::vector<drawn_node> before;
    std::map<std::uint32_t, int> index;
    for (int k = 0; k < n; ++k) {
        index[tl.leaves[std::size_t(k)]] = int(before.size());
        before.push_back({leaf_label(k), leaf_costs[std::size_t(k)], -1, -1, colours[k % 5]});
    }
    double cost_before = 0;
    for (const std::uint32_t i : tl.inner) index[i] = int(before.size()), before.push_back({"", t.nodes[i].box.surface_area()});
    for (const std::uint32_t i : tl.inner) {
        drawn_node& x = before[std::size_t(index[i])];
        x.left = index[t.nodes[i].left], x.right = index[t.nodes[i].right];
        cost_before += x.area;
    }
    for (const float c : leaf_costs) cost_before += c;

    // After: the DP's topology, read off the partitions from the whole set down.
    const optimal_topology best = subset_costs(leaf_boxes, leaf_costs, ch05::sah_costs{});
    std::vector<drawn_node> after;
    const std::function<int(unsigned)> build = [&](unsigned set) {
        if ((set & (set - 1)) == 0) {
            const int k = std::countr_zero(set);
            after.push_back({leaf_label(k), leaf_costs[std::size_t(k)], -1, -1, colours[k % 5]});
            return int(after.size() - 1);
        }
        aabb box;
        for (int k = 0; k < n; ++k)
            if (set >> k & 1) box.grow(leaf_boxes[std::size_t(k)]);
        const int me = int(after.size());
        after.push_back({"", box.surface_area()});
        const int l = build(best.partition[set]), r = build(set ^ best.partition[set]);
        after[std::size_t(me)].left = l, after[std::size_t(me)].right = r;
        return me;
    };
    const unsigned all = (1u << n) - 1;
    build(all);
    const double cost_after = best.cost[all];
    const auto label_inner = [](std::vector<drawn_node>& v, const std::string& prefix) {
        int k = 0;
        for (drawn_node& x : v)
            if (x.left >= 0) x.label = prefix + std::to_string(k++);
    };
    label_inner(before, "n");
    label_inner(after, "m");

    diagram d(1100, 470);
    const font title{15, "middle", ink::black, true}, body{13, "middle"};
    d.text(190, 24, "ten primitives, the treelet's five leaves", title);
    d.text(545, 24, "the root's treelet, as the LBVH built it", title);
    d.text(905, 24, "rewired: the subset DP's least cost", title);
    // Left: the primitives (grey) and the treelet leaves' boxes, in their colours.
    d.view(0, 0, 8, 8, 20, 45, 340, 340);
    for (const aabb& b : boxes) d.rect(b.min.x, b.min.y, b.max.x, b.max.y, {ink::grey, ink::pale_grey, 1.0});
    for (int k = 0; k < n; ++k) {
        const aabb& b = leaf_boxes[std::size_t(k)];
        d.rect(b.min.x - 0.06, b.min.y - 0.06, b.max.x + 0.06, b.max.y + 0.06, {colours[k % 5], "none", 2.5});
        d.text(b.min.x, b.max.y + 0.15, leaf_label(k), {14, "start", colours[k % 5], true, true});
    }
    const aabb centroid_box = [&] {
        aabb c;
        for (const vec3& p : centroids) c.grow(p);
        return c;
    }();
    const double mid_x = 0.5 * (centroid_box.min.x + centroid_box.max.x);
    d.line(mid_x, 0.2, mid_x, 7.8, {ink::black, "none", 1.5, true});
    d.pixels();
    d.text(190, 410, "dashed: where the codes' highest bit (x's) flips;", body);
    d.text(190, 428, "the LBVH's root splits the middle cluster there", body);
    // Middle and right: the two trees, leaf costs under the leaves, areas under the inner nodes.
    draw_tree(d, before, index[tl.root], 380, 70, 330, n);
    draw_tree(d, after, 0, 740, 70, 330, n);
    d.arrow(700, 60, 760, 60, {ink::black, "none", 2.0});
    d.text(545, 410, "cost " + number_text(cost_before), {14, "middle", ink::black, true});
    d.text(905, 410, "cost " + number_text(cost_after), {14, "middle", ink::red, true});
    d.text(725, 440, "cost = sum of the inner nodes' areas + the leaves' subtree costs (C_T = C_I = 1);", body);
    d.text(725, 458, "the five leaves' subtrees stay whole, only the four inner nodes above them are rewired", body);
    return d;
}

diagram ploc_figure() {
    // Fourteen boxes in the plane (z from 0 to 0.1), loosely in three groups.
    const float at[14][2] = {{0.5f, 0.6f}, {1.6f, 0.9f}, {1.0f, 2.0f}, {2.4f, 2.3f}, {0.4f, 3.4f}, {1.3f, 4.4f},
                             {2.6f, 4.0f}, {5.2f, 0.8f}, {6.4f, 1.5f}, {5.6f, 2.6f}, {6.9f, 3.3f}, {4.4f, 4.6f},
                             {5.8f, 4.4f}, {6.8f, 5.0f}};
    std::vector<aabb> boxes;
    std::vector<vec3> centroids;
    for (const auto& p : at) {
        boxes.push_back({vec3(p[0], p[1], 0.0f), vec3(p[0] + 0.6f, p[1] + 0.45f, 0.1f)});
        centroids.push_back(boxes.back().centroid());
    }
    // Step 1 of build_ploc: Morton codes of the centroids, radix sorted.
    ch07::morton_codes codes = ch07::compute_morton_codes(boxes, centroids, 10);
    ch07::radix_sort_params sort;
    sort.key_bits = 30;
    ch07::radix_sort(codes.keys, codes.ids, sort);
    std::vector<aabb> ordered;
    for (const std::uint32_t id : codes.ids) ordered.push_back(boxes[id]);
    const int m = int(ordered.size()), radius = 2;
    const std::vector<std::uint32_t> nn = ploc_nearest_neighbours(ordered, radius);
    const auto mutual = [&](int i) { return int(nn[std::size_t(nn[std::size_t(i)])]) == i; };
    const char* colours[] = {ink::blue, ink::red, ink::green, ink::orange, ink::purple};
    std::vector<int> pair_colour(std::size_t(m), -1);
    int pairs = 0;
    for (int i = 0; i < m; ++i)
        if (mutual(i) && i < int(nn[std::size_t(i)])) pair_colour[std::size_t(i)] = pair_colour[nn[std::size_t(i)]] = pairs++ % 5;

    diagram d(1100, 500);
    const font title{15, "middle", ink::black, true}, body{13, "middle"};
    d.text(550, 24, "One round of PLOC: nearest neighbours within r = 2 positions along the Morton curve", title);
    // Left: the boxes in the plane, numbered in curve order, the curve, the pairs that merge.
    d.view(0.0, 0.2, 7.8, 5.8, 20, 50, 420, 360);
    std::vector<point2> curve;
    for (const aabb& b : ordered) curve.push_back({b.centroid().x, b.centroid().y});
    for (std::size_t k = 1; k < curve.size(); ++k)
        d.line(curve[k - 1].x, curve[k - 1].y, curve[k].x, curve[k].y, {ink::grey, "none", 1.2, true});
    for (int i = 0; i < m; ++i) {
        const aabb& b = ordered[std::size_t(i)];
        const int c = pair_colour[std::size_t(i)];
        d.rect(b.min.x, b.min.y, b.max.x, b.max.y, {c < 0 ? ink::black : colours[c], c < 0 ? ink::pale_grey : "white", 1.5});
        d.text(b.centroid().x, b.centroid().y - 0.09, std::to_string(i), {12, "middle", ink::black, true});
        if (c >= 0 && i < int(nn[std::size_t(i)])) {
            const aabb u = unite(b, ordered[nn[std::size_t(i)]]);
            d.rect(u.min.x - 0.08, u.min.y - 0.08, u.max.x + 0.08, u.max.y + 0.08, {colours[c], "none", 1.5, true});
        }
    }
    d.pixels();
    d.text(230, 435, "boxes numbered along the Morton curve (dashed);", body);
    d.text(230, 452, "dashed frames: the pairs that merge this round", body);

    // Right: the cluster list, each position's nearest neighbour as an arrow, then the list after.
    const double left = 480, cell = 42, row1 = 200, row2 = 360;
    d.text(left + cell * m / 2, row1 - 120, "the cluster list in curve order: each looks 2 positions either way", body);
    for (int i = 0; i < m; ++i) {
        const double x = left + cell * i;
        const int c = pair_colour[std::size_t(i)];
        d.rect(x, row1, x + cell - 4, row1 + 30, {c < 0 ? ink::black : colours[c], c < 0 ? ink::pale_grey : "white", 1.5});
        d.text(x + cell / 2 - 2, row1 + 20, std::to_string(i), {13, "middle", ink::black, true});
        const double xj = left + cell * nn[std::size_t(i)];
        const bool right = nn[std::size_t(i)] > std::uint32_t(i);
        d.arrow(x + cell / 2 - 2 + (right ? 4 : -4), row1 - 2, xj + cell / 2 - 2 + (right ? -4 : 4), row1 - 2,
                {c < 0 ? ink::grey : colours[c], "none", 1.4}, right ? 28.0 : -28.0);
    }
    d.text(left + cell * m / 2, row1 + 55, "an arrow: the neighbour whose box with it has the least surface area;", body);
    d.text(left + cell * m / 2, row1 + 72, "two arrows between one pair (mutual): the pair merges into one cluster", body);
    // After: merged pairs as one cluster at the lower position, the rest in order (compaction).
    int out = 0;
    for (int i = 0; i < m; ++i) {
        const int j = int(nn[std::size_t(i)]);
        if (mutual(i) && j < i) continue;
        const double x = left + cell * out++;
        const int c = pair_colour[std::size_t(i)];
        const std::string label = c >= 0 ? std::to_string(i) + "+" + std::to_string(j) : std::to_string(i);
        d.rect(x, row2, x + cell - 4, row2 + 30, {c < 0 ? ink::black : colours[c], c < 0 ? ink::pale_grey : "white", 1.5});
        d.text(x + cell / 2 - 2, row2 + 20, label, {c >= 0 ? 11.0 : 13.0, "middle", ink::black, true});
    }
    d.text(left + cell * m / 2, row2 + 55, std::to_string(m) + " clusters become " + std::to_string(out) +
                                               ", still in curve order; the next round searches again", body);
    return d;
}

}  // namespace

std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force) {
    return write_figures(folder, force, {{"treelet.svg", treelet_figure}, {"ploc.svg", ploc_figure}});
}

}  // namespace strahl::ch08
