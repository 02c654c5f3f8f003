// Exercise 10.1 the ray's object-space transform (4 points). Read: object_ray.hpp; pbrt-v4, section 7.1.5.
#include "strahl/ch10/object_ray.hpp"

namespace strahl::ch10 {

ray to_object(const ray& r, const affine& to_object) {
    ray o = r;
    o.org = to_object.point(r.org);    // a point: rotated, scaled and moved
    o.dir = to_object.vector(r.dir);   // a vector: rotated and scaled, never moved, never normalised
    return o;                          // tmin and tmax unchanged: t names the same point in both spaces
}

}  // namespace strahl::ch10
