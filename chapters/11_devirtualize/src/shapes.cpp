// The closed set's plumbing: the scene's primitives and materials as values, in chapter 01's order.
#include "strahl/ch11/materials.hpp"
#include "strahl/ch11/shapes.hpp"
#include "strahl/ch01/materials.hpp"
#include <stdexcept>
#include <string>

namespace strahl::ch11 {

triangle_shape make_triangle(const vec3& v0, const vec3& v1, const vec3& v2) {
    // Chapter 01's triangle constructor's normal, with its fallback for a degenerate triangle.
    const vec3 c = glm::cross(v1 - v0, v2 - v0);
    const float len = glm::length(c);
    return {v0, v1, v2, len > 0.0f ? c / len : vec3(0.0f, 0.0f, 1.0f)};
}

std::vector<shape> make_shapes(const scene& s, bool with_shapes) {
    std::vector<shape> out;
    out.reserve(s.mesh.triangle_count() + (with_shapes ? s.spheres.size() + s.planes.size() : 0));
    for (std::size_t i = 0; i < s.mesh.triangle_count(); ++i) {
        const auto v = s.mesh.triangle(i);
        out.emplace_back(make_triangle(v[0], v[1], v[2]));
    }
    if (!with_shapes) return out;
    for (const sphere_desc& sp : s.spheres) {
        if (!(sp.radius > 0.0f) || !is_finite(sp.center))
            throw std::invalid_argument("scene '" + s.name + "': a sphere needs a finite centre and radius > 0");
        out.emplace_back(sphere_shape{sp.center, sp.radius});
    }
    for (const plane_desc& pl : s.planes) {
        if (!is_finite(pl.normal) || glm::length(pl.normal) == 0.0f || !std::isfinite(pl.offset))
            throw std::invalid_argument("scene '" + s.name + "': a plane needs a finite, non-zero normal");
        out.emplace_back(plane_shape{glm::normalize(pl.normal), pl.offset});
    }
    return out;
}

std::vector<std::uint32_t> make_material_ids(const scene& s, bool with_shapes) {
    std::vector<std::uint32_t> ids;
    const std::size_t n_materials = std::max<std::size_t>(1, s.materials.size());
    const auto add = [&](std::uint32_t m) {
        if (m >= n_materials)
            throw std::invalid_argument("scene '" + s.name + "': a primitive names material " + std::to_string(m) +
                                        " but the scene has " + std::to_string(n_materials));
        ids.push_back(m);
    };
    for (std::size_t i = 0; i < s.mesh.triangle_count(); ++i) add(s.triangle_material(i));
    if (with_shapes) {
        for (const sphere_desc& sp : s.spheres) add(sp.material);
        for (const plane_desc& pl : s.planes) add(pl.material);
    }
    return ids;
}

aabb bounds(const shape& s) {
    struct visitor {
        aabb operator()(const triangle_shape& t) const { return aabb().grow(t.v0).grow(t.v1).grow(t.v2); }
        aabb operator()(const sphere_shape& sp) const { return {sp.center - vec3(sp.radius), sp.center + vec3(sp.radius)}; }
        aabb operator()(const plane_shape&) const { return {vec3(-inf), vec3(inf)}; }
    };
    return std::visit(visitor{}, s);
}

vec3 normal_at(const shape& s, const vec3& p) {
    struct visitor {
        const vec3& p;
        vec3 operator()(const triangle_shape& t) const { return t.normal; }
        vec3 operator()(const sphere_shape& sp) const { return (p - sp.center) / sp.radius; }
        vec3 operator()(const plane_shape& pl) const { return pl.normal; }
    };
    return std::visit(visitor{p}, s);
}

// ---- Materials ----

namespace {
void check(const material_desc& m, int glossy_samples) {
    if (m.kind != material_kind::rough_mirror) return;
    if (glossy_samples < 1) throw std::invalid_argument("rough mirror: needs at least one reflection sample per hit");
    if (!(m.roughness >= 0.0f)) throw std::invalid_argument("rough mirror: roughness must be >= 0");
}
// Chapter 01's world adds a grey Lambert when a scene names no material.
std::vector<material_desc> descs(const scene& s) {
    return s.materials.empty() ? std::vector<material_desc>{material_desc{"default", material_kind::diffuse, color(0.8f)}}
                               : s.materials;
}
}  // namespace

variant_materials make_variant_materials(const scene& s, int glossy_samples) {
    variant_materials out;
    for (const material_desc& m : descs(s)) {
        check(m, glossy_samples);
        switch (m.kind) {
        case material_kind::diffuse: out.m.emplace_back(lambert{m.albedo}); break;
        case material_kind::mirror: out.m.emplace_back(perfect_mirror{m.albedo}); break;
        case material_kind::rough_mirror: out.m.emplace_back(glossy_mirror{m.albedo, m.roughness, glossy_samples}); break;
        }
    }
    return out;
}

switch_materials make_switch_materials(const scene& s, int glossy_samples) {
    switch_materials out;
    for (const material_desc& m : descs(s)) {
        check(m, glossy_samples);
        out.m.push_back({m.kind, m.albedo, m.roughness, glossy_samples});
    }
    return out;
}

virtual_materials make_virtual_materials(const scene& s, int glossy_samples) {
    virtual_materials out;
    for (const material_desc& m : descs(s)) {
        switch (m.kind) {
        case material_kind::diffuse: out.m.push_back(std::make_unique<ch01::diffuse>(m.albedo)); break;
        case material_kind::mirror: out.m.push_back(std::make_unique<ch01::mirror>(m.albedo)); break;
        case material_kind::rough_mirror:
            out.m.push_back(std::make_unique<ch01::rough_mirror>(m.albedo, m.roughness, glossy_samples));
            break;
        }
    }
    return out;
}

}  // namespace strahl::ch11
