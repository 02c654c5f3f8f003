// Chapter 05's two slab tests (slab_test.hpp, 0 points): conservative against a slab test in long double on
// rays made to graze boxes edge-on, near and far from the origin; the fast test refused where its products
// could overflow; and without its widening, boxes are lost (so the first check can fail).
#include "strahl/ch05/slab_test.hpp"
#include "strahl/rng.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

using namespace strahl;
using namespace strahl::ch05;

namespace {

ch04::bvh_node node_of(const aabb& b) {
    ch04::bvh_node n{};
    for (int a = 0; a < 3; ++a) n.bmin[a] = b.min[a], n.bmax[a] = b.max[a];
    return n;
}

// The slab test in long double (64-bit significand): the plane differences of two floats are exact there, so
// its only rounding is the division, 2^-64 relative: far below what the float tests are allowed.
std::optional<long double> exact_entry(const aabb& b, const ray& r, long double t0, long double t1) {
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
std::vector<grazing_case> grazing_cases(float offset, float size, std::uint64_t seed, int n) {
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

// The fast test with a given widening, its planes' t fused (one rounding) or not (two); nothing for a ray it
// refuses. Both forms are checked whatever the build compiles the traversal with (fused_plane_default).
template <bool Fused>
auto fast_test(double widen) {
    return [widen](const ch04::bvh_node& n, const ray& r, float lo, float hi) -> std::optional<float> {
        const std::optional<fast_slab> s = fast_slab::make(r, n.box(), widen);
        if (!s) return std::nullopt;
        return s->template entry<Fused>(n, lo, hi);
    };
}

}  // namespace

TEST_CASE("ch05 slab tests: no box met exactly is missed, near and far from the origin", "[ch05]") {
    int lost_without_widening = 0, lost_fused_without_widening = 0;
    for (const float offset : {0.0f, 1.0f, 1e3f, 1e5f, 1e7f})
        for (const float size : {1e-3f, 1.0f, 1e3f}) {
            const auto cases = grazing_cases(offset, size, 17, 4000);
            INFO("box of size " << size << " at " << offset << " from the origin");
            // The fast test, in both forms: no box missed, none entered late (its entry orders and prunes the
            // walk).
            const tally fast = check_against_exact(cases, fast_test<false>(fast_slab_widen));
            const tally fused = check_against_exact(cases, fast_test<true>(fast_slab_widen));
            // Most of the 4000 rays meet their box, except where the box is a few floats wide (its rays then
            // have zero direction components, which the fast test refuses).
            if (size >= offset * 0x1p-16f) CHECK(fast.tested > 1000);
            CHECK(fast.missed == 0);
            CHECK(fast.late == 0);
            CHECK(fused.tested == fast.tested);
            CHECK(fused.missed == 0);
            CHECK(fused.late == 0);
            // The robust test widens the exit only: no box missed (its entry may round late, by far less
            // than the ray's slack, which the walk's pruning allows for).
            const tally robust = check_against_exact(cases, [](const ch04::bvh_node& n, const ray& r, float lo, float hi) {
                return std::optional<float>(robust_slab(r).entry(n, lo, hi));
            });
            CHECK(robust.tested >= fast.tested);
            CHECK(robust.missed == 0);
            const tally bare = check_against_exact(cases, fast_test<false>(0.0));
            lost_without_widening += bare.missed + bare.late;
            const tally bare_fused = check_against_exact(cases, fast_test<true>(0.0));
            lost_fused_without_widening += bare_fused.missed + bare_fused.late;
        }
    // The same forms with no bound on their rounding miss boxes or enter them late: the widening is what the
    // checks above test.
    CHECK(lost_without_widening > 0);
    CHECK(lost_fused_without_widening > 0);
}

TEST_CASE("ch05 slab tests: the fast test refuses rays whose products could overflow", "[ch05][adversarial]") {
    const aabb bounds{vec3(-1e6f), vec3(1e6f)};
    const vec3 org(0.5f, 0.25f, -2.0f);
    CHECK(fast_slab::make(ray{org, vec3(1.0f, 0.5f, -0.25f)}, bounds));
    for (const float odd : {0.0f, -0.0f, std::numeric_limits<float>::denorm_min(), -1e-38f, 1e-30f}) {
        INFO("direction component " << odd);
        CHECK_FALSE(fast_slab::make(ray{org, vec3(1.0f, odd, 0.5f)}, bounds));
        CHECK_FALSE(fast_slab::make(ray{org, vec3(odd, 1.0f, 0.5f)}, bounds));
    }
    // Far enough from zero for a small scene, too small for a big one.
    CHECK(fast_slab::make(ray{org, vec3(1.0f, 1e-20f, 0.5f)}, aabb{vec3(-1.0f), vec3(1.0f)}));
    CHECK_FALSE(fast_slab::make(ray{org, vec3(1.0f, 1e-20f, 0.5f)}, aabb{vec3(-1e12f), vec3(1e12f)}));
}
