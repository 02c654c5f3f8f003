// The hand-made grids of chapter 02's exercise tests: a grid of `res` cells over the box [lo, hi].
#pragma once
#include "strahl/ch02/grid.hpp"

namespace strahl::ch02::cases {
inline grid_dims make_grid(vec3 lo, vec3 hi, ivec3 res) {
    grid_dims g;
    g.box = aabb{lo, hi};
    g.res = res;
    g.cell_size = (hi - lo) / vec3(res);
    g.inv_cell_size = vec3(res) / (hi - lo);
    return g;
}
}  // namespace strahl::ch02::cases
