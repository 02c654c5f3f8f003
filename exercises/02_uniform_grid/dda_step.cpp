// Exercise 02.3 DDA step (5 points). Read: J. Amanatides and A. Woo, "A Fast Voxel Traversal Algorithm for
// Ray Tracing", Eurographics 1987 (the incremental phase), and the chapter's section "The 3D-DDA".
#include "strahl/ch02/grid.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch02 {

// Goal: advance s to the next cell along the ray and return true, or return false when the walk ends (no
// boundary ahead on any axis, or the next cell lies outside the grid). Ties go to the lower axis (x, y, z).
// Hint: the next cell lies across the boundary the ray meets first: the axis with the smallest s.t_max.
// Why: a ray through a cell edge ties two axes and so visits one of two cells it only touches; why does
// neither choice lose a hit (think of the padding of the boxes at insertion), and why fix one all the same?
// Step by step: HINTS.md, 02.3.
bool dda_step(const grid_dims& g, dda_state& s) {
    STRAHL_TODO("02.3 DDA step");
}

}  // namespace strahl::ch02
