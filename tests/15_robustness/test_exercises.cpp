// Chapter 15's graded exercises: 15.1 the permutation and shear, 15.2 the watertight test's edge functions
// with the double fallback, 15.3 the spawn offset; each against a reference written out here or in double.
#include "strahl/ch01/shapes.hpp"
#include "strahl/ch15/spawn.hpp"
#include "strahl/ch15/watertight.hpp"
#include "strahl/procedural.hpp"
#include "strahl/rng.hpp"
#include "test_support.hpp"
#include <catch2/catch.hpp>
#include <bit>
#include <cstring>

using namespace strahl;
using namespace strahl::ch15;

namespace {

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof(float)) == 0; }

vec3 random_unit(pcg32& g) {
    for (;;) {
        const vec3 v(g.next_float() * 2 - 1, g.next_float() * 2 - 1, g.next_float() * 2 - 1);
        const float l = glm::length(v);
        if (l > 0.1f && l <= 1.0f) return v / l;
    }
}

// The sheared coordinates of p, relative to org, as watertight.hpp's step a defines them.
vec3 sheared(const shear& s, const vec3& p) {
    return vec3(p[s.kx] - s.sx * p[s.kz], p[s.ky] - s.sy * p[s.kz], s.sz * p[s.kz]);
}

}  // namespace

TEST_CASE("15.1 make_shear: the largest axis, the winding kept, the ray onto +z", "[ch15][pts:3]") {
    // The permutation: the largest |component| is kz; ties go to the lower axis.
    CHECK(make_shear(vec3(3, 1, 2)).kz == 0);
    CHECK(make_shear(vec3(1, -3, 2)).kz == 1);
    CHECK(make_shear(vec3(1, 2, -3)).kz == 2);
    CHECK(make_shear(vec3(2, 2, 1)).kz == 0);
    CHECK(make_shear(vec3(1, -2, 2)).kz == 1);
    // kx, ky follow kz cyclically, swapped for a negative dir[kz] (an odd permutation keeps the winding
    // only together with the flip of z).
    const shear up = make_shear(vec3(0.1f, 0.2f, 1.0f)), down = make_shear(vec3(0.1f, 0.2f, -1.0f));
    CHECK((up.kx == 0 && up.ky == 1));
    CHECK((down.kx == 1 && down.ky == 0));
    const shear y = make_shear(vec3(0.5f, 2.0f, 0.25f));
    CHECK((y.kx == 2 && y.ky == 0));
    // The shear maps the direction to (0, 0, 1), to rounding, for random directions.
    pcg32 g(15, 1);
    for (int i = 0; i < 1000; ++i) {
        const vec3 d = random_unit(g) * (0.01f + 100.0f * g.next_float());
        const shear s = make_shear(d);
        const vec3 m = sheared(s, d);
        INFO("dir " << d.x << " " << d.y << " " << d.z);
        CHECK(std::fabs(m.x) <= 1e-6f * glm::length(d));
        CHECK(std::fabs(m.y) <= 1e-6f * glm::length(d));
        CHECK(m.z == Approx(1.0f).epsilon(1e-6));
        CHECK(same_bits(s.sx, d[s.kx] / d[s.kz]));
        CHECK(same_bits(s.sy, d[s.ky] / d[s.kz]));
        CHECK(same_bits(s.sz, 1.0f / d[s.kz]));
    }
}

