// Chapter 01 materials: Lambert, mirror, rough mirror (Cook, Porter and Carpenter, "Distributed Ray
// Tracing", 1984: glossy reflection as an average over S reflection rays).
#include "strahl/ch01/materials.hpp"
#include "strahl/sampling.hpp"
#include <stdexcept>

namespace strahl::ch01 {

color diffuse::shade(const vec3&, const vec3& n, const vec3& wi) const {
    return albedo_ * (std::max(0.0f, glm::dot(n, wi)) / pi);
}

scatter diffuse::sample(const vec3&, const vec3&, int, pcg32&) const { return {}; }

color mirror::shade(const vec3&, const vec3&, const vec3&) const { return color(0.0f); }

scatter mirror::sample(const vec3& d, const vec3& n, int, pcg32&) const { return {reflect(d, n), reflectance_}; }

rough_mirror::rough_mirror(const color& reflectance, float roughness, int samples)
    : reflectance_(reflectance), roughness_(roughness), samples_(samples) {
    if (samples < 1) throw std::invalid_argument("rough mirror: needs at least one reflection sample per hit");
    if (!(roughness >= 0.0f)) throw std::invalid_argument("rough mirror: roughness must be >= 0");
}

color rough_mirror::shade(const vec3&, const vec3&, const vec3&) const { return color(0.0f); }

scatter rough_mirror::sample(const vec3& d, const vec3& n, int, pcg32& rng) const {
    const vec3 m = reflect(d, n);
    const color w = reflectance_ / float(samples_);
    if (roughness_ == 0.0f) return {m, w};
    // The mirror direction plus a uniform point in the ball of radius `roughness`.
    const float u0 = rng.next_float(), u1 = rng.next_float(), u2 = rng.next_float();
    const vec3 offset = sample_sphere(vec2(u0, u1)) * (roughness_ * std::cbrt(u2));
    vec3 dir = glm::normalize(m + offset);
    if (glm::dot(dir, n) < 0.0f) dir = reflect(dir, n);  // below the surface: mirror it back above
    return {dir, w};
}

}  // namespace strahl::ch01
