// Chapter 15's measurements (experiments.hpp): the spheres, the aimed rays, the escape count and the spawn test.
#include "strahl/ch15/experiments.hpp"
#include "strahl/camera.hpp"
#include "strahl/ch15/spawn.hpp"
#include "strahl/parallel.hpp"
#include "strahl/procedural.hpp"
#include "strahl/rng.hpp"
#include "strahl/sampling.hpp"
#include <algorithm>
#include <cmath>

namespace strahl::ch15 {

vec3 placement_direction() { return glm::normalize(vec3(0.6f, -0.3f, 0.74f)); }
vec3 placement::centre() const { return placement_direction() * place; }
vec3 placement::inside() const { return centre() + vec3(0.013f, -0.021f, 0.007f) * scale; }

std::vector<placement> all_placements() {
    std::vector<placement> out;
    for (const float place : {0.0f, 1e3f, 1e5f, 1e6f, 1e7f})
        for (const float scale : {1e-6f, 1e-3f, 1.0f, 1e3f, 1e7f}) out.push_back({scale, place});
    return out;
}

triangle_mesh placed_sphere(int stacks, int slices, const placement& p) {
    triangle_mesh m = tessellated_sphere(stacks, slices);
    const vec3 at = p.centre();
    for (vec3& v : m.positions) v = v * p.scale + at;
    return m;
}

const char* name(aim_kind k) {
    switch (k) {
        case aim_kind::vertex: return "vertex";
        case aim_kind::edge: return "edge";
        case aim_kind::random: return "random";
    }
    return "?";
}

std::size_t aimed_ray_count(int stacks, int slices) {
    const std::size_t vertices = std::size_t(stacks - 1) * std::size_t(slices) + 2;
    const std::size_t triangles = 2 * std::size_t(slices) * std::size_t(stacks - 1);
    return 2 * (vertices + 3 * triangles);
}

vec3 random_point(pcg32& g, const placement& p) {
    const float a = g.next_float(), b = g.next_float();
    return p.centre() + sample_sphere(vec2(a, b)) * p.scale;
}

// make_aimed_rays: exercise 15.4 (exercises/15_robustness/aimed_rays.cpp).

std::vector<std::uint8_t> found(const accel& a, std::span<const ray> rays, progress_bar* bar) {
    std::vector<std::uint8_t> out(rays.size());
    constexpr std::size_t chunk = 4096;
    parallel_for_chunks((rays.size() + chunk - 1) / chunk, 1, [&](std::size_t c0, std::size_t c1) {
        std::vector<hit> hits(chunk);
        for (std::size_t c = c0; c < c1; ++c) {
            const std::size_t first = c * chunk, n = std::min(chunk, rays.size() - first);
            a.intersect(rays.subspan(first, n), std::span<hit>(hits.data(), n));
            for (std::size_t i = 0; i < n; ++i) out[first + i] = hits[i].found() ? 1 : 0;
            if (bar) bar->add(n);
        }
    });
    return out;
}

std::array<std::size_t, 3> escapes(const aimed_rays& r, const std::vector<std::uint8_t>& found) {
    std::array<std::size_t, 3> e{};
    for (const aim_kind k : all_aims)
        for (std::size_t i = r.bounds[int(k)]; i < r.bounds[int(k) + 1]; ++i) e[int(k)] += !found[i];
    return e;
}

const char* name(offset_kind k) {
    switch (k) {
        case offset_kind::none: return "none";
        case offset_kind::fixed: return "fixed";
        case offset_kind::bounded: return "bounded";
        case offset_kind::integer: return "integer";
    }
    return "?";
}

const char* describe(offset_kind k) {
    switch (k) {
        case offset_kind::none: return "the hit point itself, tmin = 0";
        case offset_kind::fixed: return "p + 1e-4 n (one epsilon for every scene)";
        case offset_kind::bounded: return "pbrt-v4: the interpolation's error bound along n";
        case offset_kind::integer: return "Waechter-Binder: 256 ulps along n (2^-16 near the origin)";
    }
    return "?";
}

spawn_counts& spawn_counts::operator+=(const spawn_counts& o) {
    hit_points += o.hit_points, outward += o.outward, outward_self_hits += o.outward_self_hits;
    inward += o.inward, inward_self_hits += o.inward_self_hits, leaks += o.leaks;
    return *this;
}

namespace {

vec3 spawn_origin(offset_kind k, const vec3& p, const vec3& n, const vec3& w, float u, float v,
                  const std::array<vec3, 3>& tri) {
    switch (k) {
        case offset_kind::none: return p;
        case offset_kind::fixed: return offset_fixed(p, n, w, fixed_epsilon);
        case offset_kind::bounded:
            return offset_bounded(p, interpolation_error(1.0f - u - v, u, v, tri[0], tri[1], tri[2]), n, w);
        case offset_kind::integer: return offset_integer(p, n, w);
    }
    return p;
}

// One chunk of the spawn test: `count` first rays from the generator g.
spawn_counts spawn_chunk(const accel& a, const triangle_mesh& m, const placement& pl, offset_kind k,
                         std::size_t count, bool inward, pcg32& g) {
    constexpr float min_sine = 0.19866933f;  // sin(0.2 rad): inward rays at least this far below the plane
    const vec3 o = pl.inside(), centre = pl.centre();
    std::vector<ray> first(count);
    for (ray& r : first) r = ray{o, random_point(g, pl) - o, 0.0f, inf};
    std::vector<hit> hits(count);
    a.intersect(first, hits);
    std::vector<ray> out, in;
    std::vector<std::uint32_t> in_prim;
    spawn_counts c;
    for (std::size_t i = 0; i < count; ++i) {
        const hit& h = hits[i];
        if (!h.found()) continue;
        ++c.hit_points;
        const std::array<vec3, 3> tri = m.triangle(h.prim);
        const vec3 p = (1.0f - h.u - h.v) * tri[0] + h.u * tri[1] + h.v * tri[2];
        vec3 n = glm::normalize(glm::cross(tri[1] - tri[0], tri[2] - tri[0]));
        if (glm::dot(n, p - centre) < 0.0f) n = -n;
        const frame f(n);
        const vec3 w_out = f.to_world(sample_cosine_hemisphere(vec2(g.next_float(), g.next_float())));
        out.push_back(ray{spawn_origin(k, p, n, w_out, h.u, h.v, tri), w_out * pl.scale, 0.0f, inf});
        if (!inward) continue;
        vec3 local;
        do local = sample_cosine_hemisphere(vec2(g.next_float(), g.next_float()));
        while (local.z < min_sine);
        const vec3 w_in = -f.to_world(local);
        in.push_back(ray{spawn_origin(k, p, n, w_in, h.u, h.v, tri), w_in * pl.scale, 0.0f, inf});
        in_prim.push_back(h.prim);
    }
    hits.resize(std::max(out.size(), in.size()));
    a.intersect(out, std::span<hit>(hits.data(), out.size()));
    c.outward = out.size();
    for (std::size_t i = 0; i < out.size(); ++i) c.outward_self_hits += hits[i].found();
    a.intersect(in, std::span<hit>(hits.data(), in.size()));
    c.inward = in.size();
    for (std::size_t i = 0; i < in.size(); ++i) {
        if (!hits[i].found()) ++c.leaks;
        else if (hits[i].prim == in_prim[i] || hits[i].t < 1e-3f) ++c.inward_self_hits;
    }
    return c;
}

}  // namespace

spawn_counts spawn_test(const accel& a, const triangle_mesh& m, const placement& p, offset_kind k,
                        std::size_t points, bool inward, std::uint64_t seed, progress_bar* bar) {
    constexpr std::size_t chunk = 1024;
    const std::size_t chunks = (points + chunk - 1) / chunk;
    std::vector<spawn_counts> per_chunk(chunks);
    parallel_for_chunks(chunks, 1, [&](std::size_t c0, std::size_t c1) {
        for (std::size_t c = c0; c < c1; ++c) {
            pcg32 g(seed, c);
            const std::size_t n = std::min(chunk, points - c * chunk);
            per_chunk[c] = spawn_chunk(a, m, p, k, n, inward, g);
            if (bar) bar->add(n);
        }
    });
    spawn_counts total;
    for (const spawn_counts& c : per_chunk) total += c;
    return total;
}

std::vector<float> scale_steps(int lo_decade, int hi_decade) {
    std::vector<float> out;
    for (int d = lo_decade; d <= hi_decade; ++d)
        out.push_back(std::ldexp(1.0f, int(std::lround(double(d) * std::log2(10.0)))));
    return out;
}

triangle_mesh scaled(const triangle_mesh& m, float s) {
    triangle_mesh out = m;
    for (vec3& p : out.positions) p *= s;
    return out;
}

std::vector<ray> scaled(std::span<const ray> rays, float s) {
    std::vector<ray> out(rays.begin(), rays.end());
    for (ray& r : out) r.org *= s, r.tmin *= s, r.tmax *= s;
    return out;
}

std::vector<ray> scale_view_rays(int width, int height) {
    const vec3 target(0.2f, 1.4f, 0.0f);
    const float distance = 12.0f;
    const camera cam(camera_desc{target + glm::normalize(vec3(0.3f, 0.4f, 1.0f)) * distance, target, vec3(0, 1, 0),
                                 2.0f * glm::degrees(std::atan(2.5f / distance))},
                     width, height);
    std::vector<ray> rays;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) rays.push_back(cam.pixel_ray(x, y));
    return rays;
}

std::size_t count_hits(const accel& a, std::span<const ray> rays) {
    constexpr std::size_t chunk = 64;
    const std::size_t chunks = (rays.size() + chunk - 1) / chunk;
    std::vector<std::size_t> per_chunk(chunks);
    parallel_for_chunks(chunks, 1, [&](std::size_t c0, std::size_t c1) {
        std::vector<hit> hits(chunk);
        for (std::size_t c = c0; c < c1; ++c) {
            const std::size_t first = c * chunk, n = std::min(chunk, rays.size() - first);
            a.intersect(rays.subspan(first, n), std::span<hit>(hits.data(), n));
            for (std::size_t i = 0; i < n; ++i) per_chunk[c] += hits[i].found();
        }
    });
    std::size_t total = 0;
    for (const std::size_t n : per_chunk) total += n;
    return total;
}

float largest_side(const triangle_mesh& m) {
    if (m.positions.empty()) return 0.0f;
    const vec3 e = m.bounds().extent();
    return std::max({e.x, e.y, e.z});
}

}  // namespace strahl::ch15
