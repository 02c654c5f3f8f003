// Exercise 02.2 DDA set-up (6 points). Read: J. Amanatides and A. Woo, "A Fast Voxel Traversal Algorithm
// for Ray Tracing", Eurographics 1987 (the initialisation phase), and the chapter's section "The 3D-DDA".
#include "strahl/ch02/grid.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch02 {

// Return the walk's state for ray r entering the grid at t_enter (the caller clipped r to g.box).
//   Step 1, the first cell: the cell holding p = r.at(t_enter), per axis
//           floor((p[a] - g.box.min[a]) * g.inv_cell_size[a]) clamped to [0, g.res[a] - 1].
//   Step 2, per axis a with r.dir[a] > 0: step +1, t_max = the t where the ray meets the cell's upper face
//           (x = g.box.min[a] + (cell + 1) * g.cell_size[a]), t_delta = g.cell_size[a] / r.dir[a].
//   Step 3, per axis with r.dir[a] < 0: step -1, t_max at the cell's lower face (g.box.min[a] + cell *
//           g.cell_size[a]), t_delta = g.cell_size[a] / |r.dir[a]| (positive).
//   Step 4, per axis with r.dir[a] == 0 (+0 or -0): step 0, t_max = t_delta = inf.
dda_state dda_setup(const grid_dims& g, const ray& r, float t_enter) {
    STRAHL_TODO("02.2 DDA set-up");
}

}  // namespace strahl::ch02
