#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch01/world.hpp"
#include "strahl/parallel.hpp"
#include "strahl/rng.hpp"
#include "strahl/sampling.hpp"
#include "strahl/timer.hpp"
#include <stdexcept>

namespace strahl::ch01 {

ray_kind parse_ray_kind(const std::string& name) {
    if (name == "primary") return ray_kind::primary;
    if (name == "diffuse") return ray_kind::diffuse;
    if (name == "shadow") return ray_kind::shadow;
    throw std::invalid_argument("unknown ray set '" + name + "' (have: primary, diffuse, shadow)");
}

std::string to_string(ray_kind k) {
    switch (k) {
        case ray_kind::primary: return "primary";
        case ray_kind::diffuse: return "diffuse";
        case ray_kind::shadow: return "shadow";
    }
    return "?";
}

std::vector<ray> primary_rays(const scene& s, int width, int height) {
    if (width < 1 || height < 1) throw std::invalid_argument("primary_rays: image size must be positive");
    const camera cam = scene_camera(s, width, height);  // (a camera that cannot be made names the scene)
    std::vector<ray> rays;
    rays.reserve(std::size_t(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) rays.push_back(cam.pixel_ray(x, y));
    return rays;
}

std::vector<ray> secondary_rays(ray_kind kind, const scene& s, std::span<const ray> primary,
                                std::span<const hit> primary_hits, std::uint64_t seed) {
    if (kind == ray_kind::primary) throw std::invalid_argument("secondary_rays: primary rays are not secondary");
    if (kind == ray_kind::shadow && s.lights.empty())
        throw std::invalid_argument("scene '" + s.name + "' has no point light for shadow rays");
    if (primary.size() != primary_hits.size()) throw std::invalid_argument("secondary_rays: rays and hits differ in count");
    pcg32 rng(seed, 0x5eed);
    std::vector<ray> rays;
    for (std::size_t i = 0; i < primary.size(); ++i) {
        const hit& h = primary_hits[i];
        if (!h.found()) continue;
        // The hit point from the barycentrics (more accurate than org + t dir), and the geometric normal
        // turned towards where the ray came from.
        const auto tri = s.mesh.triangle(h.prim);
        const vec3 p = (1.0f - h.u - h.v) * tri[0] + h.u * tri[1] + h.v * tri[2];
        vec3 n = glm::cross(tri[1] - tri[0], tri[2] - tri[0]);
        const float len = glm::length(n);
        n = len > 0.0f ? n / len : -glm::normalize(primary[i].dir);
        if (glm::dot(n, primary[i].dir) > 0.0f) n = -n;
        if (kind == ray_kind::diffuse) {
            const vec3 local = sample_cosine_hemisphere(vec2(rng.next_float(), rng.next_float()));
            rays.push_back(ch01::spawn_ray(p, n, frame(n).to_world(local)));
        } else {
            rays.push_back(ch01::shadow_ray(p, n, s.lights.front().position));
        }
    }
    return rays;
}

// How many rays one thread takes at a time: about 1,024, at a multiple of the structure's batch alignment
// (whole rows of tiles for packet tracers), so that no chunk cuts a tile. A set too small for 8 such chunks
// per thread (the bunny's 3,926 secondary rays against rows of 768) is cut into 8 chunks per thread
// instead, each a multiple of 32 rays and, where it is longer than a row of tiles, of the alignment: the
// threads' share then differs by a fraction of a chunk, not by a row of 768 rays (a bound of 1.64x on two
// threads). A cut inside a row of tiles only regroups the rays of the packets at the cut; every exact
// structure returns the same hits, whatever the grouping.
std::size_t thread_chunk(std::size_t n, std::size_t align, int threads) {
    const std::size_t whole = (std::max<std::size_t>(1024, align) + align - 1) / align * align;
    const std::size_t parts = 8 * std::size_t(threads);
    if (n >= whole * parts) return whole;
    const std::size_t fine = std::max<std::size_t>(32, (n + parts - 1) / parts);
    const std::size_t step = fine >= align ? align : 32;
    return (fine + step - 1) / step * step;
}

namespace {
// Calls f(begin, end) on consecutive chunks of [0, n) on `threads` threads (thread_chunk).
template <class F>
void for_chunks(const accel& a, std::size_t n, int threads, F&& f) {
    if (threads <= 1) return f(std::size_t(0), n);
    const std::size_t chunk = thread_chunk(n, std::max<std::size_t>(1, a.batch_alignment()), threads);
    const thread_limit limit(threads);
    parallel_for_chunks((n + chunk - 1) / chunk, 1, [&](std::size_t b, std::size_t e) {
        for (std::size_t c = b; c < e; ++c) f(c * chunk, std::min(n, (c + 1) * chunk));
    });
}
}  // namespace

void trace_closest(const accel& a, std::span<const ray> rays, std::span<hit> hits, int threads) {
    for_chunks(a, rays.size(), threads, [&](std::size_t b, std::size_t e) {
        a.intersect(rays.subspan(b, e - b), hits.subspan(b, e - b));
    });
}

void trace_any(const accel& a, std::span<const ray> rays, std::span<std::uint8_t> blocked, int threads) {
    for_chunks(a, rays.size(), threads, [&](std::size_t b, std::size_t e) {
        a.occluded(rays.subspan(b, e - b), blocked.subspan(b, e - b));
    });
}

std::vector<ray> make_rays(ray_kind kind, const scene& s, int width, int height, std::uint64_t seed,
                           const accel& exact, int threads) {
    std::vector<ray> primary = primary_rays(s, width, height);
    if (kind == ray_kind::primary) return primary;
    std::vector<hit> hits(primary.size());
    trace_closest(exact, primary, hits, threads);
    return secondary_rays(kind, s, primary, hits, seed);
}

checked_rays make_checked_rays(const scene& s, int width, int height, const accel& exact) {
    checked_rays c;
    c.primary = primary_rays(s, width, height);
    c.primary_hits.resize(c.primary.size());
    exact.intersect(c.primary, c.primary_hits);
    c.diffuse = secondary_rays(ray_kind::diffuse, s, c.primary, c.primary_hits, 1);
    c.diffuse_hits.resize(c.diffuse.size());
    exact.intersect(c.diffuse, c.diffuse_hits);
    return c;
}

checked_speed time_checked(const accel& a, const checked_rays& rays, int repeats) {
    std::vector<hit> hits(rays.primary.size()), dhits(rays.diffuse.size());
    const double p_ms = median_ms(repeats, [&] { a.intersect(rays.primary, hits); });
    const double d_ms = median_ms(repeats, [&] { a.intersect(rays.diffuse, dhits); });
    checked_speed c;
    c.differing = hits_differing(hits, rays.primary_hits) + hits_differing(dhits, rays.diffuse_hits);
    c.primary_mrays = double(rays.primary.size()) / p_ms * 1e-3;
    c.diffuse_mrays = double(rays.diffuse.size()) / d_ms * 1e-3;
    return c;
}

}  // namespace strahl::ch01
