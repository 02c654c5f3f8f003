// Chapter 01 primitives: sphere, plane, triangle. The intersection tests themselves are free functions
// (exercises 01.2 and 01.3), so that later chapters reuse exactly the same triangle test as brute force.
//
// T. Moeller and B. Trumbore, "Fast, Minimum Storage Ray/Triangle Intersection", Journal of Graphics
// Tools 2(1), 1997.
// E. Haines, J. Guenther and T. Akenine-Moeller, "Precision Improvements for Ray/Sphere Intersection",
// Ray Tracing Gems, chapter 7, 2019.
#pragma once
#include "strahl/ch01/primitive.hpp"

namespace strahl::ch01 {

// Exercise 01.2 (exercises/01_first_tracer/sphere.cpp): ray/sphere. The nearest root t of
// |org + t dir - center| = radius with tmin < t < tmax; from inside, that is the far root. Robust quadratic.
bool intersect_sphere(const ray& r, const vec3& center, float radius, float& t);

// Exercise 01.3 (exercises/01_first_tracer/triangle.cpp): ray/triangle after Moeller and Trumbore.
// Two-sided; a hit needs tmin < t < tmax and barycentrics u >= 0, v >= 0, u + v <= 1 (edges count);
// the hit point is (1-u-v) v0 + u v1 + v v2. Degenerate triangles, parallel and NaN rays: no hit.
bool intersect_triangle(const ray& r, const vec3& v0, const vec3& v1, const vec3& v2, float& t, float& u,
                        float& v);

// Ray/plane for the plane of points p with dot(normal, p) == offset: t = (offset - dot(normal, org)) /
// dot(normal, dir), accepted in (tmin, tmax); no hit for a ray parallel to the plane or holding a NaN.
bool intersect_plane(const ray& r, const vec3& normal, float offset, float& t);

class sphere final : public primitive {
public:
    sphere(const vec3& center, float radius, std::uint32_t material_id = 0);
    bool intersect(const ray& r, hit& h) const override;
    vec3 normal(const vec3& p, const hit& h) const override;
    aabb bounds() const override;

private:
    vec3 center_;
    float radius_;
};

// The plane of points p with dot(normal, p) == offset.
class plane final : public primitive {
public:
    plane(const vec3& normal, float offset, std::uint32_t material_id = 0);
    bool intersect(const ray& r, hit& h) const override;
    vec3 normal(const vec3& p, const hit& h) const override;
    aabb bounds() const override;

private:
    vec3 normal_;
    float offset_;
};

// One triangle, storing its own three vertices (an object per triangle: the object-oriented way).
class triangle final : public primitive {
public:
    triangle(const vec3& v0, const vec3& v1, const vec3& v2, std::uint32_t material_id = 0);
    bool intersect(const ray& r, hit& h) const override;
    vec3 normal(const vec3& p, const hit& h) const override;
    aabb bounds() const override;

private:
    vec3 v0_, v1_, v2_, normal_;
};

}  // namespace strahl::ch01
