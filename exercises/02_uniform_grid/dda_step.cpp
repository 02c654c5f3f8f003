// Exercise 02.3 DDA step (5 points). Read: J. Amanatides and A. Woo, "A Fast Voxel Traversal Algorithm for
// Ray Tracing", Eurographics 1987 (the incremental phase), and the chapter's section "The 3D-DDA".
#include "strahl/ch02/grid.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch02 {

// Advance s to the next cell along the ray and return true, or return false when the walk ends.
//   Step 1, pick the axis a with the smallest s.t_max[a]; on ties the lower axis (x before y before z).
//   Step 2, if s.step[a] == 0 or s.t_max[a] is not finite (inf or NaN): return false (no next cell).
//   Step 3, s.cell[a] += s.step[a]; if the cell left [0, g.res[a] - 1]: return false.
//   Step 4, s.t_max[a] += s.t_delta[a] (the next boundary on that axis); return true.
bool dda_step(const grid_dims& g, dda_state& s) {
    STRAHL_TODO("02.3 DDA step");
}

}  // namespace strahl::ch02
