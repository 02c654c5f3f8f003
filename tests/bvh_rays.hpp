// Rays made to break a BVH (chapters 04 on): random ones, ones along each axis with +0 and -0 in the other
// components, ones starting on and lying in the faces of the first levels' boxes, and NaN, Inf and zero
// directions.
#pragma once
#include "strahl/ch04/bvh.hpp"
#include "strahl/rng.hpp"
#include "strahl/ray.hpp"
#include <limits>
#include <vector>

namespace strahl::test {

inline std::vector<ray> nasty_rays(const ch04::bvh& t, std::size_t n, std::uint64_t seed) {
    pcg32 g(seed);
    const aabb b = t.bounds.is_empty() ? aabb{vec3(-1), vec3(1)} : t.bounds;
    const vec3 lo = b.min - 0.1f * (b.extent() + 0.1f), hi = b.max + 0.1f * (b.extent() + 0.1f);
    const auto point = [&] { return lo + vec3(g.next_float(), g.next_float(), g.next_float()) * (hi - lo); };
    const auto dir = [&] { return vec3(g.next_float(), g.next_float(), g.next_float()) * 2.0f - 1.0f; };
    std::vector<ray> rays;
    for (std::size_t i = 0; i < n; ++i) rays.push_back({point(), dir()});
    for (int a = 0; a < 3; ++a)
        for (const float s : {1.0f, -1.0f})
            for (const float z : {0.0f, -0.0f})
                for (std::size_t i = 0; i < n / 8; ++i) {
                    vec3 d(z);
                    d[a] = s;
                    rays.push_back({point(), d});
                }
    for (const ch04::level_box& lb : ch04::level_boxes(t, 0, 5)) {
        for (int a = 0; a < 3; ++a)
            for (const float face : {lb.box.min[a], lb.box.max[a]}) {
                vec3 o = point();
                o[a] = face;
                vec3 in_face = dir();
                in_face[a] = g.next_float() < 0.5f ? 0.0f : -0.0f;
                rays.push_back({o, in_face});                                       // in the face's plane
                rays.push_back({o, dir()});                                         // starting on it
                rays.push_back({lb.box.centroid(), dir(), -1.0f, inf});             // from the middle, both ways
            }
    }
    const float nan = std::numeric_limits<float>::quiet_NaN();
    rays.push_back({vec3(nan), vec3(0, 0, 1)});
    rays.push_back({point(), vec3(nan, 0, 1)});
    rays.push_back({point(), vec3(inf, 0, 1)});
    rays.push_back({vec3(inf, 0, 0), vec3(0, 0, 1)});
    rays.push_back({point(), vec3(0.0f)});
    rays.push_back({point(), vec3(-0.0f)});
    return rays;
}

}  // namespace strahl::test
