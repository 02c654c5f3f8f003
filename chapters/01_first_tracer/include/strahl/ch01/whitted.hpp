// Whitted-style ray tracing (exercise 01.4) and the primary ray of the pinhole camera (exercise 01.1).
//
// T. Whitted, "An Improved Illumination Model for Shaded Display", Communications of the ACM 23(6), 1980.
#pragma once
#include "strahl/camera.hpp"
#include "strahl/ch01/world.hpp"
#include "strahl/rng.hpp"

namespace strahl::ch01 {

// Rays by kind, and the primitive tests they cost (tests.v.rays counts every ray the world traced).
struct ray_counts {
    std::uint64_t primary = 0, shadow = 0, reflection = 0;
    counting tests;

    std::uint64_t total() const { return primary + shadow + reflection; }
    void merge(const ray_counts& o) {
        primary += o.primary; shadow += o.shadow; reflection += o.reflection; tests.merge(o.tests);
    }
};

// What one thread carries while tracing: its random numbers, the depth limit, its counts.
struct trace_context {
    pcg32 rng;
    int max_depth = 5;  // reflection rays are spawned only while depth < max_depth (primary rays: depth 0)
    ray_counts counts;
};

// Exercise 01.1 (exercises/01_first_tracer/camera_ray.cpp): the primary ray through image coordinate
// (x, y), built from the camera's eye and basis; the same ray as cam.generate(x, y).
ray primary_ray(const camera& cam, float x, float y);

// Exercise 01.4 (exercises/01_first_tracer/whitted.cpp): radiance arriving along r, which is at recursion
// depth `depth`: closest hit; direct light from every point light that a shadow ray finds unoccluded;
// plus the material's reflection rays, traced recursively while depth < ctx.max_depth. A miss returns the
// background. Counts shadow and reflection rays in ctx.counts (the caller counts primary rays).
color trace(const world& w, const ray& r, int depth, trace_context& ctx);

}  // namespace strahl::ch01
