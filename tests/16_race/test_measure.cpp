// How the race judges and measures (measure.hpp): agrees() demands bit-identical hits of exact structures
// and the same primitive of Embree, and measure_closest / measure_any count exactly the rays that differ
// from the reference, time at least one run, and report brute force's tests per ray.
#include "strahl/procedural.hpp"
#include "strahl/race/brute_force.hpp"
#include "strahl/race/measure.hpp"
#include "strahl/race/ray_sets.hpp"
#include <catch2/catch.hpp>
#include <cmath>

using namespace strahl;
using namespace strahl::race;

TEST_CASE("ch16 measure: agrees() is bit-exact for exact structures, same primitive otherwise", "[ch16][measure]") {
    const hit a{1.5f, 3u, 0.25f, 0.5f, invalid_id};
    const hit miss{};
    CHECK(agrees(a, a, true));
    CHECK(agrees(miss, miss, true));
    CHECK_FALSE(agrees(a, miss, true));
    CHECK_FALSE(agrees(miss, a, false));
    hit b = a;
    b.u = std::nextafter(a.u, 1.0f);  // one ulp off
    CHECK_FALSE(agrees(b, a, true));
    CHECK(agrees(b, a, false));
    b = a;
    b.t = std::nextafter(a.t, 0.0f);
    CHECK_FALSE(agrees(b, a, true));
    CHECK(agrees(b, a, false));
    b = a;
    b.prim = 4u;
    CHECK_FALSE(agrees(b, a, true));
    CHECK_FALSE(agrees(b, a, false));
    // Bits, not values: -0 and +0 compare equal as floats but are different answers.
    const hit zero{1.0f, 0u, 0.0f, 0.0f, invalid_id};
    hit negative_zero = zero;
    negative_zero.v = -0.0f;
    CHECK_FALSE(agrees(negative_zero, zero, true));
}

TEST_CASE("ch16 measure: the race counts exactly the rays that differ from the reference", "[ch16][measure]") {
    const scene s = builtin_scene("teapot");
    brute_force brute;
    brute.build(s);
    const std::vector<ray> rays = primary_rays(s, 24, 18);
    std::vector<hit> ref(rays.size());
    trace_closest(brute, rays, ref, 2);
    const timing_rules rules{2, 0.5, 1, 100};

    const query_result same = measure_closest(brute, rays, ref, rules);
    CHECK(same.differing == 0);
    CHECK(same.rays == rays.size());
    CHECK(same.runs >= 1);
    CHECK(same.mrays > 0.0);
    REQUIRE(same.prim_per_ray.has_value());
    CHECK(*same.prim_per_ray == Approx(double(s.mesh.triangle_count())));  // brute force tests every triangle

    // Corrupt three answers of the reference by one ulp or one id: exactly three rays differ.
    std::size_t first_hit = 0;
    while (!ref[first_hit].found()) ++first_hit;
    std::vector<hit> wrong = ref;
    wrong[first_hit].u = std::nextafter(wrong[first_hit].u, 2.0f);
    wrong[0] = hit{1.0f, 0u, 0.0f, 0.0f, invalid_id};  // pixel 0 sees the sky: a miss in the reference
    wrong.back().prim = ref.back().found() ? ref.back().prim + 1 : 0u;
    wrong.back().t = ref.back().found() ? ref.back().t : 1.0f;
    REQUIRE_FALSE(ref[0].found());
    CHECK(measure_closest(brute, rays, wrong, rules).differing == 3);

    const std::vector<ray> shadow = make_rays(ray_kind::shadow, s, 24, 18, 1, brute);
    std::vector<std::uint8_t> any(shadow.size());
    trace_any(brute, shadow, any, 2);
    const query_result any_same = measure_any(brute, shadow, any, rules);
    CHECK(any_same.differing == 0);
    CHECK(any_same.rays == shadow.size());
    any[0] ^= 1;
    any[any.size() / 2] ^= 1;
    CHECK(measure_any(brute, shadow, any, rules).differing == 2);
}

TEST_CASE("ch16 measure: the counting sample takes whole blocks (a packet tracer's tile rows), at most about the limit",
          "[ch16][measure]") {
    std::vector<ray> rays(1000);
    for (std::size_t i = 0; i < rays.size(); ++i) rays[i].tmin = float(i);
    const auto index = [](const ray& r) { return std::size_t(r.tmin); };
    // One ray a block: every k-th ray, as before.
    const std::vector<ray> single = counting_sample(rays, 100, 1);
    REQUIRE(single.size() == 100);
    for (std::size_t i = 0; i < single.size(); ++i) CHECK(index(single[i]) == 10 * i);
    // Blocks of 64 (the last one short): whole blocks starting on multiples of 64, runs of consecutive rays.
    const std::vector<ray> blocks = counting_sample(rays, 200, 64);
    REQUIRE(!blocks.empty());
    CHECK(blocks.size() <= 256);
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const std::size_t at = index(blocks[i]);
        if (i == 0 || index(blocks[i - 1]) + 1 != at) CHECK(at % 64 == 0);  // a block starts
        if (i + 1 == blocks.size() || index(blocks[i + 1]) != at + 1) CHECK(((at + 1) % 64 == 0 || at == 999));
    }
    // A limit below one block still counts one block; an empty batch gives nothing.
    CHECK(counting_sample(rays, 10, 64).size() == 64);
    CHECK(counting_sample(std::vector<ray>{}, 100, 64).empty());
}
