// Warping uniform samples u in [0,1)^2 to the shapes a tracer samples from, and a local frame to use them.
// See Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed., 2023, section A.5.
#pragma once
#include "strahl/math.hpp"

namespace strahl {

// Concentric map of the square to the unit disk (Shirley and Chiu, 1997): area-preserving, low distortion.
inline vec2 sample_disk(vec2 u) {
    const vec2 o = 2.0f * u - vec2(1.0f);
    if (o.x == 0.0f && o.y == 0.0f) return vec2(0.0f);
    float r, theta;
    if (std::abs(o.x) > std::abs(o.y)) { r = o.x; theta = (pi / 4.0f) * (o.y / o.x); }
    else { r = o.y; theta = pi / 2.0f - (pi / 4.0f) * (o.x / o.y); }
    return r * vec2(std::cos(theta), std::sin(theta));
}

// Uniform direction on the unit sphere; pdf 1 / (4 pi).
inline vec3 sample_sphere(vec2 u) {
    const float z = 1.0f - 2.0f * u.x;
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * pi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Cosine-weighted direction on the hemisphere around +z (Malley's method); pdf cos(theta) / pi.
inline vec3 sample_cosine_hemisphere(vec2 u) {
    const vec2 d = sample_disk(u);
    return {d.x, d.y, std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y))};
}

// An orthonormal frame (t, b, n) around the unit vector n (Duff et al., "Building an Orthonormal Basis,
// Revisited", 2017): to_world maps a local direction (x, y, z) to x t + y b + z n.
struct frame {
    vec3 t, b, n;
    explicit frame(const vec3& normal) : n(normal) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float c = n.x * n.y * a;
        t = vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
        b = vec3(c, sign + n.y * n.y * a, -n.y);
    }
    vec3 to_world(const vec3& v) const { return v.x * t + v.y * b + v.z * n; }
    vec3 to_local(const vec3& v) const { return {glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)}; }
};

}  // namespace strahl
