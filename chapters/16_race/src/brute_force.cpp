#include "strahl/race/brute_force.hpp"

namespace strahl::race {

void brute_force::build(const scene& s) { triangles_ = std::make_unique<ch01::triangle_set>(s.mesh); }

template <class Stats>
void brute_force::closest(std::span<const ray> rays, std::span<hit> hits, Stats& stats) const {
    const auto n = std::uint32_t(triangles_->size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
        ray r = rays[i];
        hit best;
        stats.ray();
        // Every triangle in id order; each hit shrinks r.tmax (record_closest), and at equal t the lower id
        // stays: the rule of closer() that every other structure must reproduce.
        for (std::uint32_t k = 0; k < n; ++k) {
            stats.prim_test();
            triangles_->intersect(k, r, best);
        }
        hits[i] = best;
    }
}

template <class Stats>
void brute_force::any(std::span<const ray> rays, std::span<std::uint8_t> blocked, Stats& stats) const {
    const auto n = std::uint32_t(triangles_->size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
        stats.ray();
        std::uint8_t found = 0;
        for (std::uint32_t k = 0; k < n && !found; ++k) {
            stats.prim_test();
            found = triangles_->occludes(k, rays[i]) ? 1 : 0;
        }
        blocked[i] = found;
    }
}

void brute_force::intersect(std::span<const ray> rays, std::span<hit> hits) const {
    not_counting stats;
    closest(rays, hits, stats);
}

void brute_force::occluded(std::span<const ray> rays, std::span<std::uint8_t> blocked) const {
    not_counting stats;
    any(rays, blocked, stats);
}

std::optional<counter_values> brute_force::intersect_counted(std::span<const ray> rays, std::span<hit> hits) const {
    counting stats;
    closest(rays, hits, stats);
    return stats.values();
}

std::optional<counter_values> brute_force::occluded_counted(std::span<const ray> rays,
                                                            std::span<std::uint8_t> blocked) const {
    counting stats;
    any(rays, blocked, stats);
    return stats.values();
}

}  // namespace strahl::race
