// Exercise 02.4 hit in cell (4 points). Read the chapter's section "The pitfall: a hit beyond the cell".
#include "strahl/ch02/grid.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch02 {

// Whether the walk may stop in the current cell: t_end (the best hit's t, or the ray's tmax when nothing
// was hit) must lie strictly before the cell's exit t_cell_exit, by a margin for rounding:
//   t_end < t_cell_exit - 1e-4 * |t_cell_exit|.
// A hit at (or a hair before) the exit may tie with a triangle of the next cell; a hit beyond it may lie
// behind a nearer triangle in a cell not visited yet: in both cases keep walking (return false).
// NaN anywhere, or an infinite exit: return false.
bool hit_in_cell(float t_end, float t_cell_exit) {
    STRAHL_TODO("02.4 hit in cell");
}

}  // namespace strahl::ch02
