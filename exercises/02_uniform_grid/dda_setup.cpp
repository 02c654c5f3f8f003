// Exercise 02.2 DDA set-up (6 points). Read: J. Amanatides and A. Woo, "A Fast Voxel Traversal Algorithm
// for Ray Tracing", Eurographics 1987 (the initialisation phase), and the chapter's section "The 3D-DDA".
#include "strahl/ch02/grid.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch02 {

// Goal: the walk's state for ray r entering the grid at t_enter (the caller clipped r to g.box): the first
// cell (the one holding r.at(t_enter), clamped into the grid), and per axis the step (+1, -1 or 0), t_max
// (the t of the next cell boundary on that axis) and t_delta (the t from one boundary to the next, > 0).
// Hint: an axis with r.dir[a] == 0 (+0 or -0) never crosses a boundary: step 0, t_max = t_delta = inf, and
// no division at all.
// Why: why is t_delta the same for every cell along an axis, and what does that spare the walk compared
// with intersecting the ray with each cell's box?
// Step by step: HINTS.md, 02.2.
dda_state dda_setup(const grid_dims& g, const ray& r, float t_enter) {
    STRAHL_TODO("02.2 DDA set-up");
}

}  // namespace strahl::ch02
