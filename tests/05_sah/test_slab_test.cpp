// Chapter 05's two slab tests (slab_test.hpp, 0 points): conservative against a slab test in long double on
// rays made to graze boxes edge-on, near and far from the origin; the fast test refused where its products
// could overflow; and without its widening, boxes are lost (so the first check can fail).
#include "strahl/ch05/slab_test.hpp"
#include "strahl/rng.hpp"
#include "slab_cases.hpp"
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

using namespace strahl;
using namespace strahl::ch05;

using test::grazing_cases;
using test::check_against_exact;
using test::tally;

namespace {

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
