// What the tests of every structure share (chapters 03 on): small scenes made to break a structure, and
// the check that a built structure answers exactly as brute force over chapter 01's triangle_set does:
// closest hit bit for bit, any hit, and the counted queries the same as the uncounted ones.
#pragma once
#include "strahl/accel.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include <catch2/catch.hpp>
#include <cstring>
#include <vector>

namespace strahl::test {

inline scene mesh_only(triangle_mesh m) {
    scene s;
    s.name = "test";
    s.mesh = std::move(m);
    return s;
}

// n copies of the triangle (a, b, c): every tie at once (the lowest id must win).
inline triangle_mesh copies(std::size_t n, vec3 a, vec3 b, vec3 c) {
    triangle_mesh m;
    m.positions = {a, b, c};
    for (std::size_t i = 0; i < n; ++i) m.indices.push_back(uvec3(0, 1, 2));
    return m;
}

inline bool bit_equal(const hit& a, const hit& b) {
    return a.prim == b.prim && std::memcmp(&a.t, &b.t, 4) == 0 && std::memcmp(&a.u, &b.u, 4) == 0 &&
           std::memcmp(&a.v, &b.v, 4) == 0;
}

// Traces rays through the built structure a (plain and counted, closest and any hit) and compares every
// answer with brute force over mesh; checks the counted run counts every ray. Returns the rays that differ
// (the first three are reported).
inline std::size_t disagreements_with_brute_force(const accel& a, const triangle_mesh& mesh,
                                                  const std::vector<ray>& rays) {
    const ch01::triangle_set tris(mesh);
    const ray_frame frame(mesh.bounds());  // brute force moves far origins to the scene as the structures do
    std::vector<hit> got(rays.size()), got_counted(rays.size());
    std::vector<std::uint8_t> blocked(rays.size()), blocked_counted(rays.size());
    a.intersect(rays, got);
    a.occluded(rays, blocked);
    const auto counts = a.intersect_counted(rays, got_counted);
    a.occluded_counted(rays, blocked_counted);
    REQUIRE(counts);
    CHECK(counts->rays == rays.size());
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const hit ref = frame.closest(rays[i], [&](ray r) {
            hit best;
            for (std::uint32_t k = 0; k < tris.size(); ++k) tris.intersect(k, r, best);
            return best;
        });
        const bool any = frame.any(rays[i], [&](const ray& r) {
            for (std::uint32_t k = 0; k < tris.size(); ++k)
                if (tris.occludes(k, r)) return true;
            return false;
        });
        const bool ok = bit_equal(got[i], ref) && bit_equal(got_counted[i], ref) && (blocked[i] != 0) == any &&
                        blocked_counted[i] == blocked[i];
        if (!ok && ++wrong <= 3)
            FAIL_CHECK("ray " << i << ": t " << got[i].t << " prim " << got[i].prim << ", brute force t " << ref.t
                              << " prim " << ref.prim);
    }
    return wrong;
}

}  // namespace strahl::test
