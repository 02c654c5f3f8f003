// The chapter's figure, computed by the chapter's own code (`ch09 --diagrams DIR`):
//   splits.svg: two clusters of small triangles and one long sliver across both, in the plane (z from 0 to
//   0.1). Left, the best object split on x (chapter 05's SAH sweep over the centroids): the sliver goes whole
//   to one side and stretches that child's box over the other's. Right, the best spatial split on x over 8
//   chopped bins (chopped_binning, exercise 09.2, clipping with clip_to_slab, 09.1): the bins' boxes, the
//   plane, the sliver's two clipped halves, and two children that no longer overlap. Each panel prints its
//   split's SAH cost, (A(L) N(L) + A(R) N(R)) / A(node).
#include "strahl/ch09/chopped_bins.hpp"
#include "strahl/ch09/clip.hpp"
#include "strahl/diagram.hpp"
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace strahl::ch09 {

namespace {

void box(diagram& d, const aabb& b, const pen& p, double grow = 0.0) {
    if (!b.is_empty()) d.rect(b.min.x - grow, b.min.y - grow, b.max.x + grow, b.max.y + grow, p);
}

void triangles(diagram& d, const std::vector<triangle>& tris) {
    for (std::size_t i = 0; i < tris.size(); ++i) {
        const triangle& t = tris[i];
        const bool sliver = i + 1 == tris.size();
        d.polygon({{t.v0.x, t.v0.y}, {t.v1.x, t.v1.y}, {t.v2.x, t.v2.y}},
                  {sliver ? ink::purple : ink::grey, sliver ? ink::pale_purple : ink::pale_grey, 1.2});
    }
}

diagram splits_figure() {
    // Four small triangles on the left, four on the right, and last a long sliver from one to the other.
    std::vector<triangle> tris;
    const auto small = [&](float x, float y) {
        tris.push_back({vec3(x, y, 0), vec3(x + 0.9f, y + 0.1f, 0.05f), vec3(x + 0.3f, y + 0.8f, 0.1f)});
    };
    small(0.3f, 0.4f), small(1.5f, 0.9f), small(0.6f, 1.9f), small(1.7f, 2.4f);
    small(5.6f, 4.6f), small(6.8f, 5.1f), small(5.9f, 6.0f), small(6.9f, 6.6f);
    tris.push_back({vec3(0.5f, 1.2f, 0), vec3(7.6f, 6.9f, 0.05f), vec3(7.3f, 7.3f, 0.1f)});
    aabb node;
    for (const triangle& t : tris) node.grow(t.bounds());
    const double area = node.surface_area();

    // The object split: the centroids sorted on x, every split between them priced.
    std::vector<std::size_t> order(tris.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return tris[a].bounds().centroid().x < tris[b].bounds().centroid().x;
    });
    double object_cost = inf;
    aabb object_left, object_right;
    for (std::size_t n = 1; n < order.size(); ++n) {
        aabb l, r;
        for (std::size_t i = 0; i < order.size(); ++i) (i < n ? l : r).grow(tris[order[i]].bounds());
        const double c = (l.surface_area() * double(n) + r.surface_area() * double(order.size() - n)) / area;
        if (c < object_cost) object_cost = c, object_left = l, object_right = r;
    }

    // The spatial split: 8 chopped bins over the node's box on x, every boundary priced.
    constexpr int k = 8;
    const ch05::bin_mapping m = ch05::make_bin_mapping(node.min.x, node.max.x, k);
    std::vector<reference> refs;
    for (std::uint32_t i = 0; i < tris.size(); ++i) refs.push_back({tris[i].bounds(), i});
    std::vector<chopped_bin> bins(k);
    chopped_binning(refs, 0, m, bins, [&](const reference& r, float lo, float hi) {
        return clip_to_slab(tris[r.tri], 0, lo, hi, r.box);
    });
    double spatial_cost = inf;
    int plane_bin = 1;
    aabb spatial_left, spatial_right;
    for (int j = 1; j < k; ++j) {
        aabb l, r;
        std::uint32_t nl = 0, nr = 0;
        for (int b = 0; b < k; ++b) {
            if (b < j) l.grow(bins[std::size_t(b)].box), nl += bins[std::size_t(b)].entry;
            else r.grow(bins[std::size_t(b)].box), nr += bins[std::size_t(b)].exit;
        }
        const double c = (l.surface_area() * double(nl) + r.surface_area() * double(nr)) / area;
        if (c < spatial_cost) spatial_cost = c, plane_bin = j, spatial_left = l, spatial_right = r;
    }
    const float plane = bin_plane(m, plane_bin);
    const triangle& sliver = tris.back();
    const aabb half_left = clip_to_slab(sliver, 0, -inf, plane, sliver.bounds());
    const aabb half_right = clip_to_slab(sliver, 0, plane, inf, sliver.bounds());

    diagram d(1000, 480);
    const font title{15, "middle", ink::black, true}, body{13, "middle"};
    d.text(245, 24, "object split: the sliver stays whole", title);
    d.text(755, 24, "spatial split: the sliver is cut", title);
    // Left.
    d.view(node.min.x - 0.3, node.min.y - 0.3, node.max.x + 0.3, node.max.y + 0.3, 20, 40, 450, 360);
    triangles(d, tris);
    box(d, object_left, {ink::blue, "none", 2.5}, 0.06);
    box(d, object_right, {ink::red, "none", 2.5}, 0.12);
    // Right: the bins and their chopped boxes, the plane, the halves and the children.
    d.view(node.min.x - 0.3, node.min.y - 0.3, node.max.x + 0.3, node.max.y + 0.3, 530, 40, 450, 360);
    for (int j = 0; j <= k; ++j) {
        const double x = bin_plane(m, j);
        d.line(x, node.min.y - 0.2, x, node.max.y + 0.2, {ink::grey, "none", 1.0, true});
    }
    for (const chopped_bin& b : bins) box(d, b.box, {ink::orange, ink::pale_orange, 1.0, false, 0.5});
    triangles(d, tris);
    box(d, half_left, {ink::purple, "none", 2.0, true}, 0.03);
    box(d, half_right, {ink::purple, "none", 2.0, true}, 0.03);
    d.line(plane, node.min.y - 0.3, plane, node.max.y + 0.3, {ink::black, "none", 2.0});
    box(d, spatial_left, {ink::blue, "none", 2.5}, 0.06);
    box(d, spatial_right, {ink::red, "none", 2.5}, 0.06);
    d.pixels();
    d.text(245, 426, "the children's boxes (blue, red) overlap", body);
    d.text(245, 446, "SAH cost of the split " + number_text(object_cost), {14, "middle", ink::black, true});
    d.text(755, 426, "8 chopped bins (orange), the plane, the sliver's two halves (dashed)", body);
    d.text(755, 446, "SAH cost of the split " + number_text(spatial_cost) + ", the sliver counted on both sides",
           {14, "middle", ink::red, true});
    d.text(500, 472, "cost = (A(left) N(left) + A(right) N(right)) / A(node), C_T = C_I = 1", body);
    return d;
}

}  // namespace

std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force) {
    return write_figures(folder, force, {{"splits.svg", splits_figure}});
}

}  // namespace strahl::ch09
