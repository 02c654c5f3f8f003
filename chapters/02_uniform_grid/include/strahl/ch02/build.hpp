// Building chapter 02's uniform grid from boxes: the resolution heuristic and compact cell storage.
// The heuristic: cells ~ lambda * N, as cube-ish as the box allows (J. Cleary and G. Wyvill, "Analysis of
// an algorithm for fast ray tracing using uniform space subdivision", The Visual Computer, 1988; the
// lambda form as in A. Fujimoto et al. and in Wald's and Havran's grid studies).
#pragma once
#include "strahl/ch02/grid.hpp"
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace strahl::ch02 {

struct grid_options {
    float lambda = 4.0f;           // cells per triangle
    int max_res = 1024;            // cells per axis at most
    std::int64_t max_cells = 1 << 24;  // cells in all at most (16 M: 64 MB of offsets)
    bool exact_overlap = false;    // insert a triangle only into cells the triangle itself overlaps
    // References (a primitive id in a cell) at most: 64 M, 256 MiB of ids. Triangles whose boxes span many
    // cells (long thin ones, or thousands stacked in one place) would otherwise make the grid grow with the
    // square of their number; the resolution is lowered until their cell ranges hold no more than this.
    std::uint64_t max_references = std::uint64_t(1) << 26;
};

// The resolution heuristic: n_axis = extent_axis * cbrt(lambda N / volume), clamped to [1, max_res].
// Axes of zero extent are widened first (a flat scene gets one cell, of non-zero size, on that axis).
grid_dims choose_resolution(const aabb& scene_box, std::size_t n, const grid_options& opt);

// The references fill_cells would make at resolution g (before any exact overlap test): the sum over the
// boxes of the cells each box's range covers, in 64 bits. O(N), no cell is visited.
std::uint64_t count_references(const grid_dims& g, std::span<const aabb> boxes);

// choose_resolution, then, while the references would exceed opt.max_references, the same heuristic with
// half the cells per primitive (down to one cell). Sets *lowered when it had to. Throws std::length_error
// when even one cell would hold more (more primitives than max_references), or max_references >= 2^32.
grid_dims bounded_resolution(const aabb& scene_box, std::span<const aabb> boxes, const grid_options& opt,
                             bool* lowered = nullptr);

// The cells: prims[offsets[c] .. offsets[c+1]) are the primitives of cell c. One index array, no vector
// per cell: built in two passes (count, prefix sum, fill).
struct grid_cells {
    std::vector<std::uint32_t> offsets;  // cell_count + 1 entries (empty for the empty grid)
    std::vector<std::uint32_t> prims;
};

// Optional exact test: keep(i, cell_box) says whether primitive i truly overlaps the cell.
using overlap_test = std::function<bool(std::uint32_t, const aabb&)>;

grid_cells fill_cells(const grid_dims& g, std::span<const aabb> boxes, const overlap_test& keep = {});

// Occupancy: what the chapter prints and plots.
struct grid_stats {
    std::size_t cells = 0, empty_cells = 0, references = 0, max_per_cell = 0;
    double mean_per_cell = 0.0;        // over all cells
    double mean_per_nonempty = 0.0;    // over the cells holding something
    double references_per_prim = 0.0;
    std::vector<std::size_t> histogram;  // histogram[k]: cells holding k primitives (last bin: k or more)
    // What a ray meets: refs_by_log2[b] counts the references held by cells of 2^b to 2^(b+1) - 1
    // primitives (b = 0 .. 15; the last bin: 2^15 or more). They sum to `references`.
    std::vector<std::size_t> refs_by_log2;
};
grid_stats occupancy(const grid_dims& g, const grid_cells& c, std::size_t prims, std::size_t bins = 16);

}  // namespace strahl::ch02
