#include "strahl/race/brute_force.hpp"
#include "strahl/ch01/shapes.hpp"

namespace strahl::race {

void brute_force::build(const scene& s) {
    triangles_.resize(s.mesh.triangle_count());
    for (std::size_t i = 0; i < triangles_.size(); ++i) triangles_[i] = s.mesh.triangle(i);
}

template <class Stats>
void brute_force::closest(std::span<const ray> rays, std::span<hit> hits, Stats& stats) const {
    for (std::size_t i = 0; i < rays.size(); ++i) {
        ray r = rays[i];
        hit best;
        stats.ray();
        for (std::size_t k = 0; k < triangles_.size(); ++k) {
            stats.prim_test();
            float t, u, v;
            const auto& tri = triangles_[k];
            // Triangles come in id order and tmax shrinks to each hit, so a later triangle at the same t is
            // rejected: the lower id wins ties, as closer() demands.
            if (ch01::intersect_triangle(r, tri[0], tri[1], tri[2], t, u, v)) {
                best = hit{t, std::uint32_t(k), u, v, invalid_id};
                r.tmax = t;
            }
        }
        hits[i] = best;
    }
}

template <class Stats>
void brute_force::any(std::span<const ray> rays, std::span<std::uint8_t> blocked, Stats& stats) const {
    for (std::size_t i = 0; i < rays.size(); ++i) {
        stats.ray();
        std::uint8_t found = 0;
        for (std::size_t k = 0; k < triangles_.size() && !found; ++k) {
            stats.prim_test();
            float t, u, v;
            const auto& tri = triangles_[k];
            found = ch01::intersect_triangle(rays[i], tri[0], tri[1], tri[2], t, u, v) ? 1 : 0;
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
