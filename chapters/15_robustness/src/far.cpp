// The far-away experiment (far.hpp).
#include "strahl/ch15/far.hpp"
#include "strahl/camera.hpp"
#include "strahl/ch15/robust_bvh.hpp"
#include "strahl/parallel.hpp"
#include "strahl/procedural.hpp"
#include "strahl/ray_frame.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <vector>

namespace strahl::ch15 {

namespace {

template <test_kind K>
void far_rows(const scene& s, const std::vector<ray>& rays, float distance, std::ostringstream& csv) {
    robust_bvh<K, box_kind::fast> tree;
    brute_tests<K> brute;
    tree.build(s), brute.build(s);
    const ray_frame scene_frame = tree.frame();  // the one build() set
    for (const bool moved : {false, true}) {
        const ray_frame f = moved ? scene_frame : ray_frame();
        tree.set_frame(f), brute.set_frame(f);
        std::vector<hit> a(rays.size()), b(rays.size());
        constexpr std::size_t chunk = 256;
        parallel_for_chunks((rays.size() + chunk - 1) / chunk, 1, [&](std::size_t c0, std::size_t c1) {
            for (std::size_t c = c0; c < c1; ++c) {
                const std::size_t first = c * chunk, n = std::min(chunk, rays.size() - first);
                const std::span<const ray> r(rays.data() + first, n);
                tree.intersect(r, std::span<hit>(a.data() + first, n));
                brute.intersect(r, std::span<hit>(b.data() + first, n));
            }
        });
        std::size_t hits = 0, differing = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            hits += b[i].found();
            differing += a[i].prim != b[i].prim || std::memcmp(&a[i].t, &b[i].t, 4) != 0 ||
                         std::memcmp(&a[i].u, &b[i].u, 4) != 0 || std::memcmp(&a[i].v, &b[i].v, 4) != 0;
        }
        const char* origins = moved ? "moved" : "kept";
        csv << distance << ',' << name(K) << ',' << origins << ',' << rays.size() << ',' << hits << ',' << differing << '\n';
        std::printf("  %-10g %-12s %-8s %9zu %9zu %10zu\n", double(distance), name(K), origins, rays.size(), hits, differing);
    }
}

}  // namespace

std::string run_far(bool quick) {
    const int w = quick ? 32 : 320, h = quick ? 24 : 240;
    std::printf("\n2b. from far away: the teapot seen from 1e3 to 1e7, %d x %d primary rays, the fast walk against "
                "brute force with the same test, origins kept or moved to the scene\n", w, h);
    std::printf("  %-10s %-12s %-8s %9s %9s %10s\n", "distance", "test", "origins", "rays", "hits", "differing");
    std::ostringstream csv;
    csv << "distance,test,origins,rays,hits,unlike_brute_force\n";  // not "differing": kept origins may differ
    scene s = builtin_scene("teapot");
    const vec3 target(0.2f, 1.4f, 0.0f);
    for (const float distance : {1e3f, 1e4f, 1e5f, 1e6f, 1e7f}) {
        const camera cam(camera_desc{target + glm::normalize(vec3(0.3f, 0.4f, 1.0f)) * distance, target, vec3(0, 1, 0),
                                     2.0f * glm::degrees(std::atan(3.5f / distance))}, w, h);
        std::vector<ray> rays;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) rays.push_back(cam.pixel_ray(x, y));
        far_rows<test_kind::mt>(s, rays, distance, csv);
        far_rows<test_kind::watertight>(s, rays, distance, csv);
    }
    return csv.str();
}

}  // namespace strahl::ch15
