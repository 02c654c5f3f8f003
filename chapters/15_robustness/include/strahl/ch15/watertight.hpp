// The watertight ray/triangle test: S. Woop, C. Benthin and I. Wald, "Watertight ray/triangle
// intersection", Journal of Computer Graphics Techniques 2(1), 2013.
//
// Moeller-Trumbore (exercise 01.3) decides "inside" from barycentrics computed per triangle, each with its
// own rounding: along an edge two neighbours can both say "outside", and a ray aimed at the edge escapes
// through a crack that is not in the mesh. The watertight test moves the ray to the origin and shears space
// so the ray runs along +z (step 1, once per ray), then decides inside with three 2D edge functions of the
// projected vertices (step 2). Two triangles sharing an edge compute that edge's function from the same two
// projected vertices with the same operations, so its value is the same number with opposite sign: a ray
// can no longer be outside both. Where an edge function is exactly 0, it is computed again in double, where
// the products of floats are exact: its sign is then right.
#pragma once
#include "strahl/ray.hpp"

namespace strahl::ch15 {

// Step 1, per ray (exercise 15.1): the permutation and the shear.
//   kz: the axis along which |dir| is largest (the first such on ties: x before y before z); kx = kz + 1 and
//       ky = kx + 1 (mod 3), swapped when dir[kz] < 0 so that the permutation keeps the triangles' winding;
//   sx = dir[kx] / dir[kz], sy = dir[ky] / dir[kz], sz = 1 / dir[kz]: a point p, moved by -org, maps to
//       (p[kx] - sx p[kz], p[ky] - sy p[kz], sz p[kz]), and the ray to the +z axis from the origin.
// A NaN or zero direction gives NaN or infinite factors, and then no hit (step 2 tolerates them).
struct shear {
    int kx = 0, ky = 1, kz = 2;
    float sx = 0.0f, sy = 0.0f, sz = 1.0f;
};
shear make_shear(const vec3& dir);

// Step 2, per triangle (exercise 15.2), with r's shear s = make_shear(r.dir):
//   a. the vertices relative to the origin, A = v0 - org, B = v1 - org, C = v2 - org, then sheared in x and
//      y: Ax = A[kx] - sx A[kz], Ay = A[ky] - sy A[kz], and so for B and C;
//   b. the edge functions U = Cx By - Cy Bx, V = Ax Cy - Ay Cx, W = Bx Ay - By Ax (floats, in this order of
//      operations: a product, a product, their difference); if any is exactly 0, all three again in double
//      from the same floats (each product exact in double), rounded back to float;
//   c. outside if the three have mixed signs (some < 0 and some > 0); det = U + V + W, no hit if det is 0
//      (or NaN): a ray in the triangle's plane, or a degenerate triangle; and no hit on a triangle whose
//      edges are parallel in float, (v1 - v0) x (v2 - v0) == (0, 0, 0) (glm::cross, compared per axis; the
//      shear's rounding can give such a triangle a tiny area and a hit: pbrt-v4's test makes the same check);
//      only tested where the signs agree, so it costs nothing on the many misses;
//   d. the sheared depths Az = sz A[kz], Bz, Cz, and T = U Az + V Bz + W Cz (left to right);
//   e. t = T / det, accepted only in (tmin, tmax); then u = V / det, v = W / det (the weights of v1 and v2,
//      as exercise 01.3 names them).
// Two-sided, like every course test. Returns whether r hits, and then t, u, v.
bool intersect_watertight(const ray& r, const shear& s, const vec3& v0, const vec3& v1, const vec3& v2, float& t,
                          float& u, float& v);

// The same test in double throughout (shear, edge functions, depths, t, u, v; rounded to float at the end,
// t checked against the interval in double). Correct signs everywhere with no fallback; the cost of double.
bool intersect_watertight_double(const ray& r, const vec3& v0, const vec3& v1, const vec3& v2, float& t,
                                 float& u, float& v);

// Moeller and Trumbore's test as their paper prints it: a hit needs |det| >= 1e-6 (their EPSILON), an
// absolute threshold that knows nothing of the scene's scale. Otherwise exercise 01.3's steps and rules.
bool intersect_mt_epsilon(const ray& r, const vec3& v0, const vec3& v1, const vec3& v2, float& t, float& u,
                          float& v);

}  // namespace strahl::ch15
