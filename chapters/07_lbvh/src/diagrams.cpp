// The chapter's figure, computed by the chapter's own code (`ch07 --diagrams DIR`):
//   zorder.svg: sixteen centroids in the plane (z = 0), quantised to 3 bits per axis (quantizer), their
//   Morton codes (morton30, exercise 07.1) sorted (radix_sort, 07.2); the Z-order curve the sorted points
//   follow, and the radix tree over the sorted codes (build_radix_tree_karras), each inner node named by the
//   bit where its range's codes first differ: the left child holds the codes with a 0 there, the right the
//   codes with a 1.
#include "strahl/ch07/morton.hpp"
#include "strahl/ch07/radix_sort.hpp"
#include "strahl/ch07/radix_tree.hpp"
#include "strahl/diagram.hpp"
#include "strahl/rng.hpp"
#include <algorithm>
#include <bit>
#include <string>
#include <vector>

namespace strahl::ch07 {

namespace {

constexpr int bits = 3;            // per axis: an 8 x 8 grid
constexpr int cells = 1 << bits;
constexpr std::size_t points = 16;

// The code's x and y bits from the highest, interleaved as the code holds them (its z bits are all 0).
std::string code_text(std::uint64_t code) {
    std::string s;
    for (int b = 3 * bits - 1; b >= 0; --b)
        if (axis_of_bit(b) != 2) s += ((code >> b) & 1) ? '1' : '0';
    return s;
}

// Bit b of a code, as its axis and its level within the axis: "x2" is x's highest of three.
std::string bit_name(int b) { return std::string(1, "xyz"[axis_of_bit(b)]) + std::to_string(b / 3); }

diagram zorder_figure() {
    // Sixteen points in sixteen different cells of [0, 8]^2, each somewhere inside its cell.
    pcg32 g(7, 7);
    std::vector<bool> taken(cells * cells, false);
    std::vector<vec3> centroid;
    while (centroid.size() < points) {
        const std::uint32_t c = g.next_bounded(cells * cells);
        if (taken[c]) continue;
        taken[c] = true;
        centroid.push_back(vec3(float(c % cells) + 0.15f + 0.7f * g.next_float(),
                                float(c / cells) + 0.15f + 0.7f * g.next_float(), 0.0f));
    }
    // The codes phase and the sort, as the builders do them.
    const quantizer q(aabb{vec3(0.0f), vec3(float(cells), float(cells), 0.0f)}, bits);
    std::vector<std::uint64_t> codes(points);
    std::vector<std::uint32_t> ids(points);
    for (std::uint32_t i = 0; i < points; ++i) {
        codes[i] = morton30(q(centroid[i].x, 0), q(centroid[i].y, 1), q(centroid[i].z, 2));
        ids[i] = i;
    }
    radix_sort(codes, ids, radix_sort_params{3 * bits, 8});
    radix_tree tree;
    build_radix_tree_karras(codes, tree);
    const std::uint32_t root_split = tree.left[0] & ~leaf_bit;  // the last leaf of the root's left half
    const auto half_ink = [&](std::uint32_t leaf, bool pale) {
        return leaf <= root_split ? (pale ? ink::pale_blue : ink::blue) : (pale ? ink::pale_red : ink::red);
    };

    diagram d(1100, 500);
    const font title{15, "middle", ink::black, true}, small{11, "middle"};
    d.text(210, 24, "centroids, 3-bit cells, the Z-order curve", title);
    d.text(770, 24, "the radix tree over the sorted codes", title);

    // Left: the grid, the Z-order curve through every cell (grey), the points in sorted order.
    d.view(0, 0, cells, cells, 20, 40, 380, 380);
    for (int k = 0; k <= cells; ++k) {
        d.line(k, 0, k, cells, {ink::pale_grey, "none", 1.0});
        d.line(0, k, cells, k, {ink::pale_grey, "none", 1.0});
    }
    std::vector<std::pair<std::uint32_t, point2>> order;
    for (std::uint32_t y = 0; y < cells; ++y)
        for (std::uint32_t x = 0; x < cells; ++x) order.push_back({morton30(x, y, 0), {x + 0.5, y + 0.5}});
    std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t k = 1; k < order.size(); ++k)
        d.line(order[k - 1].second.x, order[k - 1].second.y, order[k].second.x, order[k].second.y,
               {ink::grey, "none", 1.0, true});
    for (std::uint32_t k = 1; k < points; ++k) {
        const vec3 a = centroid[ids[k - 1]], b = centroid[ids[k]];
        const bool across = k - 1 == root_split;
        d.line(a.x, a.y, b.x, b.y, {across ? ink::black : half_ink(k, false), "none", across ? 1.5 : 2.5, across});
    }
    for (std::uint32_t k = 0; k < points; ++k) {
        const vec3 c = centroid[ids[k]];
        d.circle(c.x, c.y, 9, {half_ink(k, false), half_ink(k, true), 1.5});
        d.text(c.x, c.y - 4 / d.scale(), std::to_string(k), {11, "middle", ink::black, true});  // 4 pixels down
    }
    d.pixels();
    d.text(210, 446, "dashed grey: the curve through all 64 cells in code order;", small);
    d.text(210, 462, "coloured: the 16 points in sorted order, numbered;", small);
    d.text(210, 478, "blue and red: the root's two halves", small);

