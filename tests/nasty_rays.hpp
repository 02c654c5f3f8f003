// What every structure's adversarial rays share (chapters 03 on): random rays in and around the scene's box,
// rays along each axis with +0 and -0 in the other components, rays in, starting on and crossing a plane
// the structure splits at, and rays with NaN, Inf or zero components. Each structure's test adds the planes
// it has: a k-d tree's split planes (tests/03_kd_tree), a BVH's box faces (bvh_rays.hpp).
#pragma once
#include "strahl/aabb.hpp"
#include "strahl/ray.hpp"
#include "strahl/rng.hpp"
#include <limits>
#include <vector>

namespace strahl::test {

class nasty_ray_maker {
public:
    // bounds: the structure's box (an empty one stands for [-1, 1]^3); points are drawn from it grown by 10%.
    nasty_ray_maker(const aabb& bounds, std::uint64_t seed) : g_(seed) {
        const aabb b = bounds.is_empty() ? aabb{vec3(-1), vec3(1)} : bounds;
        lo_ = b.min - 0.1f * (b.extent() + 0.1f);
        hi_ = b.max + 0.1f * (b.extent() + 0.1f);
    }

    vec3 point() { return lo_ + vec3(g_.next_float(), g_.next_float(), g_.next_float()) * (hi_ - lo_); }
    vec3 dir() { return vec3(g_.next_float(), g_.next_float(), g_.next_float()) * 2.0f - 1.0f; }

    // n random rays, then n / 8 along each of the six axis directions with +0 and with -0 in the others.
    void add_random_and_axis(std::vector<ray>& rays, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) rays.push_back({point(), dir()});
        for (int a = 0; a < 3; ++a)
            for (const float s : {1.0f, -1.0f})
                for (const float z : {0.0f, -0.0f})
                    for (std::size_t i = 0; i < n / 8; ++i) {
                        vec3 d(z);
                        d[a] = s;
                        rays.push_back({point(), d});
                    }
    }

    // Three rays for the plane x[axis] = at: one lying in it (direction component +0 or -0), one starting
    // on it, and one through `through` (a point on it) with t from -1, so it crosses it both ways.
    void add_plane(std::vector<ray>& rays, int axis, float at, const vec3& through) {
        vec3 o = point();
        o[axis] = at;
        vec3 in_plane = dir();
        in_plane[axis] = g_.next_float() < 0.5f ? 0.0f : -0.0f;
        rays.push_back({o, in_plane});
        rays.push_back({o, dir()});
        rays.push_back({through, dir(), -1.0f, inf});
    }

    // NaN in the origin and in the direction, Inf in both, and the zero directions +0 and -0.
    void add_degenerate(std::vector<ray>& rays) {
        const float nan = std::numeric_limits<float>::quiet_NaN();
        rays.push_back({vec3(nan), vec3(0, 0, 1)});
        rays.push_back({point(), vec3(nan, 0, 1)});
        rays.push_back({point(), vec3(inf, 0, 1)});
        rays.push_back({vec3(inf, 0, 0), vec3(0, 0, 1)});
        rays.push_back({point(), vec3(0.0f)});
        rays.push_back({point(), vec3(-0.0f)});
    }

private:
    pcg32 g_;
    vec3 lo_, hi_;
};

}  // namespace strahl::test
