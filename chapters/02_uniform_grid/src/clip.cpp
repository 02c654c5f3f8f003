// Clipping a ray to the grid box: the slab test of T. L. Kay and J. T. Kajiya, "Ray Tracing Complex
// Scenes", SIGGRAPH 1986, written out per axis so that direction components of +0 and -0 are exact.
#include "strahl/ch02/grid.hpp"

namespace strahl::ch02 {

bool clip_to_grid(const grid_dims& g, const ray& r, float& t_enter, float& t_exit) {
    if (g.cell_count() == 0) return false;
    float t0 = r.tmin, t1 = r.tmax;
    for (int a = 0; a < 3; ++a) {
        const float o = r.org[a], d = r.dir[a];
        if (d == 0.0f) {
            // Parallel to the slab: inside it for every t, or never.
            if (!(o >= g.box.min[a] && o <= g.box.max[a])) return false;
            continue;
        }
        float near = (g.box.min[a] - o) / d, far = (g.box.max[a] - o) / d;
        if (near > far) std::swap(near, far);
        if (near > t0) t0 = near;
        if (far < t1) t1 = far;
    }
    // !(t0 <= t1) also refuses NaNs.
    if (!(t0 <= t1)) return false;
    t_enter = t0;
    t_exit = t1;
    return true;
}

}  // namespace strahl::ch02
