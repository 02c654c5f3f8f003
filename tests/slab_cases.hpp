// Rays made to graze boxes edge-on, and a slab test in long double to hold a fast one to (chapter 05's
// slab tests, and chapter 13's per-ray set-up of them): shared by tests/05_sah and tests/13_wide_bvh.
#pragma once
#include "strahl/ch04/bvh.hpp"
#include "strahl/rng.hpp"
#include <cmath>
#include <optional>
#include <vector>

namespace strahl::test {

inline ch04::bvh_node node_of(const aabb& b) {
    ch04::bvh_node n{};
    for (int a = 0; a < 3; ++a) n.bmin[a] = b.min[a], n.bmax[a] = b.max[a];
    return n;
}

// The slab test in long double (64-bit significand): the plane differences of two floats are exact there, so
// its only rounding is the division, 2^-64 relative: far below what the float tests are allowed.
inline std::optional<long double> exact_entry(const aabb& b, const ray& r, long double t0, long double t1) {
    for (int a = 0; a < 3; ++a) {
        const long double o = r.org[a], d = r.dir[a];
        if (d == 0.0L) {
            if (o < b.min[a] || o > b.max[a]) return std::nullopt;
            continue;
        }
        long double near = (static_cast<long double>(b.min[a]) - o) / d;
        long double far = (static_cast<long double>(b.max[a]) - o) / d;
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
    }
    if (t0 > t1) return std::nullopt;
    return t0;
}

struct grazing_case {
    aabb box;
    ray r;
};

// Rays aimed at a box's edges and corners (two or three coordinates on its planes), and at points just
// inside and outside them, from all sides; the box is `size` wide and sits at `offset` from the origin.
inline std::vector<grazing_case> grazing_cases(float offset, float size, std::uint64_t seed, int n) {
    pcg32 g(seed);
    std::vector<grazing_case> cases;
    for (int i = 0; i < n; ++i) {
        const vec3 c = vec3(offset) * vec3(1.0f, -0.7f, 0.4f);
        const vec3 half = size * (0.1f + vec3(g.next_float(), g.next_float(), g.next_float()));
        const aabb box{c - half, c + half};
        vec3 q;
        for (int a = 0; a < 3; ++a) q[a] = box.min[a] + g.next_float() * (box.max[a] - box.min[a]);
        const int fixed = 2 + int(g.next_u32() % 2);  // an edge or a corner
        for (int k = 0; k < fixed; ++k) {
            const int a = (int(i) + k) % 3;
            q[a] = g.next_float() < 0.5f ? box.min[a] : box.max[a];
            const int nudge = int(g.next_u32() % 5) - 2;  // just outside, on, or just inside
            for (int s = 0; s < std::abs(nudge); ++s) q[a] = std::nextafter(q[a], nudge > 0 ? inf : -inf);
        }
        const vec3 away = vec3(g.next_float(), g.next_float(), g.next_float()) * 2.0f - 1.0f;
        const vec3 org = q + away * size * (1.0f + 8.0f * g.next_float());
        cases.push_back({box, ray{org, q - org}});
    }
    return cases;
}

// Of the boxes the exact test meets: how many `entry` misses, and how many it enters later than exactly.
// entry returns +inf for a miss and nothing where it does not apply (the fast test on a ray it refuses).
struct tally {
    int tested = 0, missed = 0, late = 0;
};
template <class Entry>
tally check_against_exact(const std::vector<grazing_case>& cases, Entry&& entry) {
    tally n;
    for (const grazing_case& k : cases) {
        const float lo = -1e30f, hi = 1e30f;
        const std::optional<long double> exact = exact_entry(k.box, k.r, lo, hi);
        const std::optional<float> t = entry(node_of(k.box), k.r, lo, hi);
        if (!exact || !t) continue;
        ++n.tested;
        if (*t == inf) ++n.missed;
        else if (static_cast<long double>(*t) > *exact + std::fabs(*exact) * 0x1p-60L) ++n.late;
    }
    return n;
}

}  // namespace strahl::test
