// Chapter 01 materials: diffuse (Lambert), mirror, and rough mirror: a glossy reflection estimated with
// S reflection rays per hit, the stochastic sampling of R. L. Cook, T. Porter and L. Carpenter,
// "Distributed Ray Tracing", SIGGRAPH 1984.
#pragma once
#include "strahl/ch01/primitive.hpp"

namespace strahl::ch01 {

// Lambertian: f = albedo / pi; lit by point lights, spawns no reflection rays (Whitted's model).
class diffuse final : public material {
public:
    explicit diffuse(const color& albedo) : albedo_(albedo) {}
    color shade(const vec3& wo, const vec3& n, const vec3& wi) const override;
    int sample_count() const override { return 0; }
    scatter sample(const vec3& d, const vec3& n, int i, pcg32& rng) const override;

private:
    color albedo_;
};

// Perfect mirror: nothing from point lights (a delta BRDF never points at them), one reflection ray.
class mirror final : public material {
public:
    explicit mirror(const color& reflectance) : reflectance_(reflectance) {}
    color shade(const vec3& wo, const vec3& n, const vec3& wi) const override;
    int sample_count() const override { return 1; }
    scatter sample(const vec3& d, const vec3& n, int i, pcg32& rng) const override;

private:
    color reflectance_;
};

// Rough mirror: S reflection rays around the mirror direction, each the mirror direction plus a random
// offset of length up to `roughness` (uniform in a ball), weight reflectance / S. Samples that would leave
// below the surface are mirrored back above it. roughness 0 is the perfect mirror, S times over.
class rough_mirror final : public material {
public:
    rough_mirror(const color& reflectance, float roughness, int samples = 16);
    color shade(const vec3& wo, const vec3& n, const vec3& wi) const override;
    int sample_count() const override { return samples_; }
    scatter sample(const vec3& d, const vec3& n, int i, pcg32& rng) const override;

private:
    color reflectance_;
    float roughness_;
    int samples_;
};

}  // namespace strahl::ch01
