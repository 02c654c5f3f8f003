// Into an instance's object space: the ray the bottom-level BVH is walked with.
//   I. Wald, C. Benthin, A. Dietrich and P. Slusallek, "Interactive ray tracing on commodity PC clusters"
//   (instancing in OpenRT), and S. Woop et al., "Embree" (instances as a geometry type);
//   pbrt-v4, section 7.1.5 "Object instancing" (the ray, not the mesh, is transformed).
#pragma once
#include "strahl/instancing.hpp"
#include "strahl/ray.hpp"

namespace strahl::ch10 {

// Exercise 10.1 "the ray's object-space transform": the world ray r seen from an instance whose
// world-to-object transform is to_object (the inverse of the instance's to_world). The origin is a point
// (to_object.point), the direction a vector (to_object.vector: no translation), and t keeps its meaning:
// the world point r.org + t r.dir and the object point org' + t dir' are the same point, so tmin and tmax
// are carried over unchanged, and a hit's t needs no conversion back. The direction is not normalised
// (that would rescale t).
ray to_object(const ray& r, const affine& to_object);

}  // namespace strahl::ch10
