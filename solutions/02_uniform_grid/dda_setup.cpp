// Exercise 02.2 DDA set-up: the initialisation phase of J. Amanatides and A. Woo, "A Fast Voxel Traversal
// Algorithm for Ray Tracing", Eurographics 1987.
#include "strahl/ch02/grid.hpp"
#include <cmath>

namespace strahl::ch02 {

dda_state dda_setup(const grid_dims& g, const ray& r, float t_enter) {
    dda_state s;
    const vec3 p = r.at(t_enter);
    for (int a = 0; a < 3; ++a) {
        // The first cell: the one holding the entry point, clamped (rounding may put p a hair outside).
        const float f = std::floor((p[a] - g.box.min[a]) * g.inv_cell_size[a]);
        s.cell[a] = !(f > 0.0f) ? 0 : f >= float(g.res[a] - 1) ? g.res[a] - 1 : int(f);
        const float d = r.dir[a];
        if (d > 0.0f) {
            // Step +1; the next boundary is the cell's upper face.
            s.step[a] = 1;
            s.t_max[a] = (g.box.min[a] + float(s.cell[a] + 1) * g.cell_size[a] - r.org[a]) / d;
            s.t_delta[a] = g.cell_size[a] / d;
        } else if (d < 0.0f) {
            // Step -1; the next boundary is the cell's lower face.
            s.step[a] = -1;
            s.t_max[a] = (g.box.min[a] + float(s.cell[a]) * g.cell_size[a] - r.org[a]) / d;
            s.t_delta[a] = -g.cell_size[a] / d;
        } else {
            // +0 or -0: the ray never crosses a boundary on this axis.
            s.step[a] = 0;
            s.t_max[a] = inf;
            s.t_delta[a] = inf;
        }
    }
    return s;
}

}  // namespace strahl::ch02
