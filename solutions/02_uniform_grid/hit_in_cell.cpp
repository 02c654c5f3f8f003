// Exercise 02.4 hit in cell: the classic pitfall of grid traversal. A triangle spans several cells, so a hit
// found while testing the current cell may lie in a later cell, behind a nearer triangle the walk has not
// reached yet. The search may end only once its end lies inside the current cell.
// J. Amanatides and A. Woo, "A Fast Voxel Traversal Algorithm for Ray Tracing", Eurographics 1987.
#include "strahl/ch02/grid.hpp"
#include <cmath>

namespace strahl::ch02 {

bool hit_in_cell(float t_end, float t_cell_exit) {
    // Strictly before the exit, with a margin for the rounding of the walk's t_max sums: a hit at the exit
    // itself may tie with a triangle in the next cell, and the lower id must win the tie.
    // NaN or an infinite exit: false (keep walking; the loop is bounded).
    return t_end < t_cell_exit - 1e-4f * std::abs(t_cell_exit);
}

}  // namespace strahl::ch02
