// Chapter 01 primitives as classes. Each intersect() is one virtual call; spheres and triangles hand the
// geometry to the free functions of exercises 01.2 and 01.3, planes are solved here.
#include "strahl/ch01/shapes.hpp"

namespace strahl::ch01 {

// --- sphere ----------------------------------------------------------------------------------------------

sphere::sphere(const vec3& center, float radius, std::uint32_t material_id)
    : primitive(material_id), center_(center), radius_(radius) {}

bool sphere::intersect(const ray& r, hit& h) const {
    float t;
    if (!intersect_sphere(r, center_, radius_, t)) return false;
    h.t = t;
    h.u = h.v = 0.0f;
    return true;
}

vec3 sphere::normal(const vec3& p, const hit&) const { return (p - center_) / radius_; }

aabb sphere::bounds() const { return {center_ - vec3(radius_), center_ + vec3(radius_)}; }

// --- plane -----------------------------------------------------------------------------------------------

plane::plane(const vec3& normal, float offset, std::uint32_t material_id)
    : primitive(material_id), normal_(glm::normalize(normal)), offset_(offset) {}

// dot(n, org + t dir) = offset  =>  t = (offset - dot(n, org)) / dot(n, dir); no hit when the ray runs
// parallel to the plane (or holds a NaN: every comparison with NaN is false).
bool intersect_plane(const ray& r, const vec3& normal, float offset, float& t) {
    const float denom = glm::dot(normal, r.dir);
    if (!(denom != 0.0f)) return false;
    const float tp = (offset - glm::dot(normal, r.org)) / denom;
    if (!(tp > r.tmin && tp < r.tmax)) return false;
    t = tp;
    return true;
}

bool plane::intersect(const ray& r, hit& h) const {
    float t;
    if (!intersect_plane(r, normal_, offset_, t)) return false;
    h.t = t;
    h.u = h.v = 0.0f;
    return true;
}

vec3 plane::normal(const vec3&, const hit&) const { return normal_; }

aabb plane::bounds() const { return {vec3(-inf), vec3(inf)}; }

// --- triangle --------------------------------------------------------------------------------------------

triangle::triangle(const vec3& v0, const vec3& v1, const vec3& v2, std::uint32_t material_id)
    : primitive(material_id), v0_(v0), v1_(v1), v2_(v2) {
    const vec3 c = glm::cross(v1 - v0, v2 - v0);
    const float len = glm::length(c);
    normal_ = len > 0.0f ? c / len : vec3(0.0f, 0.0f, 1.0f);  // degenerate: never hit, any normal will do
}

bool triangle::intersect(const ray& r, hit& h) const {
    float t, u, v;
    if (!intersect_triangle(r, v0_, v1_, v2_, t, u, v)) return false;
    h.t = t;
    h.u = u;
    h.v = v;
    return true;
}

vec3 triangle::normal(const vec3&, const hit&) const { return normal_; }

aabb triangle::bounds() const {
    aabb b;
    return b.grow(v0_).grow(v1_).grow(v2_);
}

}  // namespace strahl::ch01
