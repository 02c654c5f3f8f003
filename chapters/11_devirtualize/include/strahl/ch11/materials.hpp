// Chapter 11's shading steps: chapter 01's three materials (Lambert, mirror, rough mirror) without
// `virtual`. The arithmetic is chapter 01's (materials.cpp), line for line, so a render is the same image
// bit for bit whichever way the material is reached:
//   variant:  std::variant of three value types, std::visit per call (a jump on the index, inlined bodies);
//   switch:   one record per material with a kind id, a switch per call (what a C programmer writes).
// (Chapter 01's virtual classes are the baseline: ch01::material.)
//   R. L. Cook, T. Porter and L. Carpenter, "Distributed Ray Tracing", SIGGRAPH 1984 (the rough mirror).
#pragma once
#include "strahl/ch01/primitive.hpp"
#include "strahl/sampling.hpp"
#include "strahl/scene.hpp"
#include <cmath>
#include <variant>
#include <vector>

namespace strahl::ch11 {

// ---- The three materials as values, with chapter 01's formulas ----

struct lambert {
    color albedo;
    color shade(const vec3&, const vec3& n, const vec3& wi) const {
        return albedo * (std::max(0.0f, glm::dot(n, wi)) / pi);
    }
    int sample_count() const { return 0; }
    ch01::scatter sample(const vec3&, const vec3&, int, pcg32&) const { return {}; }
};

struct perfect_mirror {
    color reflectance;
    color shade(const vec3&, const vec3&, const vec3&) const { return color(0.0f); }
    int sample_count() const { return 1; }
    ch01::scatter sample(const vec3& d, const vec3& n, int, pcg32&) const { return {reflect(d, n), reflectance}; }
};

struct glossy_mirror {
    color reflectance;
    float roughness;
    int samples;
    color shade(const vec3&, const vec3&, const vec3&) const { return color(0.0f); }
    int sample_count() const { return samples; }
    ch01::scatter sample(const vec3& d, const vec3& n, int, pcg32& rng) const {
        const vec3 m = reflect(d, n);
        const color w = reflectance / float(samples);
        if (roughness == 0.0f) return {m, w};
        const float u0 = rng.next_float(), u1 = rng.next_float(), u2 = rng.next_float();
        const vec3 offset = sample_sphere(vec2(u0, u1)) * (roughness * std::cbrt(u2));
        vec3 dir = glm::normalize(m + offset);
        if (glm::dot(dir, n) < 0.0f) dir = reflect(dir, n);
        return {dir, w};
    }
};

// ---- Variant: a closed set, dispatched by std::visit ----

using material_variant = std::variant<lambert, perfect_mirror, glossy_mirror>;

struct variant_materials {
    std::vector<material_variant> m;

    color shade(std::uint32_t id, const vec3& wo, const vec3& n, const vec3& wi) const {
        return std::visit([&](const auto& x) { return x.shade(wo, n, wi); }, m[id]);
    }
    int sample_count(std::uint32_t id) const {
        return std::visit([](const auto& x) { return x.sample_count(); }, m[id]);
    }
    ch01::scatter sample(std::uint32_t id, const vec3& d, const vec3& n, int i, pcg32& rng) const {
        return std::visit([&](const auto& x) { return x.sample(d, n, i, rng); }, m[id]);
    }
};

// ---- Switch: a kind id and a switch ----

struct material_record {
    material_kind kind = material_kind::diffuse;
    color albedo{0.8f};
    float roughness = 0.0f;
    int samples = 1;
};

struct switch_materials {
    std::vector<material_record> m;

    color shade(std::uint32_t id, const vec3& wo, const vec3& n, const vec3& wi) const {
        const material_record& r = m[id];
        switch (r.kind) {
        case material_kind::diffuse: return lambert{r.albedo}.shade(wo, n, wi);
        default: return color(0.0f);  // mirrors take nothing from point lights
        }
    }
    int sample_count(std::uint32_t id) const {
        const material_record& r = m[id];
        switch (r.kind) {
        case material_kind::diffuse: return 0;
        case material_kind::mirror: return 1;
        default: return r.samples;
        }
    }
    ch01::scatter sample(std::uint32_t id, const vec3& d, const vec3& n, int i, pcg32& rng) const {
        const material_record& r = m[id];
        switch (r.kind) {
        case material_kind::diffuse: return {};
        case material_kind::mirror: return perfect_mirror{r.albedo}.sample(d, n, i, rng);
        default: return glossy_mirror{r.albedo, r.roughness, r.samples}.sample(d, n, i, rng);
        }
    }
};

// ---- Virtual: chapter 01's classes, one virtual call per use (the baseline) ----

struct virtual_materials {
    std::vector<std::unique_ptr<ch01::material>> m;

    color shade(std::uint32_t id, const vec3& wo, const vec3& n, const vec3& wi) const { return m[id]->shade(wo, n, wi); }
    int sample_count(std::uint32_t id) const { return m[id]->sample_count(); }
    ch01::scatter sample(std::uint32_t id, const vec3& d, const vec3& n, int i, pcg32& rng) const {
        return m[id]->sample(d, n, i, rng);
    }
};

// The scene's materials in each form (rough mirrors with glossy_samples reflection rays per hit; a scene
// without materials gets chapter 01's default grey Lambert). Throws std::invalid_argument as chapter 01's
// rough_mirror does for glossy_samples < 1 or a negative roughness.
variant_materials make_variant_materials(const scene& s, int glossy_samples);
switch_materials make_switch_materials(const scene& s, int glossy_samples);
virtual_materials make_virtual_materials(const scene& s, int glossy_samples);

}  // namespace strahl::ch11
