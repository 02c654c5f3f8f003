// The chapter's figure, computed by the chapter's own code (`ch13 --diagrams DIR`):
//   collapse.svg: a binary tree over twelve triangles (chapter 05's binned SAH, one triangle per leaf) and
//   the 4-wide tree the greedy collapse makes of it (collapse<4, 4>; child_to_open is exercise 13.1): the
//   binary nodes each wide node absorbed share its colour (a dashed border: opened, gone; a solid one: a
//   child slot of the wide node); below, the wide root as it lies in memory, six rows of four floats (one
//   SIMD load each) and the child references.
#include "strahl/ch05/sah.hpp"
#include "strahl/ch13/wide_bvh.hpp"
#include "strahl/diagram.hpp"
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace strahl::ch13 {

namespace {

bool same_box(const ch04::bvh_node& n, const aabb& b) {
    const float lo[3] = {b.min.x, b.min.y, b.min.z}, hi[3] = {b.max.x, b.max.y, b.max.z};
    return std::memcmp(n.bmin, lo, sizeof lo) == 0 && std::memcmp(n.bmax, hi, sizeof hi) == 0;
}

diagram collapse_figure() {
    // Twelve small triangles in the plane z = 0, in three loose rows.
    triangle_mesh mesh;
    for (int i = 0; i < 12; ++i) {
        const float x = float(i % 4) * 2.0f + 0.3f * float(i / 4), y = float(i / 4) * 2.2f + 0.4f * float(i % 3);
        const auto v = std::uint32_t(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(), {vec3(x, y, 0), vec3(x + 1.0f, y + 0.2f, 0), vec3(x + 0.4f, y + 1.1f, 0)});
        mesh.indices.push_back(uvec3(v, v + 1, v + 2));
    }
    std::vector<aabb> boxes;
    std::vector<vec3> centroids;
    for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
        aabb b;
        for (const vec3& p : mesh.triangle(i)) b.grow(p);
        boxes.push_back(b);
        centroids.push_back(b.centroid());
    }
    ch05::sah_build_params one_per_leaf;
    one_per_leaf.max_leaf = 1;
    const ch04::bvh binary = ch05::build_sah_bvh_fast(boxes, centroids, one_per_leaf);
    const wide_bvh<4, 4> wide = collapse<4, 4>(binary, mesh);

    // Which wide node each binary node went into: a wide node's origin is the binary node whose box it
    // bounds; its slots hold the boxes of binary descendants (found by their bits), and the binary nodes
    // between the origin and a slot were opened inside it.
    const auto kids = [&](std::uint32_t b) {
        return std::array<std::uint32_t, 2>{b + 1, binary.nodes[b].offset};
    };
    std::vector<int> owner(binary.nodes.size(), -1);
    std::vector<bool> slot(binary.nodes.size(), false);
    // The binary node at or below b with the box's bits (depth first), or -1.
    const std::function<int(std::uint32_t, const aabb&)> find = [&](std::uint32_t b, const aabb& box) {
        if (same_box(binary.nodes[b], box)) return int(b);
        if (binary.nodes[b].is_leaf()) return -1;
        for (const std::uint32_t c : kids(b))
            if (const int f = find(c, box); f >= 0) return f;
        return -1;
    };
    // Below b down to the slots: opened inside wide node w (a leaf slot is w's too; an inner slot is the
    // origin of its own wide node, already assigned).
    const std::function<void(std::uint32_t, int)> paint = [&](std::uint32_t b, int w) {
        if (owner[b] < 0) owner[b] = w;
        if (!slot[b])
            for (const std::uint32_t c : kids(b)) paint(c, w);
    };
    const std::function<void(int, std::uint32_t)> assign = [&](int w, std::uint32_t origin) {
        const wide_node<4>& n = wide.nodes[std::size_t(w)];
        owner[origin] = w;
        for (int i = 0; i < 4; ++i) {
            if (!n.used(i)) continue;
            int s = find(origin + 1, n.box(i));
            if (s < 0) s = find(binary.nodes[origin].offset, n.box(i));
            slot[std::size_t(s)] = true;
            if (!is_leaf(n.child[i])) assign(int(n.child[i]), std::uint32_t(s));
        }
        for (const std::uint32_t c : kids(origin)) paint(c, w);
    };
    if (!is_leaf(wide.root_ref)) assign(0, 0);


    // The binary tree: leaves side by side in depth-first order, each inner node above its children's middle.
    std::map<std::uint32_t, point2> at;
    int next_leaf = 0;
    const int leaves = int(mesh.triangle_count());
    const std::function<double(std::uint32_t, int)> place = [&](std::uint32_t b, int depth) {
        double x;
        if (binary.nodes[b].is_leaf()) x = 60 + 980.0 * next_leaf++ / double(leaves - 1);
        else x = 0.5 * (place(b + 1, depth + 1) + place(binary.nodes[b].offset, depth + 1));
        at[b] = {x, 60 + 52.0 * depth};
        return x;
    };
    place(0, 0);
    double deepest = 0;
    for (const auto& [b, p] : at) deepest = std::max(deepest, p.y);
    diagram d(1100, int(deepest) + 230);
    const font title{15, "middle", ink::black, true}, body{13, "middle"};
    const char* colours[] = {ink::blue, ink::red, ink::green, ink::orange, ink::purple};
    const char* pale[] = {ink::pale_blue, ink::pale_red, ink::pale_green, ink::pale_orange, ink::pale_purple};
    d.text(550, 24, "the binary tree, and the 4-wide nodes the greedy collapse makes of it", title);
    for (const auto& [b, p] : at)
        if (!binary.nodes[b].is_leaf())
            for (const std::uint32_t c : kids(b)) d.line(p.x, p.y + 14, at[c].x, at[c].y - 14, {ink::grey, "none", 1.2});
    for (const auto& [b, p] : at) {
        const int w = owner[b];
        const bool leaf = binary.nodes[b].is_leaf();
        const char* stroke = w < 0 ? ink::black : colours[w % 5];
        const char* fill = leaf ? ink::pale_grey : w < 0 ? "white" : pale[w % 5];
        d.rect(p.x - 20, p.y - 14, p.x + 20, p.y + 14, {stroke, fill, slot[b] ? 2.5 : 1.5, !slot[b] && !leaf && b != 0});
        d.text(p.x, p.y + 5, leaf ? "t" + std::to_string(binary.prim_ids[binary.nodes[b].offset]) : std::to_string(b),
               {12, "middle", ink::black, !leaf});
    }

    // The wide root in memory: six rows of four floats and the four child references.
    const wide_node<4>& root = wide.nodes[0];
    const double top = deepest + 50, left = 300;
    d.text(550, top, "the wide root, structure of arrays: each row one 16-byte SIMD load", body);
    const char* rows[] = {"lo x", "lo y", "lo z", "hi x", "hi y", "hi z", "child"};
    for (int r = 0; r < 7; ++r) {
        const double y = top + 24 + 17.0 * r;
        d.text(left - 10, y, rows[r], {12, "end", ink::black, true});
        for (int i = 0; i < 4; ++i) {
            const double x = left + 60 + 140.0 * i;
            std::string v;
            const char* colour = root.used(i) ? ink::black : ink::grey;
            if (r < 6) v = root.used(i) ? number_text(r < 3 ? root.lo[r][i] : root.hi[r - 3][i], "%.2f") : (r < 3 ? "+inf" : "-inf");
            else if (!root.used(i)) v = "unused";
            else if (is_leaf(root.child[i])) v = "leaf: block " + std::to_string(leaf_first(root.child[i]));
            else v = "node " + std::to_string(root.child[i]), colour = colours[root.child[i] % 5];
            d.text(x, y, v, {12, "middle", colour, r == 6});
        }
    }
    d.text(550, top + 24 + 17.0 * 7 + 8,
           std::to_string(wide.nodes.size()) + " wide nodes in place of " +
               std::to_string(binary.nodes.size() - std::size_t(leaves)) + " inner binary nodes",
           body);
    return d;
}

}  // namespace

std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force) {
    return write_figures(folder, force, {{"collapse.svg", collapse_figure}});
}

}  // namespace strahl::ch13
