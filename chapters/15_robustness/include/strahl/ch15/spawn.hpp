// Where a secondary ray starts. A hit point p = o + t d is rounded: it lies a little above or below the
// surface, and a ray leaving it may hit the very triangle it left (a self-hit: shadow acne, dark speckles)
// at a tiny t. Three ways to move the origin off the surface, along the geometric normal n, to the side
// the new direction w leaves to:
//   offset_fixed:    p + eps n, one epsilon for every scene (chapter 01's renderer, with tmin instead);
//                    too small far from the origin, too large (through thin walls) for small scenes;
//   offset_bounded:  M. Pharr, W. Jakob and G. Humphreys, "Physically Based Rendering", 4th ed., 2023,
//                    section 6.8.6 (OffsetRayOrigin): p's rounding error bound e (per axis), projected on
//                    n, is the offset d = |n| . e; the result rounded away from p;
//   offset_integer:  C. Waechter and N. Binder, "A fast and robust method for avoiding self-intersection",
//                    Ray Tracing Gems, chapter 6, 2019: p's bits moved by an integer number of ulps along
//                    n (so the offset scales with |p| without an error analysis), with a small absolute
//                    offset near the origin, where ulps vanish.
#pragma once
#include "strahl/ray.hpp"

namespace strahl::ch15 {

// n turned to the side w leaves to: n if dot(n, w) >= 0, else -n.
inline vec3 facing(const vec3& n, const vec3& w) { return glm::dot(n, w) >= 0.0f ? n : -n; }

inline vec3 offset_fixed(const vec3& p, const vec3& n, const vec3& w, float eps) { return p + eps * facing(n, w); }

// The bound on the rounding of p = b0 v0 + b1 v1 + b2 v2 (barycentric interpolation, pbrt-v4's
// Triangle::InteractionFromIntersection): gamma(7) (|b0 v0| + |b1 v1| + |b2 v2|) per axis.
vec3 interpolation_error(float b0, float b1, float b2, const vec3& v0, const vec3& v1, const vec3& v2);

// pbrt-v4's OffsetRayOrigin: p + d n' with d = |n| . p_error (n' = facing(n, w)), then each coordinate
// rounded one float further from p in the direction it moved.
vec3 offset_bounded(const vec3& p, const vec3& p_error, const vec3& n, const vec3& w);

// Exercise 15.3: Waechter and Binder's offset, with n' = facing(n, w) (not normalised beyond what n is):
//   per axis i: if |p[i]| < 1/32: p[i] + 2^-16 n'[i] (near the origin, a float offset);
//               else p[i]'s bits, as a signed integer, plus int(256 n'[i]) (truncated toward zero) ulps
//               in the direction away from zero when n'[i] and p[i] share a sign, toward zero otherwise
//               (add to the bits when p[i] >= 0, subtract when p[i] < 0).
vec3 offset_integer(const vec3& p, const vec3& n, const vec3& w);

}  // namespace strahl::ch15
