// Triangle/box overlap by separating axes: T. Akenine-Moeller, "Fast 3D Triangle-Box Overlap Testing",
// Journal of Graphics Tools, 2001. Thirteen axes: the box's three normals, the triangle's normal, and the
// nine cross products of box and triangle edges. No separating axis among them: they overlap.
#pragma once
#include "strahl/aabb.hpp"

namespace strahl::ch02 {

// Whether triangle (v0, v1, v2) and box b overlap (touching counts as overlapping).
bool triangle_overlaps_box(const vec3& v0, const vec3& v1, const vec3& v2, const aabb& b);

}  // namespace strahl::ch02
