// Chapter 16's tests share this: brute force's answers to a scene's primary, diffuse and shadow rays,
// traced in parallel (brute force is O(rays x triangles); the test binary must stay fast).
#pragma once
#include "strahl/parallel.hpp"
#include "strahl/race/brute_force.hpp"
#include "strahl/race/ray_sets.hpp"
#include <map>
#include <string>
#include <vector>

namespace strahl::test {

// trace_closest / trace_any cut a batch into chunks of whole tile rows where it is large (ch01::thread_chunk):
// these cut every batch into chunks of 64 rays instead, each traced as one batch, so that the exactness tests
// also see packets regrouped at arbitrary cuts.
inline void closest_in_parallel(const accel& a, std::span<const ray> rays, std::span<hit> hits) {
    parallel_for_chunks(rays.size(), 64, [&](std::size_t b, std::size_t e) {
        race::trace_closest(a, rays.subspan(b, e - b), hits.subspan(b, e - b), 1);
    });
}
inline void any_in_parallel(const accel& a, std::span<const ray> rays, std::span<std::uint8_t> blocked) {
    parallel_for_chunks(rays.size(), 64, [&](std::size_t b, std::size_t e) {
        race::trace_any(a, rays.subspan(b, e - b), blocked.subspan(b, e - b), 1);
    });
}

// One ray set with brute force's answers to it.
struct reference_set {
    race::ray_kind kind;
    std::vector<ray> rays;
    std::vector<hit> closest;
    std::vector<std::uint8_t> any;
};

inline std::size_t found(const std::vector<hit>& hits) {
    std::size_t n = 0;
    for (const hit& h : hits) n += h.found();
    return n;
}

// Primary rays of a width x height image, then the diffuse (seed 1) and shadow rays of their hits, each
// with brute force's closest and any hits.
inline std::vector<reference_set> reference_sets(const scene& s, int width, int height) {
    race::brute_force brute;
    brute.build(s);
    std::vector<reference_set> sets(3);
    sets[0].kind = race::ray_kind::primary;
    sets[0].rays = race::primary_rays(s, width, height);
    sets[1].kind = race::ray_kind::diffuse;
    sets[2].kind = race::ray_kind::shadow;
    for (reference_set& r : sets) {
        if (r.kind != race::ray_kind::primary) r.rays = race::secondary_rays(r.kind, s, sets[0].rays, sets[0].closest, 1);
        r.closest.resize(r.rays.size());
        r.any.resize(r.rays.size());
        closest_in_parallel(brute, r.rays, r.closest);
        any_in_parallel(brute, r.rays, r.any);
    }
    return sets;
}

// reference_sets, computed once per scene name and image size for the whole test binary (the exactness
// and the Embree tests trace the same scenes): brute force on the bunny is the binary's biggest cost.
inline const std::vector<reference_set>& shared_reference_sets(const scene& s, int width, int height) {
    static std::map<std::string, std::vector<reference_set>> cache;
    const std::string key = s.name + " " + std::to_string(s.mesh.triangle_count()) + " " + std::to_string(width) +
                            "x" + std::to_string(height);
    auto it = cache.find(key);
    if (it == cache.end()) it = cache.emplace(key, reference_sets(s, width, height)).first;
    return it->second;
}

}  // namespace strahl::test
