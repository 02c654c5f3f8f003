#include "strahl/race/brute_force.hpp"

namespace strahl::race {

void brute_force::build(const scene& s) {
    triangles_ = std::make_unique<ch01::triangle_set>(s.mesh);
    set_frame(ray_frame(s.mesh.bounds()));  // far origins moved to the scene, as every structure does
}

template <class Stats>
hit brute_force::closest(const ray& query, Stats& stats) const {
    const auto n = std::uint32_t(triangles_->size());
    ray r = query;
    hit best;
    stats.ray();
    // Every triangle in id order; each hit shrinks r.tmax (record_closest), and at equal t the lower id
    // stays: the rule of closer() that every other structure must reproduce.
    for (std::uint32_t k = 0; k < n; ++k) {
        stats.prim_test();
        triangles_->intersect(k, r, best);
    }
    return best;
}

template <class Stats>
bool brute_force::any(const ray& query, Stats& stats) const {
    const auto n = std::uint32_t(triangles_->size());
    stats.ray();
    for (std::uint32_t k = 0; k < n; ++k)
        if (stats.prim_test(), triangles_->occludes(k, query)) return true;
    return false;
}

// The two instantiations per_ray_accel calls.
template hit brute_force::closest(const ray&, not_counting&) const;
template hit brute_force::closest(const ray&, counting&) const;
template bool brute_force::any(const ray&, not_counting&) const;
template bool brute_force::any(const ray&, counting&) const;

}  // namespace strahl::race
