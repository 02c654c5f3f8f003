// Chapter 01's renderer (render.cpp and exercise 01.4's Whitted shading), written once for any structure
// and any material form: the tracer answers closest_surface(ray, surface) and occluded_ray(ray), the
// materials answer shade(id, ...), sample_count(id) and sample(id, ...). Same tiles, same seeds, same
// arithmetic in the same order as chapter 01's, so the image is the same bit for bit.
//   T. Whitted, "An Improved Illumination Model for Shaded Display", CACM 23(6), 1980.
#pragma once
#include "strahl/ch01/render.hpp"
#include "strahl/ch01/whitted.hpp"
#include "strahl/ch11/step_accels.hpp"
#include "strahl/parallel.hpp"
#include "strahl/timer.hpp"
#include <mutex>

namespace strahl::ch11 {

template <class Tracer, class Materials>
color whitted(const Tracer& tr, const Materials& mats, std::span<const point_light> lights, const ray& r, int depth,
              ch01::trace_context& ctx) {
    // Step 1, closest hit: a miss sees the background (chapter 01's world: black).
    surface s;
    if (!tr.closest_surface(r, s)) return color(0.0f);
    const vec3 d = glm::normalize(r.dir);
    const vec3 wo = -d;
    color radiance(0.0f);
    // Step 2, direct light through shadow rays.
    for (const point_light& light : lights) {
        const vec3 to_light = light.position - s.p;
        const float d2 = glm::dot(to_light, to_light);
        const vec3 wi = to_light / std::sqrt(d2);
        if (!(glm::dot(s.n, wi) > 0.0f)) continue;
        ++ctx.counts.shadow;
        if (tr.occluded_ray(ch01::shadow_ray(s.p, s.n, light.position))) continue;
        radiance += mats.shade(s.material, wo, s.n, wi) * light.intensity / d2;
    }
    // Step 3, the material's reflection rays, recursively up to the depth limit.
    if (depth < ctx.max_depth) {
        const int n = mats.sample_count(s.material);
        for (int i = 0; i < n; ++i) {
            const ch01::scatter sc = mats.sample(s.material, d, s.n, i, ctx.rng);
            ++ctx.counts.reflection;
            radiance += sc.weight * whitted(tr, mats, lights, ch01::spawn_ray(s.p, s.n, sc.dir), depth + 1, ctx);
        }
    }
    return radiance;
}

// Chapter 01's render loop (render.cpp) over whitted(); settings.primary_only is not offered here.
template <class Tracer, class Materials>
ch01::render_result render_with(const Tracer& tr, const Materials& mats, std::span<const point_light> lights,
                                const camera& cam, const ch01::render_settings& settings) {
    const int width = cam.width(), height = cam.height();
    ch01::render_result out;
    out.img = image(width, height);
    out.rays_per_pixel.assign(std::size_t(width) * height, 0.0f);
    std::mutex merge;
    const timer clock;
    parallel_for_tiles(width, height, settings.tile_size, [&](const tile& t) {
        ch01::trace_context ctx{pcg32(settings.seed, std::uint64_t(t.index)), settings.max_depth, {}};
        for (int y = t.y0; y < t.y1; ++y)
            for (int x = t.x0; x < t.x1; ++x) {
                const ray r = ch01::primary_ray(cam, float(x) + 0.5f, float(y) + 0.5f);
                const std::uint64_t before = ctx.counts.total();
                ++ctx.counts.primary;
                out.img.at(x, y) = whitted(tr, mats, lights, r, 0, ctx);
                out.rays_per_pixel[std::size_t(y) * width + x] = float(ctx.counts.total() - before);
            }
        const std::lock_guard lock(merge);
        out.counts.merge(ctx.counts);
    });
    out.seconds = clock.seconds();
    return out;
}

// The renderers compiled with steps 2, 5 and 6 (steps_impl.hpp) and with step 1 (src/steps.cpp).
ch01::render_result render_virtual(const scene& s, const camera& cam, const ch01::render_settings& settings, int glossy);
ch01::render_result render_variant(const scene& s, const camera& cam, const ch01::render_settings& settings, int glossy);
ch01::render_result render_triangles(const scene& s, const camera& cam, shading materials,
                                     const ch01::render_settings& settings, int glossy);

// The structures compiled in leaf_tests.cpp (steps_impl.hpp).
std::unique_ptr<step_accel> make_variant_accel(bool with_shapes);
std::unique_ptr<step_accel> make_inlined_accel(step s, bool with_shapes);  // step::inlined or step::soa

}  // namespace strahl::ch11
