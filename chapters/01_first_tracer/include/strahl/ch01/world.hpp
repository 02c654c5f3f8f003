// The world: every primitive in one std::vector of owning pointers, tested one by one (brute force).
// A ray costs one virtual intersect() call per primitive, hit or not: linear in the primitive count.
#pragma once
#include "strahl/ch01/materials.hpp"
#include "strahl/ch01/primitive.hpp"
#include "strahl/scene.hpp"
#include "strahl/stats.hpp"
#include <memory>
#include <vector>

namespace strahl::ch01 {

// What the tracer needs to know about a closest hit.
struct surface {
    hit h;                         // t, primitive index (h.prim), barycentrics
    vec3 p{0.0f};                  // hit point
    vec3 n{0.0f};                  // unit normal, turned to face the incoming ray
    const material* mat = nullptr;
};

class world {
public:
    std::vector<std::unique_ptr<primitive>> primitives;
    std::vector<std::unique_ptr<material>> materials;
    std::vector<point_light> lights;
    color background{0.0f};

    // Adds a material or primitive; returns its index. A primitive's material id must name a material.
    std::uint32_t add(std::unique_ptr<material> m);
    std::uint32_t add(std::unique_ptr<primitive> p);

    // Brute force closest hit: tests every primitive, shrinking tmax as hits are found. Counts one ray and
    // one primitive test per primitive in c. Fills s and returns true on a hit.
    bool closest_hit(const ray& r, surface& s, counting& c) const;
    // Brute force any hit (shadow rays): stops at the first primitive hit in (tmin, tmax).
    bool occluded(const ray& r, counting& c) const;
};

// A ray leaving surface point p (normal n facing the side it leaves to) in direction dir, its origin moved
// off the surface by a small offset relative to the point's magnitude, so it does not hit its own surface.
ray spawn_ray(const vec3& p, const vec3& n, const vec3& dir);
// The shadow ray from p (normal n facing the light) to a point light at `to`: t in (0, 1) reaches the light.
ray shadow_ray(const vec3& p, const vec3& n, const vec3& to);

struct world_counts {
    std::size_t triangles = 0, spheres = 0, planes = 0;
};

// The scene as objects: one triangle object per mesh triangle (with its material id), spheres, planes,
// its lights. Rough mirrors take glossy_samples reflection rays per hit.
world build_world(const scene& s, int glossy_samples = 16, world_counts* counts = nullptr);

}  // namespace strahl::ch01