    // Right: the leaves in sorted order with their codes (x and y bits interleaved), the inner nodes above.
    const double left = 460, right = 1080, leaf_y = 420;
    const double step = (right - left) / double(points - 1);
    std::vector<int> depth(points - 1, 0);
    int deepest = 0;
    for (std::uint32_t i = 1; i < points - 1; ++i) {
        for (std::uint32_t p = i; tree.parent[p] != radix_tree::none; p = tree.parent[p]) ++depth[i];
        deepest = std::max(deepest, depth[i]);
    }
    const double level = (leaf_y - 80) / double(deepest + 1);
    const auto leaf_x = [&](std::uint32_t k) { return left + step * double(k); };
    const auto inner_at = [&](std::uint32_t i) {
        return point2{0.5 * (leaf_x(tree.first[i]) + leaf_x(tree.last[i])), 60 + level * depth[i]};
    };
    const auto child_at = [&](std::uint32_t ref) {
        return is_leaf_ref(ref) ? point2{leaf_x(ref & ~leaf_bit), leaf_y - 12} : inner_at(ref);
    };
    for (std::uint32_t i = 0; i < points - 1; ++i)
        for (const std::uint32_t c : {tree.left[i], tree.right[i]}) {
            const point2 a = inner_at(i), b = child_at(c);
            d.line(a.x, a.y + 11, b.x, b.y - (is_leaf_ref(c) ? 0 : 11), {ink::grey, "none", 1.2});
        }
    for (std::uint32_t i = 0; i < points - 1; ++i) {
        const point2 p = inner_at(i);
        const std::uint64_t x = codes[tree.first[i]] ^ codes[tree.last[i]];
        const std::string name = x != 0 ? bit_name(63 - std::countl_zero(x)) : "index";
        const bool root = i == 0;
        d.rect(p.x - 17, p.y - 11, p.x + 17, p.y + 11,
               {root ? ink::black : half_ink(tree.first[i], false), root ? ink::pale_grey : half_ink(tree.first[i], true),
                1.2});
        d.text(p.x, p.y + 5, name, {13, "middle", ink::black, true});
    }
    for (std::uint32_t k = 0; k < points; ++k) {
        const double x = leaf_x(k);
        d.circle(x, leaf_y, 9, {half_ink(k, false), half_ink(k, true), 1.5});
        d.text(x, leaf_y + 4, std::to_string(k), {11, "middle", ink::black, true});
        d.text(x, leaf_y + 26, code_text(codes[k]).substr(0, 3), {11, "middle", ink::black});
        d.text(x, leaf_y + 40, code_text(codes[k]).substr(3), {11, "middle", ink::black});
    }
    d.text(770, 478, "codes x2 y2 x1 / y1 x0 y0; a node named x1 splits its range where x's middle bit flips from 0 to 1",
           small);
    return d;
}

}  // namespace

std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force) {
    return write_figures(folder, force, {{"zorder.svg", zorder_figure}});
}

}  // namespace strahl::ch07
