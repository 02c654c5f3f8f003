// Exercise 15.4 the escape experiment's rays: the counts and the order the experiment's tables rely on,
// every aimed ray exactly at its vertex or edge midpoint, the random control rays as the seed makes them,
// and the point of it all: Moeller-Trumbore (chapter 01's test, not an exercise of this chapter) lets aimed
// rays out of a closed sphere where the random ones find no crack.
#include "strahl/ch15/experiments.hpp"
#include "strahl/ch15/robust_bvh.hpp"
#include "exactness.hpp"
#include "test_support.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <utility>

namespace escape_rays_test {

using namespace strahl;
using namespace strahl::ch15;

bool same_bits(const vec3& a, const vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The ray's origin, direction (bit for bit) and interval against an origin and a target.
bool aimed_at(const ray& r, const vec3& o, const vec3& target) {
    return same_bits(r.org, o) && same_bits(r.dir, target - o) && r.tmin == 0.0f && r.tmax == inf;
}

TEST_CASE("15.4 aimed rays: the vertices, then three sides per triangle, then as many random: counts and bounds",
          "[ch15][pts:1]") {
    for (const auto& [stacks, slices] : {std::pair{12, 24}, std::pair{5, 7}, std::pair{2, 3}}) {
        const placement p{1.0f, 0.0f};
        const triangle_mesh m = placed_sphere(stacks, slices, p);
        const aimed_rays r = make_aimed_rays(m, p, 1);
        INFO(stacks << " x " << slices << " sphere, " << m.positions.size() << " vertices, " << m.triangle_count()
                    << " triangles");
        CHECK(r.bounds[0] == 0);
        CHECK(r.count(aim_kind::vertex) == m.positions.size());
        CHECK(r.count(aim_kind::edge) == 3 * m.triangle_count());
        CHECK(r.count(aim_kind::random) == r.count(aim_kind::vertex) + r.count(aim_kind::edge));
        CHECK(r.rays.size() == r.bounds[3]);
        CHECK(r.rays.size() == aimed_ray_count(stacks, slices));
    }
}

TEST_CASE("15.4 aimed rays: from inside, exactly at each vertex and each side's midpoint, in order, unnormalised",
          "[ch15][pts:1]") {
    // A sphere of radius 1e3 at 1e5 from the origin: a normalised direction, or a midpoint computed another
    // way, differs here in its last bits.
    const placement p{1e3f, 1e5f};
    const triangle_mesh m = placed_sphere(12, 24, p);
    const aimed_rays r = make_aimed_rays(m, p, 1);
    REQUIRE(r.rays.size() == aimed_ray_count(12, 24));
    const vec3 o = p.inside();
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < m.positions.size(); ++i)
        if (!aimed_at(r.rays[r.bounds[0] + i], o, m.positions[i]) && ++wrong <= 3)
            FAIL_CHECK("vertex ray " << i << " is not aimed at vertex " << i);
    for (std::size_t f = 0; f < m.indices.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const vec3 a = m.positions[m.indices[f][k]], b = m.positions[m.indices[f][(k + 1) % 3]];
            if (!aimed_at(r.rays[r.bounds[1] + 3 * f + std::size_t(k)], o, 0.5f * (a + b)) && ++wrong <= 3)
                FAIL_CHECK("edge ray " << 3 * f + std::size_t(k) << " is not aimed at side " << k << " of triangle " << f);
        }
    CHECK(wrong == 0);
}

TEST_CASE("15.4 aimed rays: the random rays are random_point's, as seeded, on the ideal sphere", "[ch15][pts:1]") {
    const placement p{1.0f, 0.0f};
    const triangle_mesh m = placed_sphere(12, 24, p);
    const aimed_rays a = make_aimed_rays(m, p, 7), b = make_aimed_rays(m, p, 8);
    REQUIRE(a.rays.size() == aimed_ray_count(12, 24));
    REQUIRE(b.rays.size() == a.rays.size());
    pcg32 g(7, 15);
    std::size_t wrong = 0, same_as_other_seed = 0;
    for (std::size_t i = a.bounds[2]; i < a.bounds[3]; ++i) {
        const ray& r = a.rays[i];
        if (!aimed_at(r, p.inside(), random_point(g, p)) && ++wrong <= 3) FAIL_CHECK("random ray " << i);
        CHECK(std::abs(glm::length(r.org + r.dir - p.centre()) - p.scale) < 1e-5f);
        same_as_other_seed += same_bits(r.dir, b.rays[i].dir);
    }
    CHECK(wrong == 0);
    CHECK(same_as_other_seed == 0);  // another seed, other points
}

TEST_CASE("15.4 aimed rays: Moeller-Trumbore lets aimed rays out of a closed sphere, random ones find no crack",
          "[ch15][pts:1]") {
    // Chapter 01's test by brute force (every triangle per ray) on a closed 12 x 24 sphere of radius 1 at
    // the origin: rays aimed at vertices and edges find the cracks between neighbours, as many random rays
    // none.
    const placement p{1.0f, 0.0f};
    const triangle_mesh m = placed_sphere(12, 24, p);
    const aimed_rays r = make_aimed_rays(m, p, 1);
    REQUIRE(r.rays.size() == aimed_ray_count(12, 24));
    brute_tests<test_kind::mt> brute;
    brute.build(test::mesh_only(m));
    const std::array<std::size_t, 3> e = escapes(r, found(brute, r.rays, nullptr));
    INFO("escapes: " << e[0] << " vertex, " << e[1] << " edge, " << e[2] << " random rays");
    CHECK(e[int(aim_kind::vertex)] > 0);
    CHECK(e[int(aim_kind::edge)] > 0);
    CHECK(e[int(aim_kind::random)] == 0);
}

}  // namespace escape_rays_test
