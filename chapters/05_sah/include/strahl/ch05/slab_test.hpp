// The two slab tests of chapter 05's fast traversal. Both choose each axis's near and far plane once per ray
// from the direction's signs, so a box costs no swap; they differ in how a plane's t is computed:
//   robust_slab: t = (plane - org) * (1 / dir), the exit widened by 1 + 2 gamma(3) at every box (chapter 04's
//                test, after Ize): right for every ray, a direction component of +0 or -0 included;
//   fast_slab:   t = plane * (1 / dir) - org * (1 / dir), the second product computed once per ray: one fused
//                multiply-add per plane (a multiply and a subtract where the processor has no FMA), no widening
//                per box. This form rounds relative to |plane| + |org|,
//                not |plane - org|, so the origin's two terms per axis are moved outward once per ray by a
//                bound on that error (below). It needs every product finite: a ray with a zero or tiny
//                direction component gets no fast_slab and takes the robust test.
//   A. Williams, S. Barrus, R. K. Morley and P. Shirley, "An efficient and robust ray-box intersection
//   algorithm", Journal of Graphics Tools 10(1), 2005 (near and far planes from the direction's signs);
//   T. Ize, "Robust BVH ray traversal", Journal of Computer Graphics Techniques 2(2), 2013 (the widening, and
//   why the multiply-subtract form needs more care).
#pragma once
#include "strahl/inlining.hpp"
#include "strahl/ch04/traverse.hpp"
#include <cmath>
#include <optional>

namespace strahl::ch05 {

// Which of a node's six floats (bmin[0..2], bmax[0..2]: bvh.hpp) is the near and which the far plane on
// axis a: bmax is near when the direction's sign bit is set (-0 included).
struct plane_choice {
    int near_plane[3], far_plane[3];
    explicit plane_choice(const vec3& dir) {
        for (int a = 0; a < 3; ++a) {
            const bool down = std::signbit(dir[a]);
            near_plane[a] = down ? 3 + a : a;
            far_plane[a] = down ? a : 3 + a;
        }
    }
};

// Every box optionally grown by `grow` on each side (strahl/tree_query.hpp's space_slack), folded into the
// origin once per ray: the near plane's origin term moves toward the box, the far plane's away. grow = 0
// (pbrt-v4's test, chapter 15's conservative walk) leaves org as it is. The fast walk grows the boxes for
// the rays it gives this test: a ray with a zero direction component passing just beside a box can still
// get a hit from a triangle inside it (the triangle test's rounding); fast_slab's own widening covers that
// for every other ray.
struct robust_slab : plane_choice {
    vec3 org_near, org_far, inv_dir;
    explicit robust_slab(const ray& r, float grow = 0.0f) : plane_choice(r.dir), inv_dir(1.0f / r.dir) {
        for (int a = 0; a < 3; ++a) {
            const float toward = near_plane[a] < 3 ? grow : -grow;  // near plane bmin: going up the axis
            org_near[a] = r.org[a] + toward, org_far[a] = r.org[a] - toward;
        }
    }

