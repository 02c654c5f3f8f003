// The chapter's figures, drawn from the structures its code builds (`ch04 --diagrams DIR`):
//   subdivision.svg: space subdivision against object subdivision: chapter 02's uniform grid and this
//                    chapter's BVH over the same twelve triangles;
//   flattened.svg:   a small BVH as boxes in space, as a tree, and as the flat depth-first node array;
//   slab_test.svg:   the slab test: each axis's entry and exit t, and their overlap, for a hit and a miss.
// The triangles lie in the plane z = 0, so the boxes are rectangles and the pictures are exact.
#include "strahl/ch02/build.hpp"
#include "strahl/ch04/bvh.hpp"
#include "strahl/ch04/traverse.hpp"
#include "strahl/diagram.hpp"
#include "strahl/program.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace strahl::ch04 {

namespace {

using tri2 = std::array<point2, 3>;

// Small triangles around the given centres, of varied shape and turn.
std::vector<tri2> triangles_around(const std::vector<point2>& centres, double size) {
    std::vector<tri2> out;
    for (std::size_t i = 0; i < centres.size(); ++i) {
        tri2 t;
        for (int k = 0; k < 3; ++k) {
            const double angle = 1.3 * double(i) + 2.1 * double(k), r = size * (0.75 + 0.25 * double((i + k) % 3));
            t[k] = {centres[i].x + r * std::cos(angle), centres[i].y + r * std::sin(angle)};
        }
        out.push_back(t);
    }
    return out;
}

aabb box_of(const tri2& t) {
    aabb b;
    for (const point2& p : t) b.grow(vec3(float(p.x), float(p.y), 0.0f));
    return b;
}

struct inputs {
    std::vector<aabb> boxes;
    std::vector<vec3> centroids;
};
inputs inputs_of(const std::vector<tri2>& tris) {
    inputs in;
    for (const tri2& t : tris) {
        in.boxes.push_back(box_of(t));
        in.centroids.push_back(in.boxes.back().centroid());
    }
    return in;
}

std::string fixed(double v, int digits = 2) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

void draw_triangles(diagram& d, const std::vector<tri2>& tris) {
    for (const tri2& t : tris) d.polygon({t[0], t[1], t[2]}, {ink::orange, ink::pale_orange, 1.2});
}

void draw_box(diagram& d, const aabb& b, const pen& p, double grow_px = 0.0) {
    const double g = grow_px / d.scale();
    d.rect(b.min.x - g, b.min.y - g, b.max.x + g, b.max.y + g, p);
}

// The colours of the tree's levels: root, its children, their children, ...
const char* level_ink(int depth) {
    static const char* const inks[] = {ink::black, ink::blue, ink::green, ink::purple, ink::red};
    return inks[std::min(depth, 4)];
}
const char* level_fill(int depth) {
    static const char* const fills[] = {ink::pale_grey, ink::pale_blue, ink::pale_green, ink::pale_purple, ink::pale_red};
    return fills[std::min(depth, 4)];
}

// Depth of each node of the flat tree (left child index + 1, right child offset).
std::vector<int> node_depths(const bvh& t) {
    std::vector<int> depth(t.nodes.size(), 0);
    for (std::size_t i = 0; i < t.nodes.size(); ++i)
        if (!t.nodes[i].is_leaf()) depth[i + 1] = depth[t.nodes[i].offset] = depth[i] + 1;
    return depth;
}

// The tree's boxes, each level in its colour, the root dashed. A box is drawn 3 pixels larger per level above
// the deepest, so that a parent stays visible where it shares an edge with its child (leaves are exact).
void draw_tree_boxes(diagram& d, const bvh& t, const std::vector<int>& depth) {
    const int deepest = *std::max_element(depth.begin(), depth.end());
    for (std::size_t i = 0; i < t.nodes.size(); ++i)
        draw_box(d, t.nodes[i].box(), {level_ink(depth[i]), "none", depth[i] == 0 ? 2.0 : 1.6, depth[i] == 0},
                 3.0 * (deepest - depth[i]));
}

// 1. Space against objects: the same triangles in a grid's cells and in a BVH's boxes.
diagram subdivision() {
    const std::vector<tri2> tris = triangles_around(
        {{1.0, 1.0}, {2.1, 1.5}, {1.3, 2.5}, {2.9, 0.8}, {3.1, 2.3}, {2.2, 3.3}, {6.2, 4.3}, {8.6, 1.4},
         {10.3, 6.4}, {11.1, 5.5}, {9.5, 5.9}, {4.9, 6.6}}, 0.5);
    const inputs in = inputs_of(tris);
    aabb scene;
    for (const aabb& b : in.boxes) scene.grow(b);

    // Chapter 02's grid: lambda N cells (lambda = 4, its default), as square as the box allows. (The scene is
    // flat, so the heuristic is taken in two dimensions: one cell in z, the rest in x and y.)
    ch02::grid_dims g;
    const vec3 ext = scene.extent();
    const double per_unit = std::sqrt(4.0 * double(tris.size()) / (double(ext.x) * double(ext.y)));
    g.res = ch02::ivec3(std::max(1, int(std::lround(ext.x * per_unit))), std::max(1, int(std::lround(ext.y * per_unit))), 1);
    g.box = {vec3(scene.min.x, scene.min.y, -1.0f), vec3(scene.max.x, scene.max.y, 1.0f)};
    g.cell_size = (g.box.max - g.box.min) / vec3(g.res);
    g.inv_cell_size = vec3(g.res) / (g.box.max - g.box.min);
    const ch02::grid_cells cells = ch02::fill_cells(g, in.boxes);
    const bvh tree = build_bvh(in.boxes, in.centroids, {split_method::object_median, 3});

    diagram d(720, 370);
    const double pad = 0.25;
    const font title{15, "middle", ink::black, true};
    d.text(185, 24, "space: chapter 02's uniform grid", title);
    d.text(545, 24, "objects: this chapter's BVH", title);
    // Left: cells shaded by the triangles they hold.
    d.view(scene.min.x - pad, scene.min.y - pad, scene.max.x + pad, scene.max.y + pad, 15, 40, 340, 220);
    static const char* const shades[] = {"#ffffff", "#dbe9f6", "#a9cbea", "#6fa6d6"};
    std::size_t empty = 0;
    for (int y = 0; y < g.res.y; ++y)
        for (int x = 0; x < g.res.x; ++x) {
            const int c = g.index({x, y, 0});
            const std::uint32_t n = cells.offsets[c + 1] - cells.offsets[c];
            empty += n == 0;
            const aabb cb = g.cell_box({x, y, 0});
            draw_box(d, cb, {ink::grey, shades[std::min<std::uint32_t>(n, 3)], 0.8});
        }
    draw_triangles(d, tris);
    // Right: the BVH's boxes, leaves shaded, each level in its colour.
    d.view(scene.min.x - pad, scene.min.y - pad, scene.max.x + pad, scene.max.y + pad, 375, 40, 340, 220);
    const std::vector<int> depth = node_depths(tree);
    for (std::size_t i = 0; i < tree.nodes.size(); ++i)
        if (tree.nodes[i].is_leaf()) draw_box(d, tree.nodes[i].box(), {"none", level_fill(depth[i]), 0.0});
    draw_triangles(d, tris);
    draw_tree_boxes(d, tree, depth);

    d.pixels();
    const font body{13, "middle"};
    d.text(185, 290, std::to_string(g.res.x) + " x " + std::to_string(g.res.y) + " equal cells, " +
                         std::to_string(empty) + " of them empty;", body);
    d.text(185, 310, "a triangle goes into every cell its box overlaps:", body);
    d.text(185, 330, std::to_string(cells.prims.size()) + " references for " + std::to_string(tris.size()) +
                         " triangles", body);
    // The legend of the cells' shades.
    d.text(40, 356, "triangles per cell:", {12, "start", ink::grey});
    for (int k = 0; k < 4; ++k) {
        d.rect(160 + 45.0 * k, 345, 174 + 45.0 * k, 359, {ink::grey, shades[k], 0.8});
        d.text(179 + 45.0 * k, 356, k == 3 ? "3+" : std::to_string(k), {12, "start", ink::grey});
    }
    int inner = 0;
    for (const bvh_node& node : tree.nodes) inner += !node.is_leaf();
    d.text(545, 290, std::to_string(tree.nodes.size()) + " boxes: the root (dashed), " + std::to_string(inner - 1) +
                         " inner (blue),", body);
    d.text(545, 310, std::to_string(tree.nodes.size() - inner) + " leaves (green): each triangle in one leaf,", body);
    d.text(545, 330, std::to_string(tree.prim_ids.size()) + " references; the boxes fit the triangles", body);
    d.text(545, 350, "and may overlap", body);
    return d;
}

// 2. A BVH in space, as a tree, and as the flat array the traversal reads.
diagram flattened() {
    const std::vector<tri2> tris = triangles_around(
        {{1.0, 1.2}, {2.4, 0.8}, {1.6, 3.0}, {0.9, 4.2}, {6.8, 1.0}, {8.2, 1.9}, {6.4, 3.9}, {7.9, 4.6}}, 0.55);
    const inputs in = inputs_of(tris);
    const bvh tree = build_bvh(in.boxes, in.centroids, {split_method::object_median, 2});
    const std::vector<int> depth = node_depths(tree);
    const std::size_t n = tree.nodes.size();

    diagram d(720, 560);
    const font title{15, "middle", ink::black, true};
    d.text(185, 24, "the boxes in space", title);
    d.text(545, 24, "the tree", title);
    // Boxes in space, numbered by their slot in the array.
    const aabb& root = tree.bounds;
    d.view(root.min.x - 0.4, root.min.y - 0.4, root.max.x + 0.4, root.max.y + 0.4, 15, 40, 340, 230);
    draw_triangles(d, tris);
    draw_tree_boxes(d, tree, depth);
    for (std::size_t i = 0; i < n; ++i) {
        const aabb b = tree.nodes[i].box();
        const bool leaf = tree.nodes[i].is_leaf();
        // Leaves are numbered inside their top left corner, inner boxes above it (the root left of it).
        const double s = d.scale();
        const point2 at = i == 0 ? point2{b.min.x - 22.0 / s, b.max.y - 4.0 / s}
                          : leaf ? point2{b.min.x + 3.0 / s, b.max.y - 14.0 / s}
                                 : point2{b.min.x - 3.0 / s, b.max.y + 7.0 / s};
        d.text(at.x, at.y, std::to_string(i), {13, "start", level_ink(depth[i]), true, true});
    }

    // The tree: leaves side by side in depth-first order, each inner node above the middle of its children.
    d.pixels();
    std::vector<point2> at(n);
    double next_leaf = 0.0;
    int leaves = 0;
    for (const bvh_node& node : tree.nodes) leaves += node.is_leaf();
    const double left = 395, right = 695, step = (right - left) / std::max(1, leaves - 1);
    int max_depth = 0;
    for (int k : depth) max_depth = std::max(max_depth, k);
    for (std::size_t k = 0; k < n; ++k) {  // leaves in array order are the depth-first order
        at[k].y = 70 + 170.0 * depth[k] / std::max(1, max_depth);
        if (tree.nodes[k].is_leaf()) at[k].x = left + step * next_leaf++;
    }
    for (std::size_t k = n; k-- > 0;)  // children come after their parent: inner nodes bottom up
        if (!tree.nodes[k].is_leaf()) at[k].x = 0.5 * (at[k + 1].x + at[tree.nodes[k].offset].x);
    for (std::size_t k = 0; k < n; ++k)
        if (!tree.nodes[k].is_leaf())
            for (std::size_t c : {k + 1, std::size_t(tree.nodes[k].offset)})
                d.line(at[k].x, at[k].y, at[c].x, at[c].y, {ink::grey, "none", 1.5});
    for (std::size_t k = 0; k < n; ++k) {
        d.circle(at[k].x, at[k].y, 15, {level_ink(depth[k]), level_fill(depth[k]), 2.0});
        d.text(at[k].x, at[k].y + 5, std::to_string(k), {14, "middle", ink::black, true});
        if (tree.nodes[k].is_leaf()) {
            const std::uint32_t first = tree.nodes[k].offset;
            std::string ids;
            for (std::uint32_t j = first; j < first + tree.nodes[k].count; ++j)
                ids += (ids.empty() ? "" : ", ") + std::to_string(tree.prim_ids[j]);
            d.text(at[k].x, at[k].y + 34, "tri " + ids, {12, "middle", ink::grey});
        }
    }

    // The flat array: one 32-byte node per slot, depth first.
    d.text(360, 318, "the flat array, depth first: left child = next slot, right child = offset", title);
    const double x0 = 25, w = 670.0 / double(n), top = 395, h = 74;
    for (std::size_t k = 0; k < n; ++k) {
        const bvh_node& node = tree.nodes[k];
        const double x = x0 + w * double(k), cx = x + 0.5 * w;
        d.rect(x, top, x + w, top + h, {ink::black, level_fill(depth[k]), 1.2});
        d.text(cx, top + h + 18, "[" + std::to_string(k) + "]", {13, "middle", ink::black, true});
        const font small{12, "middle"};
        if (node.is_leaf()) {
            d.text(cx, top + 20, "leaf", {12, "middle", ink::black, true});
            d.text(cx, top + 40, "offset " + std::to_string(node.offset), small);
            d.text(cx, top + 58, "count " + std::to_string(node.count), small);
        } else {
            d.text(cx, top + 20, "inner", {12, "middle", ink::black, true});
            d.text(cx, top + 40, "offset " + std::to_string(node.offset), small);
            d.text(cx, top + 58, std::string("axis ") + "xyz"[node.axis] + ", count 0", small);
        }
    }
    // Arrows from each inner node to its right child's slot, above the array; higher for longer jumps.
    for (std::size_t k = 0; k < n; ++k) {
        if (tree.nodes[k].is_leaf()) continue;
        const double from = x0 + w * (double(k) + 0.5), to = x0 + w * (double(tree.nodes[k].offset) + 0.5);
        const double span = double(tree.nodes[k].offset - k);
        d.arrow(from + 8, top - 2, to - 8, top - 2, {ink::red, "none", 1.6}, 16.0 + 14.0 * span);
    }
    d.text(360, 522, "a leaf's triangles are prim_ids[offset, offset + count); an inner node's left child needs no "
                     "index", {13, "middle"});
    std::string ids;
    for (std::uint32_t id : tree.prim_ids) ids += (ids.empty() ? "" : " ") + std::to_string(id);
    d.text(360, 545, "prim_ids, reordered in place by the build: " + ids, {13, "middle"});
    return d;
}

// 3. The slab test: per axis the t where the ray enters and leaves the slab between the box's two planes;
// it meets the box where all the slabs' intervals overlap, [max of entries, min of exits].
void slab_panel(diagram& d, double left, const vec3& org, const vec3& dir, const aabb& box) {
    const double wx0 = -2.0, wy0 = -1.2, wx1 = 8.5, wy1 = 6.2, width = 345;
    d.view(wx0, wy0, wx1, wy1, left, 40, width, 250);
    // The slabs, drawn across the whole window; their overlap is the box.
    d.rect(box.min.x, wy0, box.max.x, wy1, {"none", ink::pale_blue, 0.0, false, 0.7});
    d.rect(wx0, box.min.y, wx1, box.max.y, {"none", ink::pale_orange, 0.0, false, 0.7});
    draw_box(d, box, {ink::black, "none", 2.0});
    d.text(0.5 * (box.min.x + box.max.x), wy1 - 0.45, "x-slab", {13, "middle", ink::blue, true});
    d.text(wx0 + 0.1, box.max.y - 0.45, "y-slab", {13, "start", ink::orange, true});
    // The ray's t per plane; entries and exits ordered per axis (the direction may point either way).
    double t_in[2], t_out[2];
    for (int a = 0; a < 2; ++a) {
        const double t0 = (box.min[a] - org[a]) / dir[a], t1 = (box.max[a] - org[a]) / dir[a];
        t_in[a] = std::min(t0, t1), t_out[a] = std::max(t0, t1);
    }
    const double enter = std::max(t_in[0], t_in[1]), leave = std::min(t_out[0], t_out[1]);
    // The chapter's slab test (exercise 04.1) gives the verdict.
    const bool hit = slab_test(box, org, 1.0f / dir, 0.0f, 100.0f);
    // The ray to the window's edge.
    double t_end = 100.0;
    for (int a = 0; a < 2; ++a) {
        const double lo = a == 0 ? wx0 : wy0, hi = a == 0 ? wx1 : wy1;
        t_end = std::min(t_end, ((dir[a] > 0 ? hi : lo) - org[a]) / dir[a]);
    }
    const auto p = [&](double t) { return point2{org.x + t * dir.x, org.y + t * dir.y}; };
    const point2 e = p(t_end - 0.05);
    d.arrow(org.x, org.y, e.x, e.y, {ink::black, "none", 1.6});
    d.circle(org.x, org.y, 4, {ink::black, ink::black, 1.0});
    if (hit) {
        const point2 a = p(enter), b = p(leave);
        d.line(a.x, a.y, b.x, b.y, {ink::green, "none", 5.0});
    }
    const char* names[2][2] = {{"tx0", "tx1"}, {"ty0", "ty1"}};
    const char* colours[2] = {ink::blue, ink::orange};
    for (int a = 0; a < 2; ++a)
        for (int k = 0; k < 2; ++k) {
            const point2 q = p(k == 0 ? t_in[a] : t_out[a]);
            d.circle(q.x, q.y, 4.5, {ink::black, colours[a], 1.0});
            // x-plane crossings labelled right of the point, y-plane crossings above and left of it.
            const double s = d.scale();
            d.text(q.x + (a == 0 ? 8.0 : -8.0) / s, q.y + (a == 0 ? -4.0 : 6.0) / s, names[a][k],
                   {13, a == 0 ? "start" : "end", colours[a], true, true});
        }

    // Below: the three intervals on the t axis.
    d.pixels();
    const double axis_left = left + 62, axis_right = left + width - 18, t_max = 10.0;
    const auto px = [&](double t) { return axis_left + (axis_right - axis_left) * t / t_max; };
    const double row0 = 306;
    const auto interval = [&](int row, const std::string& name, double a, double b, const char* colour) {
        const double y = row0 + 24.0 * row;
        d.text(left + 4, y + 19, name, {12, "start", colour, true});
        d.rect(px(a), y + 12, px(b), y + 20, {"none", colour, 0.0});
        d.text(px(a), y + 9, fixed(a), {11, "middle", colour});
        d.text(px(b), y + 9, fixed(b), {11, "middle", colour});
    };
    interval(0, "x-slab", t_in[0], t_out[0], ink::blue);
    interval(1, "y-slab", t_in[1], t_out[1], ink::orange);
    const double y3 = row0 + 48;
    if (hit) interval(2, "inside", enter, leave, ink::green);
    else d.text(left + 4, y3 + 19, "inside: none", {12, "start", ink::red, true});
    d.line(axis_left, y3 + 30, axis_right, y3 + 30, {ink::grey, "none", 1.0});
    for (int t = 0; t <= int(t_max); t += 2) {
        d.line(px(t), y3 + 27, px(t), y3 + 33, {ink::grey, "none", 1.0});
        d.text(px(t), y3 + 46, std::to_string(t), {11, "middle", ink::grey});
    }
    d.text(axis_right + 8, y3 + 34, "t", {13, "start", ink::grey, true});
    const std::string verdict = hit ? "max entry " + fixed(enter) + " <= min exit " + fixed(leave) + ": a hit"
                                    : "max entry " + fixed(enter) + " > min exit " + fixed(leave) + ": a miss";
    d.text(left + width / 2, 418, verdict, {13, "middle", hit ? ink::green : ink::red, true});
}

diagram slab_figure() {
    diagram d(720, 430);
    const aabb box{vec3(2, 2, -1), vec3(6, 4.5, 1)};
    const font title{15, "middle", ink::black, true};
    d.text(185, 24, "a hit: the intervals overlap", title);
    d.text(545, 24, "a miss: it leaves y before entering x", title);
    slab_panel(d, 12, vec3(-1.5f, -1.0f, 0.0f), vec3(1.0f, 0.6f, 0.0f), box);
    slab_panel(d, 372, vec3(-1.5f, 0.7f, 0.0f), vec3(1.0f, 1.2f, 0.0f), box);
    return d;
}

}  // namespace

std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force) {
    return write_figures(folder, force, {{"subdivision.svg", subdivision}, {"flattened.svg", flattened},
                                         {"slab_test.svg", slab_figure}});
}

}  // namespace strahl::ch04
