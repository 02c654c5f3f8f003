// Chapter 02's uniform grid: the cells, the 3D-DDA state, and the four functions students write.
// Read: J. Amanatides and A. Woo, "A Fast Voxel Traversal Algorithm for Ray Tracing", Eurographics 1987.
//
// The grid splits a box into res.x * res.y * res.z equal cells; cell (x, y, z) covers
// [box.min + (x, y, z) * cell_size, box.min + (x+1, y+1, z+1) * cell_size] and has index x + res.x (y + res.y z).
#pragma once
#include "strahl/aabb.hpp"
#include "strahl/ray.hpp"
#include <glm/vec3.hpp>

namespace strahl::ch02 {

using ivec3 = glm::ivec3;

struct grid_dims {
    aabb box;               // the grid box (axes of zero extent widened: never flat)
    ivec3 res{0};           // cells per axis; all 0 for the empty grid (no cells, every ray misses)
    vec3 cell_size{0.0f};   // (box.max - box.min) / res
    vec3 inv_cell_size{0.0f};  // 1 / cell_size

    int cell_count() const { return res.x * res.y * res.z; }
    int index(const ivec3& c) const { return c.x + res.x * (c.y + res.y * c.z); }
    bool inside(const ivec3& c) const {
        return c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x < res.x && c.y < res.y && c.z < res.z;
    }
    aabb cell_box(const ivec3& c) const {
        return {box.min + vec3(c) * cell_size, box.min + vec3(c + 1) * cell_size};
    }
};

// The cells a box overlaps: every cell c with lo <= c <= hi (per axis, inclusive).
struct cell_range {
    ivec3 lo{0}, hi{-1};
    bool empty() const { return hi.x < lo.x || hi.y < lo.y || hi.z < lo.z; }
};

// The state of the 3D-DDA walk along one ray (Amanatides and Woo's variables).
struct dda_state {
    ivec3 cell{0};          // the current cell
    ivec3 step{0};          // +1, -1 or 0 per axis: the direction the walk moves in
    vec3 t_max{inf};        // per axis, the ray's t at the next cell boundary on that axis
    vec3 t_delta{inf};      // per axis, the t it takes to cross one cell on that axis
};

// The t at which the ray leaves the current cell: the nearest of the three next boundaries.
inline float cell_exit(const dda_state& s) { return std::min(s.t_max.x, std::min(s.t_max.y, s.t_max.z)); }

// Exercise 02.1 cell range: the cells box b overlaps, clamped to the grid. An empty box: an empty range.
cell_range cells_of_box(const grid_dims& g, const aabb& b);

// Exercise 02.2 DDA set-up: the walk's state for ray r entering the grid at t_enter (already clipped to
// the grid box): the first cell, and per axis step, t_max and t_delta.
dda_state dda_setup(const grid_dims& g, const ray& r, float t_enter);

// Exercise 02.3 DDA step: advance s to the next cell along the ray; false when the walk leaves the grid.
bool dda_step(const grid_dims& g, dda_state& s);

// Exercise 02.4 hit in cell: whether the ray's search may end in the current cell: t_end (the best hit's
// t, or the ray's own end) lies safely before the cell's exit t_cell_exit.
bool hit_in_cell(float t_end, float t_cell_exit);

// Clips r's interval (tmin, tmax) to the grid box: false if the ray misses it (or is not finite).
bool clip_to_grid(const grid_dims& g, const ray& r, float& t_enter, float& t_exit);

}  // namespace strahl::ch02