TEST_CASE("15.2 watertight test: hits, misses and barycentrics as Moeller-Trumbore's, to rounding",
          "[ch15][pts:2]") {
    // Away from edges both tests agree on hit or miss, and on t, u, v to a few ulps.
    pcg32 g(15, 2);
    int hits = 0;
    const int cases = 20000;
    for (int i = 0; i < cases; ++i) {
        const vec3 v0 = random_unit(g) * 2.0f, v1 = random_unit(g) * 2.0f, v2 = random_unit(g) * 2.0f;
        // Half the rays aimed at a random point of the triangle's plane near it, half at random.
        const vec3 org = random_unit(g) * 4.0f;
        const float b1 = g.next_float() * 1.4f - 0.2f, b2 = g.next_float() * 1.4f - 0.2f;
        const vec3 aim = (1.0f - b1 - b2) * v0 + b1 * v1 + b2 * v2;
        const ray r{org, i % 2 == 0 ? aim - org : random_unit(g), 0.0f, 10.0f};
        float t0, u0, w0, t1, u1, w1;
        const bool mt = ch01::intersect_triangle(r, v0, v1, v2, t0, u0, w0);
        const bool wt = intersect_watertight(r, make_shear(r.dir), v0, v1, v2, t1, u1, w1);
        if (mt) {
            const float margin = std::min({u0, w0, 1.0f - u0 - w0});
            if (margin < 1e-4f) continue;  // near an edge: the tests may differ, that is the point
        } else {
            float td, ud, vd;
            if (intersect_watertight_double(r, v0, v1, v2, td, ud, vd)) continue;  // a near miss
        }
        const vec3 normal = glm::cross(v1 - v0, v2 - v0);
        if (std::fabs(glm::dot(glm::normalize(normal), glm::normalize(r.dir))) < 0.05f) continue;  // grazing
        INFO("case " << i);
        REQUIRE(mt == wt);
        if (!mt) continue;
        ++hits;
        CHECK(t1 == Approx(t0).epsilon(1e-4));
        CHECK(u1 == Approx(u0).margin(1e-4));
        CHECK(w1 == Approx(w0).margin(1e-4));
    }
    CHECK(hits > cases / 10);
    // Two-sided, and the interval (tmin, tmax) is open.
    const vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    float t, u, v;
    const ray down{vec3(0.25f, 0.5f, 2), vec3(0, 0, -1), 0.0f, inf};
    REQUIRE(intersect_watertight(down, make_shear(down.dir), a, b, c, t, u, v));
    CHECK((t == 2.0f && u == 0.25f && v == 0.5f));
    const ray up{vec3(0.25f, 0.5f, -2), vec3(0, 0, 1), 0.0f, inf};
    CHECK(intersect_watertight(up, make_shear(up.dir), a, b, c, t, u, v));
    CHECK_FALSE(intersect_watertight(ray{down.org, down.dir, 0.0f, 2.0f}, make_shear(down.dir), a, b, c, t, u, v));
    CHECK_FALSE(intersect_watertight(ray{down.org, down.dir, 2.0f, 3.0f}, make_shear(down.dir), a, b, c, t, u, v));
    // A ray in the plane, a degenerate triangle, a NaN or zero direction: no hit, no NaN.
    const ray flat{vec3(-1, 0.25f, 0), vec3(1, 0, 0), 0.0f, inf};
    CHECK_FALSE(intersect_watertight(flat, make_shear(flat.dir), a, b, c, t, u, v));
    CHECK_FALSE(intersect_watertight(down, make_shear(down.dir), a, b, b, t, u, v));
    const ray nan_ray{down.org, vec3(std::nanf(""), 0, -1), 0.0f, inf};
    CHECK_FALSE(intersect_watertight(nan_ray, make_shear(nan_ray.dir), a, b, c, t, u, v));
    const ray zero{down.org, vec3(0), 0.0f, inf};
    CHECK_FALSE(intersect_watertight(zero, make_shear(zero.dir), a, b, c, t, u, v));
}

TEST_CASE("15.2 watertight test: rays aimed at shared edges and vertices never escape a closed mesh",
          "[ch15][pts:1]") {
    // From inside a closed sphere of 48 x 24 segments, rays aimed exactly at its vertices and at its
    // edges' midpoints: each must hit some triangle. Moeller-Trumbore lets some through; the watertight
    // test none: two triangles compute their shared edge's function from the same projected vertices.
    triangle_mesh m = tessellated_sphere(24, 48);
    std::vector<vec3> targets = m.positions;
    for (const uvec3& f : m.indices)
        for (int k = 0; k < 3; ++k) targets.push_back(0.5f * (m.positions[f[k]] + m.positions[f[(k + 1) % 3]]));
    std::size_t escapes = 0, mt_escapes = 0;
    const vec3 inside(0.1f, -0.05f, 0.02f);
    for (const vec3& p : targets) {
        const ray r{inside, p - inside, 0.0f, inf};
        const shear s = make_shear(r.dir);
        bool hit = false, mt_hit = false;
        for (const uvec3& f : m.indices) {
            float t, u, v;
            hit = hit || intersect_watertight(r, s, m.positions[f.x], m.positions[f.y], m.positions[f.z], t, u, v);
            mt_hit = mt_hit || ch01::intersect_triangle(r, m.positions[f.x], m.positions[f.y], m.positions[f.z], t, u, v);
        }
        escapes += !hit;
        mt_escapes += !mt_hit;
    }
    INFO(targets.size() << " rays; Moeller-Trumbore lets " << mt_escapes << " through");
    CHECK(mt_escapes > 0);  // the case is hard enough to show a crack
    CHECK(escapes == 0);
}

TEST_CASE("15.2 watertight test: the double fallback decides edge functions that round to 0", "[ch15][pts:1]") {
    // The ray runs up the z axis (no shear); the edge from B to C passes just beside it. In float, the
    // edge function Cx By - Cy Bx = -(1 + 2^-11) + (1 + 2^-12)^2 rounds to 0 (the square's last bit is a
    // tie, rounded to even); exactly, it is 2^-24 > 0, while the other two are negative: a miss. Without
    // the fallback, the 0 counts as "on the edge" and the triangle is hit, together with its neighbour
    // across that edge: the wrong triangle can win.
    const ray r{vec3(0), vec3(0, 0, 1), 0.0f, inf};
    const vec3 a(1, -1, 1), b(1 + 0x1p-12f, 1, 1), c(-1 - 0x1p-11f, -1 - 0x1p-12f, 1), d(-1, 1, 1);
    REQUIRE(float(b.x) * float(b.x) == 1 + 0x1p-11f);  // the rounding the case relies on
    float t, u, v;
    CHECK_FALSE(intersect_watertight(r, make_shear(r.dir), a, b, c, t, u, v));
    CHECK_FALSE(intersect_watertight_double(r, a, b, c, t, u, v));
    // The neighbour across B-C is hit, in float as in double.
    CHECK(intersect_watertight(r, make_shear(r.dir), d, c, b, t, u, v));
    CHECK(intersect_watertight_double(r, d, c, b, t, u, v));
    CHECK(t == 1.0f);
}

