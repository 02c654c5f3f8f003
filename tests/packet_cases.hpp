// The cases every packet tracer must answer exactly as brute force does (chapters 12 and 14): tiles of an
// image's ray sets, rays made to break a packet, degenerate scenes and a scene far from the origin.
#pragma once
#include "bvh_rays.hpp"
#include "exactness.hpp"
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch05/accel.hpp"
#include "strahl/ch05/sah.hpp"
#include "strahl/ch05/slab_test.hpp"
#include "strahl/ch12/packet.hpp"
#include "strahl/procedural.hpp"
#include <limits>
#include <vector>

namespace strahl::test {

// What chapter 05's fast_slab::entry computes for lane i of p: its entry distance, or +inf for a miss.
template <int K, int V>
inline float scalar_entry(const ch12::ray_packet<K, V>& p, int i, const aabb& b) {
    float t0 = p.t0[i], t1 = p.t1[i];
    for (int a = 0; a < 3; ++a) {
        const bool down = std::signbit(p.dir[a][i]);
        const float near = ch05::plane_t<ch05::fused_plane_default>(down ? b.max[a] : b.min[a], p.inv[a][i], p.org_near[a][i]);
        const float far = ch05::plane_t<ch05::fused_plane_default>(down ? b.min[a] : b.max[a], p.inv[a][i], p.org_far[a][i]);
        t0 = near > t0 ? near : t0;
        t1 = far < t1 ? far : t1;
    }
    return t0 <= t1 ? t0 : inf;
}

// Chapter 05's fast binned SAH tree over a mesh (for nasty_rays' boxes).
inline ch04::bvh binned_tree(const triangle_mesh& m) {
    std::vector<aabb> boxes(m.triangle_count());
    std::vector<vec3> centroids(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const auto t = m.triangle(i);
        boxes[i] = aabb().grow(t[0]).grow(t[1]).grow(t[2]), centroids[i] = boxes[i].centroid();
    }
    return ch05::build_sah_bvh_fast(boxes, centroids);
}

// An image's primary rays, or the diffuse or shadow rays from their hits (one per hit, in pixel order).
inline std::vector<ray> image_rays(const scene& s, int w, int h, ch01::ray_kind kind, std::uint64_t seed = 7) {
    const auto exact = ch05::make_accel(false, {}, ch05::walk_kind::fast);  // exact, as every course structure
    exact->build(s);
    return ch01::make_rays(kind, s, w, h, seed, *exact);
}

// A scene, rays, and the row widths to cut its packets from (0: packets of consecutive rays; a width: tiles of
// rows of that many rays, unrelated rays side by side).
struct packet_case {
    const char* what;
    scene s;
    std::vector<ray> rays;
    std::vector<int> widths;
};

inline std::vector<packet_case> packet_cases() {
    std::vector<packet_case> out;
    // Rays made to break it: nasty rays, denormal and tiny direction components, an empty and a reversed
    // interval, a negative tmin.
    {
        scene s = teapot_scene(3);
        std::vector<ray> rays = nasty_rays(binned_tree(s.mesh), 200, 31);
        for (const float tiny : {1e-40f, -1e-42f, 1e-30f, 1e-20f})
            rays.push_back({vec3(0.1f, 0.2f, -3.0f), vec3(tiny, 0.05f, 1.0f)});
        rays.push_back({vec3(0.0f, 0.3f, -3.0f), vec3(0, 0, 1), 2.0f, 2.0f});
        rays.push_back({vec3(0.0f, 0.3f, -3.0f), vec3(0, 0, 1), 3.0f, 1.0f});
        rays.push_back({vec3(0.0f, 0.3f, 0.0f), vec3(0, 0, 1), -5.0f, inf});
        out.push_back({"rays made to break it", std::move(s), std::move(rays), {0, 16}});
    }
    // Ties, one triangle, an empty scene, a flat soup.
    const auto rays_for = [](const triangle_mesh& m) { return nasty_rays(binned_tree(m), 120, 5); };
    const triangle_mesh ties = copies(300, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0));
    out.push_back({"300 equal triangles", mesh_only(ties), rays_for(ties), {0}});
    const triangle_mesh one = copies(1, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0));
    out.push_back({"one triangle", mesh_only(one), rays_for(one), {8}});
    out.push_back({"an empty scene", mesh_only(triangle_mesh{}), rays_for(one), {0}});
    triangle_mesh flat = random_soup(500, 5, 0.1f);
    for (vec3& p : flat.positions) p.z = 0.5f;
    out.push_back({"a flat soup", mesh_only(flat), rays_for(flat), {0}});
    // Triangles with a NaN or an infinite corner: left out of the trees (loose), so every ray is traced alone
    // and tests them.
    {
        triangle_mesh m = random_soup(300, 5, 0.1f);
        m.positions[m.indices[7][1]].x = std::numeric_limits<float>::quiet_NaN();
        m.positions[m.indices[40][0]].y = inf;
        m.positions[m.indices[41][2]].z = -inf;
        out.push_back({"a soup with non-finite triangles", mesh_only(m), rays_for(m), {0}});
    }
    // A scene far from the origin, and origins 1e9 away aimed at it (moved to the scene by ray_frame).
    {
        scene s = teapot_scene(3);
        for (vec3& p : s.mesh.positions) p += vec3(3e4f, -1e5f, 2e4f);
        std::vector<ray> rays = nasty_rays(binned_tree(s.mesh), 150, 9);
        const vec3 c = s.mesh.bounds().centroid();
        for (int i = 0; i < 40; ++i) {
            const vec3 o = c + vec3(1e9f, 3e8f * float(i % 5), -2e8f);
            rays.push_back({o, c + vec3(0.01f * float(i), 0.0f, 0.0f) - o});
        }
        out.push_back({"a far scene and far origins", std::move(s), std::move(rays), {0}});
    }
    return out;
}

}  // namespace strahl::test
