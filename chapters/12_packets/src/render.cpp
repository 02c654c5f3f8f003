// The packet renderer (render.hpp).
#include "strahl/ch12/render.hpp"
#include "strahl/ch11/materials.hpp"
#include "strahl/ch11/render.hpp"
#include "strahl/ch11/shapes.hpp"
#include "strahl/parallel.hpp"
#include "strahl/timer.hpp"
#include <mutex>

namespace strahl::ch12 {

accel_tracer::accel_tracer(const accel& a, const scene& s)
    : a_(&a), mesh_(&s.mesh), materials_(ch11::make_material_ids(s, false)) {}

// As chapter 11's tracers make it: the normal from cross(v1 - v0, v2 - v0), normalised, facing the ray.
ch11::surface accel_tracer::surface_of(const ray& r, const hit& h) const {
    ch11::surface s;
    s.h = h;
    s.p = r.at(h.t);
    const auto v = mesh_->triangle(h.prim);
    const vec3 c = glm::cross(v[1] - v[0], v[2] - v[0]);
    const float len = glm::length(c);
    s.n = len > 0.0f ? c / len : vec3(0.0f, 0.0f, 1.0f);
    if (glm::dot(s.n, r.dir) > 0.0f) s.n = -s.n;  // two-sided: face the incoming ray
    s.material = materials_[h.prim];
    return s;
}

bool accel_tracer::closest_surface(const ray& r, ch11::surface& s) const {
    hit h;
    a_->intersect(std::span<const ray>(&r, 1), std::span<hit>(&h, 1));
    if (!h.found()) return false;
    s = surface_of(r, h);
    return true;
}

bool accel_tracer::occluded_ray(const ray& r) const {
    std::uint8_t blocked = 0;
    a_->occluded(std::span<const ray>(&r, 1), std::span<std::uint8_t>(&blocked, 1));
    return blocked != 0;
}

ch01::render_result render_single(const accel& single, const scene& s, const camera& cam,
                                  const ch01::render_settings& settings, int glossy) {
    return ch11::render_with(accel_tracer(single, s), ch11::make_variant_materials(s, glossy), s.lights, cam, settings);
}

ch01::render_result render_packets(const accel& packets, const accel& single, const scene& s, const camera& cam,
                                   const ch01::render_settings& settings, int glossy) {
    const accel_tracer batch(packets, s), alone(single, s);
    const auto mats = ch11::make_variant_materials(s, glossy);
    const std::span<const point_light> lights = s.lights;
    const int width = cam.width(), height = cam.height();
    ch01::render_result out;
    out.img = image(width, height);
    out.rays_per_pixel.assign(std::size_t(width) * height, 0.0f);
    std::mutex merge;
    const timer clock;
    parallel_for_tiles(width, height, settings.tile_size, [&](const tile& t) {
        ch01::trace_context ctx{pcg32(settings.seed, std::uint64_t(t.index)), settings.max_depth, {}};
        const int tw = t.x1 - t.x0, th = t.y1 - t.y0;
        // 1. The tile's primary rays in 4x4 blocks (consecutive rays: a packet each), one batch.
        std::vector<int> slot(std::size_t(tw) * th);  // pixel (row-major in the tile) -> its place in the batch
        std::vector<ray> rays;
        rays.reserve(slot.size());
        for (int by = 0; by < th; by += 4)
            for (int bx = 0; bx < tw; bx += 4)
                for (int y = by; y < std::min(by + 4, th); ++y)
                    for (int x = bx; x < std::min(bx + 4, tw); ++x) {
                        slot[std::size_t(y) * tw + x] = int(rays.size());
                        rays.push_back(ch01::primary_ray(cam, float(t.x0 + x) + 0.5f, float(t.y0 + y) + 0.5f));
                    }
        std::vector<hit> hits(rays.size());
        packets.intersect(rays, hits);
        // 2. Every shadow ray of those hits, in the order shading asks for them, one batch.
        std::vector<ch11::surface> surfaces(rays.size());
        std::vector<ray> shadows;
        std::vector<std::size_t> first_shadow(rays.size() + 1, 0);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            first_shadow[i] = shadows.size();
            if (!hits[i].found()) continue;
            const ch11::surface& sf = surfaces[i] = batch.surface_of(rays[i], hits[i]);
            for (const point_light& light : lights) {
                const vec3 to_light = light.position - sf.p;
                const vec3 wi = to_light / std::sqrt(glm::dot(to_light, to_light));
                if (glm::dot(sf.n, wi) > 0.0f) shadows.push_back(ch01::shadow_ray(sf.p, sf.n, light.position));
            }
        }
        first_shadow[rays.size()] = shadows.size();
        std::vector<std::uint8_t> blocked(shadows.size());
        packets.occluded(shadows, blocked);
        // 3. Each pixel in chapter 01's order (the random numbers' order), whitted()'s steps with the batches'
        // answers at depth 0, its reflection rays one at a time.
        for (int y = 0; y < th; ++y)
            for (int x = 0; x < tw; ++x) {
                const std::size_t i = std::size_t(slot[std::size_t(y) * tw + x]);
                const std::uint64_t before = ctx.counts.total();
                ++ctx.counts.primary;
                color radiance(0.0f);
                if (hits[i].found()) {
                    const ch11::surface& sf = surfaces[i];
                    const vec3 d = glm::normalize(rays[i].dir);
                    const vec3 wo = -d;
                    std::size_t next = first_shadow[i];
                    for (const point_light& light : lights) {
                        const vec3 to_light = light.position - sf.p;
                        const float d2 = glm::dot(to_light, to_light);
                        const vec3 wi = to_light / std::sqrt(d2);
                        if (!(glm::dot(sf.n, wi) > 0.0f)) continue;
                        ++ctx.counts.shadow;
                        if (blocked[next++]) continue;
                        radiance += mats.shade(sf.material, wo, sf.n, wi) * light.intensity / d2;
                    }
                    if (0 < ctx.max_depth) {
                        const int n = mats.sample_count(sf.material);
                        for (int k = 0; k < n; ++k) {
                            const ch01::scatter sc = mats.sample(sf.material, d, sf.n, k, ctx.rng);
                            ++ctx.counts.reflection;
                            radiance += sc.weight * ch11::whitted(alone, mats, lights, ch01::spawn_ray(sf.p, sf.n, sc.dir), 1, ctx);
                        }
                    }
                }
                out.img.at(t.x0 + x, t.y0 + y) = radiance;
                out.rays_per_pixel[std::size_t(t.y0 + y) * width + t.x0 + x] = float(ctx.counts.total() - before);
            }
        const std::lock_guard lock(merge);
        out.counts.merge(ctx.counts);
    });
    out.seconds = clock.seconds();
    return out;
}

}  // namespace strahl::ch12
