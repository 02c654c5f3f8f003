// Exercise 02.1 cell range (5 points). Read: J. Amanatides and A. Woo, "A Fast Voxel Traversal Algorithm
// for Ray Tracing", Eurographics 1987, and the chapter's section "Building the grid".
#include "strahl/ch02/grid.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch02 {

// Goal: the cells box b overlaps: per axis a, lo[a] = the cell holding b.min[a], hi[a] = the cell holding
// b.max[a], each clamped to [0, g.res[a] - 1]. An empty box (b.is_empty()), a grid without cells, or a box
// lying wholly outside the grid box on some axis: an empty range, cell_range{} (lo = 0, hi = -1).
// Hint: clamp the float that floor() gives before converting it to int: converting a NaN or a float
// beyond int's range is undefined behaviour.
// Why: why can a box lying inside the grid box still give the cell index g.res[a] on its upper face?
// Step by step: HINTS.md, 02.1.
cell_range cells_of_box(const grid_dims& g, const aabb& b) {
    STRAHL_TODO("02.1 cell range");
}

}  // namespace strahl::ch02
