// The chapter's figure, priced by the chapter's own functions (`ch05 --diagrams DIR`):
//   sweep_and_bins.svg: the candidate planes of one node on the x axis, left for the full sweep (a plane
//   between every two neighbouring centroids) and right for binning (k = 8 equal bins over the centroids,
//   k - 1 planes), each plane's SAH cost plotted below it and the cheapest one marked. The costs come from
//   split_cost (exercise 05.1), the bins from bin_index (05.2), the cheapest plane from best_boundary (05.3).
// The triangles lie in the plane z = 0: a box's surface area is then twice its area in the picture.
#include "strahl/ch05/sah.hpp"
#include "strahl/diagram.hpp"
#include "strahl/program.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

namespace strahl::ch05 {

namespace {

using tri2 = std::array<point2, 3>;

std::string fixed(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

// The candidates of one method: each plane's x and SAH cost, and which is cheapest.
struct candidates {
    std::vector<double> x, cost;
    std::vector<std::uint32_t> left_count;
    std::size_t best = 0;
    float best_cost = 0.0f;
};

// Prices the boundaries between consecutive groups (a group: one primitive of the sorted sweep, or one bin).
// Each boundary with both sides non-empty is priced by split_cost; best_boundary, the builder's own sweep,
// picks the cheapest, and the figure marks that one.
candidates price(const std::vector<bin>& groups, const std::vector<double>& plane_x, float area_parent) {
    const sah_costs costs;
    candidates c;
    std::uint32_t total = 0;
    for (const bin& g : groups) total += g.count;
    aabb left;
    std::uint32_t n_left = 0;
    for (std::size_t b = 1; b < groups.size(); ++b) {
        left.grow(groups[b - 1].box);
        n_left += groups[b - 1].count;
        aabb right;
        for (std::size_t r = b; r < groups.size(); ++r) right.grow(groups[r].box);
        if (n_left == 0 || n_left == total) continue;
        c.x.push_back(plane_x[b - 1]);
        c.left_count.push_back(n_left);
        c.cost.push_back(split_cost(costs, area_parent, left.surface_area(), n_left, right.surface_area(), total - n_left));
    }
    std::vector<float> scratch(groups.size());
    const bin_split best = best_boundary(groups, scratch, costs, area_parent);
    // The candidate whose boundary best_boundary chose: the one with that many primitives on the left.
    std::uint32_t best_left = 0;
    for (int b = 0; b < best.index; ++b) best_left += groups[std::size_t(b)].count;
    for (std::size_t k = 0; k < c.x.size(); ++k)
        if (c.left_count[k] == best_left) c.best = k;
    c.best_cost = best.cost;
    return c;
}

diagram sweep_and_bins() {
    const std::vector<point2> centres{{0.9, 1.4}, {1.7, 3.1}, {2.3, 1.1}, {2.7, 2.4}, {1.2, 4.4}, {3.1, 3.8},
                                      {2.1, 5.2}, {6.6, 1.3}, {7.4, 4.9}, {8.7, 2.6}, {9.4, 5.5}, {10.3, 1.5},
                                      {11.0, 3.9}, {3.6, 0.8}};
    std::vector<tri2> tris;
    for (std::size_t i = 0; i < centres.size(); ++i) {
        tri2 t;
        for (int k = 0; k < 3; ++k) {
            const double angle = 1.7 * double(i) + 2.1 * double(k), r = 0.5 * (0.75 + 0.25 * double((i + k) % 3));
            t[k] = {centres[i].x + r * std::cos(angle), centres[i].y + r * std::sin(angle)};
        }
        tris.push_back(t);
    }
    std::vector<aabb> boxes;
    std::vector<double> cx;  // centroid x, the axis the figure shows
    aabb node, centroid_box;
    for (const tri2& t : tris) {
        aabb b;
        for (const point2& p : t) b.grow(vec3(float(p.x), float(p.y), 0.0f));
        boxes.push_back(b);
        node.grow(b);
        centroid_box.grow(b.centroid());
        cx.push_back(b.centroid().x);
    }
    const float area = node.surface_area();
    const std::size_t n = tris.size();

    // The full sweep: primitives sorted by centroid (ties by id), one "bin" each, a plane between neighbours.
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return cx[a] < cx[b] || (cx[a] == cx[b] && a < b); });
    std::vector<bin> singles;
    std::vector<double> sweep_x;
    for (std::size_t k = 0; k < n; ++k) {
        singles.push_back({boxes[order[k]], 1});
        if (k + 1 < n) sweep_x.push_back(0.5 * (cx[order[k]] + cx[order[k + 1]]));
    }
    const candidates sweep = price(singles, sweep_x, area);
    // Binning: k equal bins over the centroids' extent, each primitive in the bin bin_index gives it.
    const int k = 8;
    const bin_mapping m = make_bin_mapping(centroid_box.min.x, centroid_box.max.x, k);
    std::vector<bin> bins(k);
    for (std::size_t i = 0; i < n; ++i) {
        bin& b = bins[std::size_t(bin_index(m, float(cx[i])))];
        b.box.grow(boxes[i]);
        ++b.count;
    }
    std::vector<double> bin_x;
    for (int b = 1; b < k; ++b) bin_x.push_back(m.lo + double(b) / m.scale);
    const candidates binned = price(bins, bin_x, area);

