// Exercise 02.1 cell range: which cells of a uniform grid a box overlaps.
// J. Amanatides and A. Woo, "A Fast Voxel Traversal Algorithm for Ray Tracing", Eurographics 1987.
#include "strahl/ch02/grid.hpp"
#include <algorithm>
#include <cmath>

namespace strahl::ch02 {

namespace {
// The cell holding coordinate x on axis a, clamped to [0, res - 1].
int cell_on_axis(const grid_dims& g, float x, int a) {
    const float f = std::floor((x - g.box.min[a]) * g.inv_cell_size[a]);
    if (!(f > 0.0f)) return 0;  // also NaN
    return f >= float(g.res[a] - 1) ? g.res[a] - 1 : int(f);
}
}  // namespace

cell_range cells_of_box(const grid_dims& g, const aabb& b) {
    if (b.is_empty() || g.cell_count() == 0) return {};
    cell_range r;
    for (int a = 0; a < 3; ++a) {
        // Boxes beyond the grid on this axis overlap no cell.
        if (b.max[a] < g.box.min[a] || b.min[a] > g.box.max[a]) return {};
        r.lo[a] = cell_on_axis(g, b.min[a], a);
        r.hi[a] = cell_on_axis(g, b.max[a], a);
    }
    return r;
}

}  // namespace strahl::ch02
