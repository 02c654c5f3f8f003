// Exercise 01.4 Whitted shading: T. Whitted, "An Improved Illumination Model for Shaded Display",
// Communications of the ACM 23(6), 1980 (with point lights, shadow rays and reflection rays; no refraction).
#include "strahl/ch01/whitted.hpp"

namespace strahl::ch01 {

color trace(const world& w, const ray& r, int depth, trace_context& ctx) {
    // Step 1, closest hit: a miss sees the background.
    surface s;
    if (!w.closest_hit(r, s, ctx.counts.tests)) return w.background;
    const vec3 d = glm::normalize(r.dir);
    const vec3 wo = -d;
    color radiance(0.0f);

    // Step 2, direct light: for each point light on the side the normal faces, a shadow ray; if nothing
    // blocks it, the material's f cos times the light's intensity over the squared distance.
    for (const point_light& light : w.lights) {
        const vec3 to_light = light.position - s.p;
        const float d2 = glm::dot(to_light, to_light);
        const vec3 wi = to_light / std::sqrt(d2);
        if (!(glm::dot(s.n, wi) > 0.0f)) continue;
        ++ctx.counts.shadow;
        if (w.occluded(shadow_ray(s.p, s.n, light.position), ctx.counts.tests)) continue;
        radiance += s.mat->shade(wo, s.n, wi) * light.intensity / d2;
    }

    // Step 3, reflection: the material's reflection rays, traced recursively up to the depth limit.
    if (depth < ctx.max_depth) {
        const int n = s.mat->sample_count();
        for (int i = 0; i < n; ++i) {
            const scatter sc = s.mat->sample(d, s.n, i, ctx.rng);
            ++ctx.counts.reflection;
            radiance += sc.weight * trace(w, spawn_ray(s.p, s.n, sc.dir), depth + 1, ctx);
        }
    }
    return radiance;
}

}  // namespace strahl::ch01
