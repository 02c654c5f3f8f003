// Exercise 01.4 Whitted shading (5 points). Read: T. Whitted, "An Improved Illumination Model for Shaded
// Display", Communications of the ACM 23(6), 1980.
#include "strahl/ch01/whitted.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch01 {

// Goal: the radiance arriving along r, a ray at recursion depth `depth` (primary rays: 0): the background on
// a miss; at the closest hit, the light of every point light that a shadow ray reaches (no ambient term),
// plus the material's reflection rays, each weighted and traced recursively while depth < ctx.max_depth.
// Every shadow and reflection ray is counted in ctx.counts.
// Hint: a light on the far side of the surface (wi against s.n) gets no shadow ray at all.
// Why: why does a rough mirror that sees another mirror cost about S^2 rays per pixel, and what does each of
// those rays cost in chapter 01's world?
// Step by step: HINTS.md, 01.4.
color trace(const world& w, const ray& r, int depth, trace_context& ctx) {
    STRAHL_TODO("01.4 Whitted shading");
}

}  // namespace strahl::ch01
