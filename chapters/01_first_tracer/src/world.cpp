// The world and brute force: every ray tests every primitive through a virtual call.
#include "strahl/ch01/world.hpp"
#include "strahl/ch01/shapes.hpp"
#include <stdexcept>
#include <string>

namespace strahl::ch01 {

std::uint32_t world::add(std::unique_ptr<material> m) {
    materials.push_back(std::move(m));
    return std::uint32_t(materials.size() - 1);
}

std::uint32_t world::add(std::unique_ptr<primitive> p) {
    if (p->material() >= materials.size())
        throw std::invalid_argument("world: primitive names material " + std::to_string(p->material()) +
                                    " but the world has " + std::to_string(materials.size()));
    primitives.push_back(std::move(p));
    return std::uint32_t(primitives.size() - 1);
}

// Brute force closest hit: test every primitive; each hit shortens the ray, so later tests only accept
// closer hits.
bool world::closest_hit(const ray& r, surface& s, counting& c) const {
    c.ray();
    ray shortened = r;
    hit best;
    for (std::size_t i = 0; i < primitives.size(); ++i) {
        c.prim_test();
        hit h;
        if (primitives[i]->intersect(shortened, h)) {
            best = h;
            best.prim = std::uint32_t(i);
            shortened.tmax = h.t;
        }
    }
    if (!best.found()) return false;
    const primitive& p = *primitives[best.prim];
    s.h = best;
    s.p = r.at(best.t);
    s.n = p.normal(s.p, best);
    if (glm::dot(s.n, r.dir) > 0.0f) s.n = -s.n;  // two-sided: face the incoming ray
    s.mat = materials[p.material()].get();
    return true;
}

// Brute force any hit: the first primitive that blocks the ray ends the search.
bool world::occluded(const ray& r, counting& c) const {
    c.ray();
    for (const auto& p : primitives) {
        c.prim_test();
        hit h;
        if (p->intersect(r, h)) return true;
    }
    return false;
}

namespace {
vec3 offset_origin(const vec3& p, const vec3& n) {
    const vec3 a = glm::abs(p);
    const float scale = std::max(1.0f, std::max(a.x, std::max(a.y, a.z)));
    return p + (1e-4f * scale) * n;
}
}  // namespace

ray spawn_ray(const vec3& p, const vec3& n, const vec3& dir) { return ray{offset_origin(p, n), dir, 0.0f, inf}; }

ray shadow_ray(const vec3& p, const vec3& n, const vec3& to) {
    const vec3 org = offset_origin(p, n);
    return ray{org, to - org, 0.0f, 1.0f - 1e-4f};
}

world build_world(const scene& s, int glossy_samples, world_counts* counts) {
    world w;
    for (const material_desc& m : s.materials) {
        switch (m.kind) {
        case material_kind::diffuse: w.add(std::make_unique<diffuse>(m.albedo)); break;
        case material_kind::mirror: w.add(std::make_unique<mirror>(m.albedo)); break;
        case material_kind::rough_mirror:
            w.add(std::make_unique<rough_mirror>(m.albedo, m.roughness, glossy_samples));
            break;
        }
    }
    if (w.materials.empty()) w.add(std::make_unique<diffuse>(color(0.8f)));
    world_counts n;
    for (std::size_t i = 0; i < s.mesh.triangle_count(); ++i) {
        const auto v = s.mesh.triangle(i);
        w.add(std::make_unique<triangle>(v[0], v[1], v[2], s.triangle_material(i)));
        ++n.triangles;
    }
    for (const sphere_desc& sp : s.spheres) {
        if (!(sp.radius > 0.0f) || !is_finite(sp.center))
            throw std::invalid_argument("scene '" + s.name + "': a sphere needs a finite centre and radius > 0");
        w.add(std::make_unique<sphere>(sp.center, sp.radius, sp.material));
        ++n.spheres;
    }
    for (const plane_desc& pl : s.planes) {
        if (!is_finite(pl.normal) || glm::length(pl.normal) == 0.0f || !std::isfinite(pl.offset))
            throw std::invalid_argument("scene '" + s.name + "': a plane needs a finite, non-zero normal");
        w.add(std::make_unique<plane>(pl.normal, pl.offset, pl.material));
        ++n.planes;
    }
    w.lights = s.lights;
    if (counts) *counts = n;
    return w;
}

}  // namespace strahl::ch01
