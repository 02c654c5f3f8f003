// Building the uniform grid: the resolution heuristic, then compact cell storage in two passes.
// J. G. Cleary and G. Wyvill, "Analysis of an algorithm for fast ray tracing using uniform space
// subdivision", The Visual Computer 4(2), 1988: cells in proportion to the primitive count.
#include "strahl/ch02/build.hpp"
#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

namespace strahl::ch02 {

std::uint64_t next_grid_id() {
    static std::atomic<std::uint64_t> next{1};
    return next++;
}

grid_dims choose_resolution(const aabb& scene_box, std::size_t n, const grid_options& opt) {
    grid_dims g;
    if (n == 0 || scene_box.is_empty() || !is_finite(scene_box.min) || !is_finite(scene_box.max)) return g;
    if (!(opt.lambda > 0.0f) || opt.max_res < 1 || opt.max_cells < 1)
        throw std::invalid_argument("grid: lambda, max_res and max_cells must be positive");
    // Flat scenes: an axis of zero extent gets a thin but non-zero slab (and, below, one cell).
    aabb box = scene_box;
    const vec3 e = box.extent();
    const float largest = std::max({e.x, e.y, e.z});
    for (int a = 0; a < 3; ++a) {
        if (e[a] > 1e-6f * largest) continue;
        const float scale = std::max({largest, std::abs(box.min[a]), std::abs(box.max[a]), 1.0f});
        box.min[a] -= 1e-4f * scale;
        box.max[a] += 1e-4f * scale;
    }
    // The heuristic: cells ~ lambda N, cube-ish: n_axis = extent_axis * cbrt(lambda N / volume).
    const vec3 ext = box.max - box.min;
    const double cells = std::min(double(opt.lambda) * double(n), double(opt.max_cells));
    const double volume = double(ext.x) * double(ext.y) * double(ext.z);
    const double per_unit = std::cbrt(cells / volume);
    for (int a = 0; a < 3; ++a) {
        const double want = std::round(double(ext[a]) * per_unit);
        g.res[a] = int(std::clamp(want, 1.0, double(opt.max_res)));
    }
    // Rounding and the clamp to 1 can overshoot the cap: shrink the largest axis until it holds.
    while (std::int64_t(g.res.x) * g.res.y * g.res.z > opt.max_cells) {
        const int a = g.res.x >= g.res.y ? (g.res.x >= g.res.z ? 0 : 2) : (g.res.y >= g.res.z ? 1 : 2);
        g.res[a] = std::max(1, g.res[a] - 1);
    }
    g.box = box;
    g.cell_size = ext / vec3(g.res);
    g.inv_cell_size = vec3(g.res) / ext;
    return g;
}

namespace {
// Boxes are padded a hair (far below a cell) so that a triangle touching a cell boundary is in the cells
// on both sides, whatever the rounding in the DDA's walk.
vec3 box_pad(const grid_dims& g) {
    const vec3 ext = g.box.max - g.box.min;
    return vec3(1e-5f * std::max({ext.x, ext.y, ext.z}));
}
}  // namespace

std::uint64_t count_references(const grid_dims& g, std::span<const aabb> boxes) {
    if (g.cell_count() == 0) return 0;
    const vec3 pad = box_pad(g);
    std::uint64_t n = 0;
    for (const aabb& b : boxes) {
        const cell_range cr = cells_of_box(g, aabb{b.min - pad, b.max + pad});
        if (cr.hi.x < cr.lo.x || cr.hi.y < cr.lo.y || cr.hi.z < cr.lo.z) continue;
        n += std::uint64_t(cr.hi.x - cr.lo.x + 1) * std::uint64_t(cr.hi.y - cr.lo.y + 1) *
             std::uint64_t(cr.hi.z - cr.lo.z + 1);
    }
    return n;
}

grid_dims bounded_resolution(const aabb& scene_box, std::span<const aabb> boxes, const grid_options& opt,
                             bool* lowered) {
    if (opt.max_references >= (std::uint64_t(1) << 32))
        throw std::length_error("grid: max_references must stay below 2^32 (the cells' offsets are 32 bits)");
    if (lowered) *lowered = false;
    grid_options o = opt;
    for (;;) {
        const grid_dims g = choose_resolution(scene_box, boxes.size(), o);
        if (count_references(g, boxes) <= opt.max_references) return g;
        if (g.res == ivec3(1))
            throw std::length_error("grid: " + std::to_string(boxes.size()) + " primitives exceed the grid's " +
                                    std::to_string(opt.max_references) + " references even in one cell");
        if (lowered) *lowered = true;
        o.lambda *= 0.5f;  // half the cells per primitive; the loop ends at one cell
        o.max_res = std::max(1, std::min(o.max_res, std::max({g.res.x, g.res.y, g.res.z}) - 1));
    }
}

grid_cells fill_cells(const grid_dims& g, std::span<const aabb> boxes, const overlap_test& keep) {
    grid_cells out;
    if (g.cell_count() == 0) return out;
    const vec3 pad = box_pad(g);
    const auto range_of = [&](std::size_t i) { return cells_of_box(g, aabb{boxes[i].min - pad, boxes[i].max + pad}); };
    const auto each_cell = [&](std::size_t i, auto&& f) {
        const cell_range cr = range_of(i);
        for (int z = cr.lo.z; z <= cr.hi.z; ++z)
            for (int y = cr.lo.y; y <= cr.hi.y; ++y)
                for (int x = cr.lo.x; x <= cr.hi.x; ++x) {
                    const ivec3 c(x, y, z);
                    if (keep) {
                        aabb cb = g.cell_box(c);
                        cb.min -= pad, cb.max += pad;
                        if (!keep(std::uint32_t(i), cb)) continue;
                    }
                    f(g.index(c));
                }
    };
    // Pass 1, count: how many primitives each cell holds.
    out.offsets.assign(std::size_t(g.cell_count()) + 1, 0);
    for (std::size_t i = 0; i < boxes.size(); ++i) each_cell(i, [&](int c) { ++out.offsets[std::size_t(c) + 1]; });
    // Pass 2, prefix sum: where each cell's run starts in the one index array.
    for (std::size_t c = 1; c < out.offsets.size(); ++c) out.offsets[c] += out.offsets[c - 1];
    // Pass 3, fill: primitives in id order within each cell.
    out.prims.resize(out.offsets.back());
    std::vector<std::uint32_t> cursor(out.offsets.begin(), out.offsets.end() - 1);
    for (std::size_t i = 0; i < boxes.size(); ++i)
        each_cell(i, [&](int c) { out.prims[cursor[std::size_t(c)]++] = std::uint32_t(i); });
    return out;
}

grid_stats occupancy(const grid_dims& g, const grid_cells& c, std::size_t prims, std::size_t bins) {
    grid_stats s;
    s.cells = std::size_t(g.cell_count());
    s.references = c.prims.size();
    s.histogram.assign(std::max<std::size_t>(bins, 1), 0);
    s.refs_by_log2.assign(16, 0);
    for (std::size_t i = 0; i < s.cells; ++i) {
        const std::size_t k = c.offsets[i + 1] - c.offsets[i];
        s.empty_cells += k == 0;
        s.max_per_cell = std::max(s.max_per_cell, k);
        ++s.histogram[std::min(k, s.histogram.size() - 1)];
        if (k > 0) s.refs_by_log2[std::min<std::size_t>(std::bit_width(k) - 1, 15)] += k;
    }
    if (s.cells) s.mean_per_cell = double(s.references) / double(s.cells);
    if (s.cells > s.empty_cells) s.mean_per_nonempty = double(s.references) / double(s.cells - s.empty_cells);
    if (prims) s.references_per_prim = double(s.references) / double(prims);
    return s;
}

}  // namespace strahl::ch02
