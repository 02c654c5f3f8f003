// Exercise 02.1 cell range (5 points). Read: J. Amanatides and A. Woo, "A Fast Voxel Traversal Algorithm
// for Ray Tracing", Eurographics 1987, and the chapter's section "Building the grid".
#include "strahl/ch02/grid.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch02 {

// Return the cells box b overlaps: per axis a, lo[a] = the cell holding b.min[a], hi[a] = the cell holding
// b.max[a], where the cell holding x is floor((x - g.box.min[a]) * g.inv_cell_size[a]) clamped to
// [0, g.res[a] - 1] (a box reaching past the grid is clamped to its border cells).
// An empty box (b.is_empty()), a grid without cells, or a box lying wholly outside the grid box on some
// axis: return an empty range, cell_range{} (lo = 0, hi = -1).
cell_range cells_of_box(const grid_dims& g, const aabb& b) {
    STRAHL_TODO("02.1 cell range");
}

}  // namespace strahl::ch02
