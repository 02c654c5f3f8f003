// Exercise 15.4 the escape experiment's rays (4 points). Read: experiments.hpp (aimed_rays, placement);
// README.md, "The experiment" and section 1; S. Woop, C. Benthin and I. Wald, "Watertight ray/triangle
// intersection", JCGT 2(1), 2013 (the cracks this experiment looks for).
#include "strahl/ch15/experiments.hpp"

namespace strahl::ch15 {

aimed_rays make_aimed_rays(const triangle_mesh& m, const placement& p, std::uint64_t seed) {
    aimed_rays out;
    const vec3 o = p.inside();
    out.rays.reserve(2 * (m.positions.size() + 3 * m.triangle_count()));
    // Every vertex: where several triangles meet, the likeliest place for all of them to say "outside".
    for (const vec3& v : m.positions) out.rays.push_back(ray{o, v - o, 0.0f, inf});
    out.bounds[1] = out.rays.size();
    // Every side of every triangle at its midpoint: each shared edge twice, once from each of its triangles
    // (the same ray: a + b == b + a in float).
    for (const uvec3& f : m.indices)
        for (int k = 0; k < 3; ++k) {
            const vec3 mid = 0.5f * (m.positions[f[k]] + m.positions[f[(k + 1) % 3]]);
            out.rays.push_back(ray{o, mid - o, 0.0f, inf});
        }
    out.bounds[2] = out.rays.size();
    // As many at random points of the ideal sphere: the control, rays that meet a triangle's interior.
    pcg32 g(seed, 15);
    for (std::size_t i = 0, n = out.bounds[2]; i < n; ++i) out.rays.push_back(ray{o, random_point(g, p) - o, 0.0f, inf});
    out.bounds[3] = out.rays.size();
    return out;
}

}  // namespace strahl::ch15