    // The entry distance of node n's box for t in [t0, t1], or +inf when the ray misses it. Where the origin
    // lies on a plane and the direction component is +-0, that plane's t is NaN (0 * inf); the comparisons are
    // written so that a NaN never wins (the ray runs in the plane: no constraint).
    STRAHL_ALWAYS_INLINE float entry(const ch04::bvh_node& n, float t0, float t1) const {
        const float* planes = n.bmin;
        for (int a = 0; a < 3; ++a) {
            const float near = (planes[near_plane[a]] - org_near[a]) * inv_dir[a];
            const float far = (planes[far_plane[a]] - org_far[a]) * inv_dir[a];
            t0 = near > t0 ? near : t0;
            t1 = far < t1 ? far : t1;
        }
        t1 *= t1 > 0.0f ? 1.0f + 2.0f * ch04::gamma(3) : 1.0f - 2.0f * ch04::gamma(3);
        return t0 <= t1 ? t0 : inf;
    }
};

// The widening of fast_slab, relative to P + |org| on each axis (P: the largest |coordinate| of the tree's
// box on that axis). Why 2^-20 is enough, with u = 2^-24 the unit roundoff: for a plane p with exact
// t = (p - o) / d, the computed t is (1 + e0)(1 + e3) / d * [(p - o) -+ eps + p e1 - (o +- eps) e2], every
// |e| <= u (+ 2^-52 for e2) (e0: 1 / d, e1: p * inv_dir, e2: the origin's term, rounded once from double,
// e3: the subtraction). The bracket's rounding terms add up to at most u (|p| + |o| + eps); the two outer
// factors move it by at most 2.01 u |p - o| <= 2.01 u (|p| + |o|). An eps of 16 u (|p| + |o|) exceeds both
// together, so the computed near t never exceeds the exact one and the computed far t never falls short of
// it: every box the exact ray meets is met, and entered no later than exactly. (2^-126 more in t covers
// results in the subnormal range, where rounding is absolute.) A fused multiply-add rounds the product and
// the subtraction once, together (e1 = 0): the same bound holds with room to spare. widen = 0 drops the
// bound; the tests show that boxes are then lost, in both forms.
inline constexpr double fast_slab_widen = 0x1p-20;

// Whether the build targets a processor with fused multiply-add (-march=native on most x86-64 processors
// made since 2013, or -mfma). The fast test then computes a plane's t in one instruction: 6 to 8% more rays
// per second on this course's machine (median ratios of alternating strahl-trace runs: chapter 05's README). Without it, std::fma would be a slow library call, so
// the multiply and the subtract stay apart. (-ffp-contract=off keeps the compiler from fusing on its own;
// std::fma is asked for by name.)
#ifdef __FMA__
inline constexpr bool fused_plane_default = true;
#else
inline constexpr bool fused_plane_default = false;
#endif

// A plane's t in the fast test: plane * inv_dir - org_term, fused or not.
template <bool Fused>
STRAHL_ALWAYS_INLINE inline float plane_t(float plane, float inv_dir, float org_term) {
    if constexpr (Fused) return std::fma(plane, inv_dir, -org_term);
    else return plane * inv_dir - org_term;
}

struct fast_slab : plane_choice {
    float inv_dir[3];
    float org_near[3], org_far[3];  // (org +- eps) * inv_dir: the origin's term of the near and the far plane

    // The terms for a ray r and planes inside `bounds` (the tree's box), or nothing when a product could
    // overflow (a direction component zero, subnormal or so small that |plane| / |dir| passes 2^100).
    static std::optional<fast_slab> make(const ray& r, const aabb& bounds, double widen = fast_slab_widen) {
        fast_slab s(r.dir);
        for (int a = 0; a < 3; ++a) {
            const float inv = 1.0f / r.dir[a];
            const double o = r.org[a], p = std::max(std::fabs(bounds.min[a]), std::fabs(bounds.max[a]));
            const double eps = widen * (p + std::fabs(o)), reach = (p + std::fabs(o) + eps) * std::fabs(inv);
            if (!std::isfinite(inv) || !(reach <= 0x1p100)) return std::nullopt;
            // Move the near plane's term toward smaller t and the far plane's toward larger t: d's sign (the
            // sign of inv) says which way the origin moves for that.
            const double toward = inv > 0.0f ? 1.0 : -1.0, tiny = widen > 0.0 ? 0x1p-126 : 0.0;
            s.inv_dir[a] = inv;
            s.org_near[a] = float((o + toward * eps) * inv + tiny);
            s.org_far[a] = float((o - toward * eps) * inv - tiny);
        }
        return s;
    }

    // As robust_slab::entry: two plane_t()s per axis, no NaN possible. Both entry()s are forced inline: g++
    // decides inlining per translation unit, and in one with many other instantiations (measured: the walk
    // instantiated in the race's registry.cpp) it called this one out of line, and Sponza's primary rays ran
    // 29% slower (1.10 against 1.54 Mrays/s in the same session). Fused: see plane_t (the tests run both).
    template <bool Fused = fused_plane_default>
    STRAHL_ALWAYS_INLINE float entry(const ch04::bvh_node& n, float t0, float t1) const {
        const float* planes = n.bmin;
        for (int a = 0; a < 3; ++a) {
            const float near = plane_t<Fused>(planes[near_plane[a]], inv_dir[a], org_near[a]);
            const float far = plane_t<Fused>(planes[far_plane[a]], inv_dir[a], org_far[a]);
            t0 = near > t0 ? near : t0;
            t1 = far < t1 ? far : t1;
        }
        return t0 <= t1 ? t0 : inf;
    }

private:
    explicit fast_slab(const vec3& dir) : plane_choice(dir) {}
};

}  // namespace strahl::ch05
