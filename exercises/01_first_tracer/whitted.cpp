// Exercise 01.4 Whitted shading (5 points). Read: T. Whitted, "An Improved Illumination Model for Shaded
// Display", Communications of the ACM 23(6), 1980.
#include "strahl/ch01/whitted.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch01 {

// Return the radiance arriving along r, a ray at recursion depth `depth` (primary rays: 0).
//   Step 1, closest hit: w.closest_hit(r, s, ctx.counts.tests); a miss returns w.background. The surface s
//           gives the point s.p, the normal s.n (already facing the ray) and the material s.mat.
//   Step 2, direct light: for each light in w.lights whose direction wi from s.p lies on the side of s.n,
//           count a shadow ray (++ctx.counts.shadow) and, when !w.occluded(shadow_ray(s.p, s.n, light
//           position), ctx.counts.tests), add s.mat->shade(wo, s.n, wi) * intensity / (squared distance).
//           wo = -normalize(r.dir) points back to the viewer. No ambient term.
//   Step 3, reflection: only while depth < ctx.max_depth, for i in [0, s.mat->sample_count()): take
//           sc = s.mat->sample(normalize(r.dir), s.n, i, ctx.rng), count a reflection ray
//           (++ctx.counts.reflection) and add sc.weight * trace(w, spawn_ray(s.p, s.n, sc.dir), depth + 1, ctx).
color trace(const world& w, const ray& r, int depth, trace_context& ctx) {
    STRAHL_TODO("01.4 Whitted shading");
}

}  // namespace strahl::ch01