TEST_CASE("15.2 watertight test: no hit on a triangle whose edges are parallel in float (pbrt-v4's case)",
          "[ch15][pts:1]") {
    // pbrt-v4's shapes_test.cpp, Triangle.BadCases: three collinear corners (equal x and z) and a ray that
    // once reported a hit on it (tmax 0.9999). Sheared and rounded, the corners span a tiny area, the three
    // edge functions agree in sign and det is not 0: only step c's check of (v1 - v0) x (v2 - v0) == 0
    // refuses the hit.
    const vec3 v0(-1113.45459f, -79.049614f, -56.2431908f), v1(-1113.45459f, -87.0922699f, -56.2431908f),
        v2(-1113.45459f, -79.2090149f, -56.2431908f);
    REQUIRE(glm::cross(v1 - v0, v2 - v0) == vec3(0.0f));  // parallel in float
    const ray r{vec3(-1081.47925f, 99.9999542f, 87.7701111f), vec3(-32.1072998f, -183.355865f, -144.607635f), 0.0f,
                0.9999f};
    float t = -1.0f, u = -1.0f, v = -1.0f;
    CHECK_FALSE(intersect_watertight(r, make_shear(r.dir), v0, v1, v2, t, u, v));
    CHECK_FALSE(intersect_watertight(r, make_shear(r.dir), v1, v2, v0, t, u, v));  // every corner first
    CHECK_FALSE(intersect_watertight(r, make_shear(r.dir), v2, v0, v1, t, u, v));
    CHECK_FALSE(intersect_watertight(r, make_shear(r.dir), v0, v2, v1, t, u, v));  // and the other winding
    // A triangle beside it that is not degenerate is still hit: the check refuses parallel edges only.
    const vec3 w2 = v2 + vec3(0.0f, 0.0f, 1.0f);
    const ray through{(v0 + v1 + w2) / 3.0f + vec3(10.0f, 0.0f, 0.0f), vec3(-1.0f, 0.0f, 0.0f), 0.0f, inf};
    CHECK(intersect_watertight(through, make_shear(through.dir), v0, v1, w2, t, u, v));
}

TEST_CASE("15.3 offset_integer: moved by ulps along the normal, to the side the ray leaves to", "[ch15][pts:3]") {
    const vec3 n(0, 0, 1);
    // Near the origin, a float offset of 2^-16 n.
    const vec3 small = offset_integer(vec3(0.01f, -0.02f, 0.0f), n, n);
    CHECK(same_bits(small.z, 0x1p-16f));
    CHECK((small.x == 0.01f && small.y == -0.02f));
    // Elsewhere, 256 ulps along n; away from zero for p > 0 and n > 0, toward zero for p < 0 and n > 0.
    const vec3 p(3.0f, -5.0f, 1000.0f);
    const vec3 w(0.6f, 0.0f, 0.8f);
    const vec3 nn = glm::normalize(vec3(1, 1, 1));
    const vec3 o = offset_integer(p, nn, w);
    const std::int32_t ulps = std::int32_t(256.0f * nn.x);  // 147
    CHECK(std::bit_cast<std::uint32_t>(o.x) == std::bit_cast<std::uint32_t>(p.x) + std::uint32_t(ulps));
    CHECK(std::bit_cast<std::uint32_t>(o.y) == std::bit_cast<std::uint32_t>(p.y) - std::uint32_t(ulps));
    CHECK(o.y > p.y);  // moved toward zero, which is +n's side for a negative coordinate
    CHECK(std::bit_cast<std::uint32_t>(o.z) == std::bit_cast<std::uint32_t>(p.z) + std::uint32_t(ulps));
    // The side: a direction below the surface flips n.
    const vec3 below = offset_integer(p, nn, -w);
    CHECK(below.x < p.x);
    CHECK(below.y < p.y);
    CHECK(below.z < p.z);
    // The offset grows with |p|: the moved point stays on the right side at every scale.
    for (const float scale : {1e-3f, 1.0f, 1e3f, 1e6f, 1e9f}) {
        const vec3 q = vec3(0.3f, 0.4f, 0.5f) * scale;
        const vec3 out = offset_integer(q, n, n);
        INFO("scale " << scale);
        CHECK(out.z > q.z);
        CHECK((out.x == q.x && out.y == q.y));
    }
}
