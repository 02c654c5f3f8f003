// M triangles against one ray at once: exercise 01.3's Moeller-Trumbore test (T. Moeller and B. Trumbore,
// "Fast, minimum storage ray/triangle intersection", JGT 1997) written on M lanes. Every lane computes
// exactly what the scalar test computes, operation for operation (glm's cross and dot products spelled out
// in glm's order), so a lane's t, u and v are the scalar test's bits and the wide BVH answers exactly what
// brute force answers. Only the early exits are gone: every lane runs to the end, and a mask says which
// lanes hit.
//
// Below it, chapter 15's watertight test on M lanes (S. Woop, C. Benthin and I. Wald, "Watertight ray/
// triangle intersection", JCGT 2013), step for step as exercise 15.2 writes it, so that its lanes equal
// brute force with that test bit for bit.
#pragma once
#include "strahl/inlining.hpp"
#include "strahl/ch13/wide_bvh.hpp"
#include "strahl/ray.hpp"
#include "strahl/simd.hpp"
#include <bit>
#include <utility>

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
STRAHL_ALWAYS_INLINE inline simd::vmask<M> intersect_block(const triangle_block<M>& b, const ray_lanes<M>& r,
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

// The watertight test needs the corners themselves (v0 + e1 rounds: it is not v1): v[corner][axis][lane],
// filled from the ids of the tree's triangle_block of the same index.
template <int M>
struct alignas(64) vertex_block {
    float v[3][3][M];
};

// The ray moved to the origin and sheared onto +z, once per ray: exercise 15.1's permutation and shear.
template <int M>
struct shear_lanes {
    using vf = simd::vfloat<M>;
    int kx = 0, ky = 1, kz = 2;
    vf org[3], sx, sy, sz;
    explicit shear_lanes(const ray& r) {
        const vec3 a = glm::abs(r.dir);
        kz = a.x >= a.y ? (a.x >= a.z ? 0 : 2) : (a.y >= a.z ? 1 : 2);
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        if (r.dir[kz] < 0.0f) std::swap(kx, ky);
        sx = vf(r.dir[kx] / r.dir[kz]), sy = vf(r.dir[ky] / r.dir[kz]), sz = vf(1.0f / r.dir[kz]);
        for (int k = 0; k < 3; ++k) org[k] = vf(r.org[k]);
    }
};

// Which lanes of block b the ray hits with t in (tmin, tmax); their t, u, v. Steps a to e of exercise 15.2.
template <int M>
STRAHL_ALWAYS_INLINE inline simd::vmask<M> intersect_block_watertight(const vertex_block<M>& b,
                                                                      const shear_lanes<M>& s, float tmin,
                                                                        float tmax, simd::vfloat<M>& t,
                                                                        simd::vfloat<M>& u, simd::vfloat<M>& v) {
    using vf = simd::vfloat<M>;
    // a. The corners relative to the origin (only the three axes the shear uses), sheared in x and y.
    const auto rel = [&](int corner, int axis) { return vf::load(b.v[corner][axis]) - s.org[axis]; };
    const vf akx = rel(0, s.kx), aky = rel(0, s.ky), akz = rel(0, s.kz);
    const vf bkx = rel(1, s.kx), bky = rel(1, s.ky), bkz = rel(1, s.kz);
    const vf ckx = rel(2, s.kx), cky = rel(2, s.ky), ckz = rel(2, s.kz);
    const vf ax = akx - s.sx * akz, ay = aky - s.sy * akz;
    const vf bx = bkx - s.sx * bkz, by = bky - s.sy * bkz;
    const vf cx = ckx - s.sx * ckz, cy = cky - s.sy * ckz;
    // b. The edge functions; lanes where one is exactly 0 again in double (rare: a lane at a time).
    vf eu = cx * by - cy * bx, ev = ax * cy - ay * cx, ew = bx * ay - by * ax;
    const vf zero(0.0f);
    if (unsigned z = simd::movemask((eu == zero) | (ev == zero) | (ew == zero))) {
        alignas(64) float x[6][M], e[3][M];
        ax.store(x[0]), ay.store(x[1]), bx.store(x[2]), by.store(x[3]), cx.store(x[4]), cy.store(x[5]);
        eu.store(e[0]), ev.store(e[1]), ew.store(e[2]);
        for (; z != 0; z &= z - 1) {
            const int i = std::countr_zero(z);
            const double dax = x[0][i], day = x[1][i], dbx = x[2][i], dby = x[3][i], dcx = x[4][i], dcy = x[5][i];
            e[0][i] = float(dcx * dby - dcy * dbx);
            e[1][i] = float(dax * dcy - day * dcx);
            e[2][i] = float(dbx * day - dby * dax);
        }
        eu = vf::load(e[0]), ev = vf::load(e[1]), ew = vf::load(e[2]);
    }
    // c. Mixed signs: outside; det = 0 or NaN: no hit.
    const simd::vmask<M> negative = (eu < zero) | (ev < zero) | (ew < zero);
    const simd::vmask<M> positive = (zero < eu) | (zero < ev) | (zero < ew);
    const vf det = eu + ev + ew;
    simd::vmask<M> hit = ~(negative & positive) & ((det < zero) | (zero < det));
    // d. The sheared depths and T; e. t = T / det in (tmin, tmax), u and v.
    const vf az = s.sz * akz, bz = s.sz * bkz, cz = s.sz * ckz;
    const vf big_t = eu * az + ev * bz + ew * cz;
    const vf tt = big_t / det;
    hit = hit & (vf(tmin) < tt) & (tt < vf(tmax));
    // Parallel edges in float (glm::cross of v1 - v0 and v2 - v0 is exactly 0): degenerate, no hit. Only
    // where a lane hits.
    if (simd::movemask(hit) != 0) {
        vf e1[3], e2[3];
        for (int a = 0; a < 3; ++a) {
            const vf v0 = vf::load(b.v[0][a]);
            e1[a] = vf::load(b.v[1][a]) - v0, e2[a] = vf::load(b.v[2][a]) - v0;
        }
        const vf nx = e1[1] * e2[2] - e2[1] * e1[2], ny = e1[2] * e2[0] - e2[2] * e1[0],
                 nz = e1[0] * e2[1] - e2[0] * e1[1];
        hit = hit & ~((nx == zero) & (ny == zero) & (nz == zero));
    }
    t = tt, u = ev / det, v = ew / det;
    return hit;
}

}  // namespace strahl::ch13
