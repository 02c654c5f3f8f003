// Exercise 02.4 hit in cell (4 points). Read the chapter's section "The pitfall: a hit beyond the cell".
#include "strahl/ch02/grid.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch02 {

// Goal: whether the walk may stop in the current cell: t_end (the best hit's t, or the ray's tmax when
// nothing was hit) lies strictly before the cell's exit t_cell_exit, by a margin for rounding:
//   t_end < t_cell_exit - 1e-4 * |t_cell_exit|.
// NaN anywhere, or an infinite exit: false (keep walking).
// Hint: written as that one comparison, every NaN already makes it false.
// Why: why is a hit exactly at the exit not enough to stop (a triangle of the next cell may tie in t, with
// a lower id), and why is walking one cell too far harmless while stopping one cell early is wrong?
// Step by step: HINTS.md, 02.4.
bool hit_in_cell(float t_end, float t_cell_exit) {
    STRAHL_TODO("02.4 hit in cell");
}

}  // namespace strahl::ch02
