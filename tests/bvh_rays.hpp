// Rays made to break a BVH (chapters 04 on): nasty_rays.hpp's random, axis-aligned and degenerate rays,
// and rays lying in, starting on and crossing the faces of the boxes of the tree's first six levels.
#pragma once
#include "nasty_rays.hpp"
#include "strahl/ch04/bvh.hpp"
#include <vector>

namespace strahl::test {

inline std::vector<ray> nasty_rays(const ch04::bvh& t, std::size_t n, std::uint64_t seed) {
    nasty_ray_maker m(t.bounds, seed);
    std::vector<ray> rays;
    m.add_random_and_axis(rays, n);
    for (const ch04::level_box& lb : ch04::level_boxes(t, 0, 5))
        for (int a = 0; a < 3; ++a)
            for (const float face : {lb.box.min[a], lb.box.max[a]}) {
                vec3 on_face = lb.box.centroid();
                on_face[a] = face;
                m.add_plane(rays, a, face, on_face);
            }
    m.add_degenerate(rays);
    return rays;
}

}  // namespace strahl::test
