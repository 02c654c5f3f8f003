// A ray and the record of its closest hit, as every acceleration structure in the course exchanges them.
#pragma once
#include "strahl/math.hpp"
#include <cstring>
#include <span>

namespace strahl {

// Points org + t * dir for t in [tmin, tmax]. dir need not be normalised; t is in units of |dir|.
struct ray {
    vec3 org{0.0f};
    vec3 dir{0.0f, 0.0f, 1.0f};
    float tmin = 0.0f;
    float tmax = inf;

    vec3 at(float t) const { return org + t * dir; }
};

inline constexpr std::uint32_t invalid_id = 0xFFFFFFFFu;

// The closest hit found so far. A miss is t == +inf and prim == invalid_id.
// (u, v) are the barycentric coordinates of the hit within triangle prim: p = (1-u-v) v0 + u v1 + v v2.
struct hit {
    float t = inf;
    std::uint32_t prim = invalid_id;
    float u = 0.0f;
    float v = 0.0f;
    std::uint32_t inst = invalid_id;  // instance id, for two-level structures (chapter 10)

    bool found() const { return prim != invalid_id; }
};

// The course's closest-hit rule: the nearer t wins, and at equal t the lower primitive id wins. Every
// structure, whatever order it visits triangles in, thereby reports exactly the hit brute force reports.
inline bool closer(float t, std::uint32_t prim, const hit& best) {
    return t < best.t || (t == best.t && prim < best.prim);
}

// How many of two equally long hit lists differ in primitive or in t's bits (the programs' exactness check).
inline std::size_t hits_differing(std::span<const hit> a, std::span<const hit> b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
        n += a[i].prim != b[i].prim || std::memcmp(&a[i].t, &b[i].t, sizeof(float)) != 0;
    return n;
}

}  // namespace strahl
