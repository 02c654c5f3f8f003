// Chapter 01's primitives as later chapters see them. From chapter 02 on, every structure is generic over
// the primitive: its builder sees only boxes and centroids, its traversal calls the set's leaf test. Two
// sets run side by side in the programs and the race, so the cost of late binding is visible from the start:
//   triangle_set: plain triangles, vertices in one array, the leaf test a direct call;
//   object_set:   chapter 01's objects, one heap allocation and one virtual intersect() per triangle.
// Both use exercise 01.3's triangle test, so both give brute force's answers bit for bit.
#pragma once
#include "strahl/ch01/shapes.hpp"
#include "strahl/scene.hpp"
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace strahl::ch01 {

// The closest-hit step every structure takes at a leaf, for a hit (t, u, v) of primitive id found with
// the query ray r: keep it if closer() says so, then shrink r.tmax to just above t. Ties at exactly t can
// then still be tested, and the lower id wins them: the same hit brute force keeps when visiting in id order.
inline bool record_closest(std::uint32_t id, float t, float u, float v, ray& r, hit& best) {
    if (!closer(t, id, best)) return false;
    best = hit{t, id, u, v, invalid_id};
    r.tmax = std::nextafter(t, inf);
    return true;
}

class triangle_set {
public:
    static constexpr const char* kind = "triangles";

    explicit triangle_set(const triangle_mesh& mesh) : tris_(mesh.triangle_count()) {
        for (std::size_t i = 0; i < tris_.size(); ++i) tris_[i] = mesh.triangle(i);
    }
    std::size_t size() const { return tris_.size(); }
    aabb bounds(std::size_t i) const {
        aabb b;
        return b.grow(tris_[i][0]).grow(tris_[i][1]).grow(tris_[i][2]);
    }
    vec3 centroid(std::size_t i) const { return bounds(i).centroid(); }

    // Closest hit: tests triangle i against r; see record_closest.
    bool intersect(std::uint32_t i, ray& r, hit& best) const {
        float t, u, v;
        return intersect_triangle(r, tris_[i][0], tris_[i][1], tris_[i][2], t, u, v) &&
               record_closest(i, t, u, v, r, best);
    }
    // Any hit: whether triangle i blocks r anywhere in (tmin, tmax).
    bool occludes(std::uint32_t i, const ray& r) const {
        float t, u, v;
        return intersect_triangle(r, tris_[i][0], tris_[i][1], tris_[i][2], t, u, v);
    }
    std::size_t memory_bytes() const { return tris_.size() * sizeof(tris_[0]); }

private:
    std::vector<std::array<vec3, 3>> tris_;
};

class object_set {
public:
    static constexpr const char* kind = "virtual";

    explicit object_set(const triangle_mesh& mesh) {
        objects_.reserve(mesh.triangle_count());
        for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
            const auto v = mesh.triangle(i);
            objects_.push_back(std::make_unique<triangle>(v[0], v[1], v[2]));
        }
    }
    std::size_t size() const { return objects_.size(); }
    aabb bounds(std::size_t i) const { return objects_[i]->bounds(); }
    vec3 centroid(std::size_t i) const { return bounds(i).centroid(); }

    bool intersect(std::uint32_t i, ray& r, hit& best) const {
        hit h;
        return objects_[i]->intersect(r, h) && record_closest(i, h.t, h.u, h.v, r, best);
    }
    bool occludes(std::uint32_t i, const ray& r) const {
        hit h;
        return objects_[i]->intersect(r, h);
    }
    // The objects (vtable pointer, material id, vertices and normal) and the owning pointers.
    std::size_t memory_bytes() const { return objects_.size() * (sizeof(triangle) + sizeof(void*)); }

private:
    std::vector<std::unique_ptr<primitive>> objects_;
};

}  // namespace strahl::ch01
