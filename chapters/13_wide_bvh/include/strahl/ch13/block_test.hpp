// M triangles against one ray at once: exercise 01.3's Moeller-Trumbore test (T. Moeller and B. Trumbore,
// "Fast, minimum storage ray/triangle intersection", JGT 1997) written on M lanes. Every lane computes
// exactly what the scalar test computes, operation for operation (glm's cross and dot products spelled out
// in glm's order), so a lane's t, u and v are the scalar test's bits and the wide BVH answers exactly what
// brute force answers. Only the early exits are gone: every lane runs to the end, and a mask says which
// lanes hit.
#pragma once
#include "strahl/ch13/wide_bvh.hpp"
#include "strahl/ray.hpp"
#include "strahl/simd.hpp"

namespace strahl::ch13 {

// The ray's origin and direction broadcast to M lanes, once per ray.
template <int M>
struct ray_lanes {
    using vf = simd::vfloat<M>;
    vf org[3], dir[3];
    explicit ray_lanes(const ray& r) {
        for (int a = 0; a < 3; ++a) org[a] = vf(r.org[a]), dir[a] = vf(r.dir[a]);
    }
};

// Which lanes of block b the ray hits with t in (tmin, tmax); their t, u, v.
template <int M>
[[gnu::always_inline]] inline simd::vmask<M> intersect_block(const triangle_block<M>& b, const ray_lanes<M>& r,
                                                             float tmin, float tmax, simd::vfloat<M>& t,
                                                             simd::vfloat<M>& u, simd::vfloat<M>& v) {
    using vf = simd::vfloat<M>;
    const vf e1x = vf::load(b.e1[0]), e1y = vf::load(b.e1[1]), e1z = vf::load(b.e1[2]);
    const vf e2x = vf::load(b.e2[0]), e2y = vf::load(b.e2[1]), e2z = vf::load(b.e2[2]);
    const vf &dx = r.dir[0], &dy = r.dir[1], &dz = r.dir[2];
    // Step 1, the determinant: p = d x e2, det = e1 . p (zero: parallel or degenerate; NaN passes here and
    // fails below, as in the scalar test).
    const vf px = dy * e2z - e2y * dz, py = dz * e2x - e2z * dx, pz = dx * e2y - e2x * dy;
    const vf det = e1x * px + e1y * py + e1z * pz;
    simd::vmask<M> hit = det != vf(0.0f);
    const vf inv_det = vf(1.0f) / det;
    // Step 2, the first barycentric: u = s . p / det with s = org - v0.
    const vf sx = r.org[0] - vf::load(b.v0[0]), sy = r.org[1] - vf::load(b.v0[1]), sz = r.org[2] - vf::load(b.v0[2]);
    const vf bu = (sx * px + sy * py + sz * pz) * inv_det;
    hit = hit & (bu >= vf(0.0f)) & (bu <= vf(1.0f));
    // Step 3, the second barycentric: v = d . q / det with q = s x e1.
    const vf qx = sy * e1z - e1y * sz, qy = sz * e1x - e1z * sx, qz = sx * e1y - e1x * sy;
    const vf bv = (dx * qx + dy * qy + dz * qz) * inv_det;
    hit = hit & (bv >= vf(0.0f)) & (bu + bv <= vf(1.0f));
    // Step 4, the distance: t = e2 . q / det, inside (tmin, tmax).
    const vf bt = (e2x * qx + e2y * qy + e2z * qz) * inv_det;
    hit = hit & (bt > vf(tmin)) & (bt < vf(tmax));
    t = bt, u = bu, v = bv;
    return hit;
}

}  // namespace strahl::ch13
