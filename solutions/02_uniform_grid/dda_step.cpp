// Exercise 02.3 DDA step: the incremental phase of J. Amanatides and A. Woo, "A Fast Voxel Traversal
// Algorithm for Ray Tracing", Eurographics 1987.
#include "strahl/ch02/grid.hpp"

namespace strahl::ch02 {

bool dda_step(const grid_dims& g, dda_state& s) {
    // The axis whose boundary comes first (ties: the lower axis, x before y before z).
    int a = 0;
    if (s.t_max.y < s.t_max[a]) a = 1;
    if (s.t_max.z < s.t_max[a]) a = 2;
    // Every boundary at infinity (or NaN): the walk never leaves this cell by a face.
    if (s.step[a] == 0 || !(s.t_max[a] < inf)) return false;
    s.cell[a] += s.step[a];
    if (s.cell[a] < 0 || s.cell[a] >= g.res[a]) return false;  // left the grid
    s.t_max[a] += s.t_delta[a];
    return true;
}

}  // namespace strahl::ch02