    diagram d(720, 500);
    const font title{15, "middle", ink::black, true};
    d.text(185, 24, "full sweep: " + std::to_string(n - 1) + " planes", title);
    d.text(545, 24, "binning: " + std::to_string(k) + " bins, " + std::to_string(k - 1) + " planes", title);
    const double wx0 = node.min.x - 0.3, wx1 = node.max.x + 0.3, wy0 = node.min.y - 0.3, wy1 = node.max.y + 1.0;
    double cost_lo = 1e30, cost_hi = 0.0;
    for (const candidates* c : {&sweep, &binned})
        for (double v : c->cost) cost_lo = std::min(cost_lo, v), cost_hi = std::max(cost_hi, v);
    cost_lo = std::floor(cost_lo), cost_hi = std::ceil(cost_hi);
    for (int side = 0; side < 2; ++side) {
        const double left = side == 0 ? 12 : 372, width = 340;
        const candidates& c = side == 0 ? sweep : binned;
        d.view(wx0, wy0, wx1, wy1, left + 30, 40, width - 30, 200);
        const double s = d.scale();
        if (side == 1) {
            // The bins, shaded in turn, with the number of centroids each holds written at the top.
            for (int b = 0; b < k; ++b) {
                const double x0 = m.lo + double(b) / m.scale, x1 = m.lo + double(b + 1) / m.scale;
                d.rect(x0, node.min.y, x1, node.max.y, {"none", b % 2 ? ink::pale_blue : "#eaf2fa", 0.0});
                d.text(0.5 * (x0 + x1), node.max.y + 6.0 / s, std::to_string(bins[std::size_t(b)].count),
                       {13, "middle", ink::blue, true});
            }
        }
        for (const tri2& t : tris) d.polygon({t[0], t[1], t[2]}, {ink::orange, ink::pale_orange, 1.0});
        d.rect(node.min.x, node.min.y, node.max.x, node.max.y, {ink::black, "none", 1.5});
        for (std::size_t i = 0; i < n; ++i) d.circle(cx[i], boxes[i].centroid().y, 2.5, {"none", ink::black, 0.0});
        const std::vector<double>& planes = side == 0 ? sweep_x : bin_x;
        for (double x : planes) d.line(x, node.min.y, x, node.max.y, {ink::grey, "none", 1.0, true});
        d.line(c.x[c.best], node.min.y - 0.2, c.x[c.best], node.max.y, {ink::red, "none", 2.5});
        // The cost of each plane, below it, on one scale for both panels.
        const double chart_top = 300, chart_bottom = 400;
        std::vector<double> px;
        for (double x : c.x) px.push_back(d.to_pixel(x, 0).x);
        const point2 below = d.to_pixel(c.x[c.best], node.min.y - 0.2);
        d.pixels();
        const auto py = [&](double v) { return chart_bottom - (chart_bottom - chart_top) * (v - cost_lo) / (cost_hi - cost_lo); };
        const double axis_left = left + 26, axis_right = left + width;
        d.line(below.x, below.y, px[c.best], py(c.cost[c.best]), {ink::red, "none", 1.0, true});
        d.line(axis_left, chart_bottom, axis_right, chart_bottom, {ink::grey, "none", 1.0});
        d.line(axis_left, chart_top, axis_left, chart_bottom, {ink::grey, "none", 1.0});
        for (double v : {cost_lo, cost_hi}) d.text(axis_left - 4, py(v) + 4, std::to_string(int(v)), {11, "end", ink::grey});
        d.text(axis_left + 4, chart_top - 16, "SAH cost of each plane", {12, "start", ink::grey});
        for (std::size_t j = 0; j + 1 < px.size(); ++j) d.line(px[j], py(c.cost[j]), px[j + 1], py(c.cost[j + 1]), {ink::grey, "none", 1.0});
        for (std::size_t j = 0; j < px.size(); ++j)
            d.circle(px[j], py(c.cost[j]), j == c.best ? 5 : 3.5, {"none", j == c.best ? ink::red : ink::black, 0.0});
        d.text(px[c.best] + 8, py(c.cost[c.best]) + 16, "cost " + fixed(c.best_cost), {13, "start", ink::red, true, true});
        const std::uint32_t nl = c.left_count[c.best];
        d.text(left + width / 2, 432, std::to_string(nl) + " triangles left, " + std::to_string(n - nl) + " right: cost " +
                                          fixed(c.best_cost), {13, "middle", ink::red, true});
    }
    d.text(360, 462, "cost = C_T + C_I (A(L) N_L + A(R) N_R) / A(P), C_T = C_I = 1; as a leaf the node costs " +
                         std::to_string(int(leaf_cost({}, n))), {13, "middle"});
    d.text(360, 484, "dashed: the candidate planes; red: the cheapest; dots: the centroids", {13, "middle", ink::grey});
    return d;
}

}  // namespace

std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force) {
    return write_figures(folder, force, {{"sweep_and_bins.svg", sweep_and_bins}});
}

}  // namespace strahl::ch05
