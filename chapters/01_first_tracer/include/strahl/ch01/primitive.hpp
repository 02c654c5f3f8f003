// Chapter 01: the object-oriented tracer. Everything a ray can hit is a `primitive`, everything a surface
// does with light is a `material`; both are abstract classes, and the tracer calls them through `virtual`
// functions without knowing what they are. This is the starting point the rest of the course speeds up.
//
// T. Whitted, "An Improved Illumination Model for Shaded Display", Communications of the ACM 23(6), 1980.
#pragma once
#include "strahl/aabb.hpp"
#include "strahl/ray.hpp"
#include "strahl/rng.hpp"
#include <cstdint>

namespace strahl::ch01 {

// A primitive: sphere, plane or triangle (shapes.hpp), or anything a test derives.
class primitive {
public:
    explicit primitive(std::uint32_t material_id = 0) : material_(material_id) {}
    virtual ~primitive() = default;

    // The intersection test: the nearest hit with t in the open interval (r.tmin, r.tmax). On a hit, sets
    // h.t (and h.u, h.v for triangles; 0 otherwise) and returns true; on a miss leaves h alone.
    virtual bool intersect(const ray& r, hit& h) const = 0;
    // Unit geometric normal at the hit point p (as returned by intersect); which side it faces is the
    // shape's own convention: the tracer turns it towards the incoming ray.
    virtual vec3 normal(const vec3& p, const hit& h) const = 0;
    // Bounding box (planes are unbounded: an infinite box).
    virtual aabb bounds() const = 0;

    std::uint32_t material() const { return material_; }

private:
    std::uint32_t material_;
};

// One reflection ray a material asks for: its direction and the weight of the radiance it brings back.
struct scatter {
    vec3 dir{0.0f};
    color weight{0.0f};
};

class material {
public:
    virtual ~material() = default;

    // Direct light: the BRDF times the cosine, f(wo, wi) cos(theta_i), for light arriving from unit
    // direction wi at a point with unit normal n facing the viewer (wo: unit direction towards the viewer).
    // Radiance from a point light of intensity I at distance d is shade(...) * I / d^2.
    virtual color shade(const vec3& wo, const vec3& n, const vec3& wi) const = 0;

    // Reflection rays: how many the material spawns per hit (diffuse 0, mirror 1, rough mirror S) ...
    virtual int sample_count() const = 0;
    // ... and the i-th of them, for a ray arriving along unit direction d at unit normal n (facing the
    // viewer). The weights of all sample_count() samples add up to the reflectance.
    virtual scatter sample(const vec3& d, const vec3& n, int i, pcg32& rng) const = 0;
};

}  // namespace strahl::ch01
