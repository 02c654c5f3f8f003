// Exercise 07.1 the bit expansion (6 points), and beyond the points: the 21-bit expansion, the pdep
// versions, the quantisation and the codes phase.
#include "strahl/ch07/morton.hpp"
#include "strahl/rng.hpp"
#include <catch2/catch.hpp>
#include <limits>

using namespace strahl;
using namespace strahl::ch07;

namespace {

// The slow definition: bit k of v to bit 3k, one bit at a time.
std::uint64_t spread_slowly(std::uint64_t v, int bits) {
    std::uint64_t out = 0;
    for (int k = 0; k < bits; ++k) out |= ((v >> k) & 1u) << (3 * k);
    return out;
}

}  // namespace

TEST_CASE("07.1 bit expansion: all 1024 inputs equal the bit-by-bit definition", "[ch07][pts:4]") {
    std::size_t wrong = 0;
    for (std::uint32_t v = 0; v < 1024; ++v)
        if (expand_bits10(v) != spread_slowly(v, 10) && ++wrong <= 3)
            FAIL_CHECK("expand_bits10(" << v << ") = " << expand_bits10(v) << ", expected " << spread_slowly(v, 10));
    CHECK(wrong == 0);
}

TEST_CASE("07.1 bit expansion: the 30-bit codes of some points, bits above the tenth ignored", "[ch07][pts:2]") {
    CHECK(morton30(0, 0, 0) == 0u);
    CHECK(morton30(1, 0, 0) == 4u);  // x's bits highest
    CHECK(morton30(0, 1, 0) == 2u);
    CHECK(morton30(0, 0, 1) == 1u);
    CHECK(morton30(3, 1, 2) == 0b101110u);  // x1 y1 z1 x0 y0 z0 = 1 0 1 1 1 0
    CHECK(morton30(1023, 1023, 1023) == (1u << 30) - 1);
    CHECK(morton30(512, 0, 0) == 1u << 29);
    CHECK(expand_bits10(0xfffffc00u | 5u) == expand_bits10(5u));
    CHECK(expand_bits10(1024u) == 0u);
}

TEST_CASE("ch07 Morton: the 21-bit expansion and both pdep versions equal the definition", "[ch07]") {
    pcg32 g(7);
    std::vector<std::uint64_t> inputs = {0, 1, 0x1fffff, 0x155555, 0x0aaaaa};
    for (int k = 0; k < 21; ++k) inputs.push_back(std::uint64_t(1) << k);
    for (int i = 0; i < 20000; ++i) inputs.push_back(g.next_u32() & 0x1fffffu);
    for (const std::uint64_t v : inputs) {
        INFO("v = " << v);
        REQUIRE(expand_bits21(v) == spread_slowly(v, 21));
        REQUIRE(expand_bits21_pdep(v) == spread_slowly(v, 21));
        REQUIRE(expand_bits10_pdep(std::uint32_t(v & 0x3ff)) == spread_slowly(v & 0x3ff, 10));
    }
    CHECK(expand_bits21(std::uint64_t(1) << 21) == 0u);  // bits above the 21st ignored
    CHECK(morton63(0x1fffff, 0x1fffff, 0x1fffff) == (std::uint64_t(1) << 63) - 1);
    CHECK(axis_of_bit(62) == 0);
    CHECK(axis_of_bit(61) == 1);
    CHECK(axis_of_bit(60) == 2);
}

TEST_CASE("ch07 Morton: quantisation clamps, flat axes and NaN give cell 0", "[ch07]") {
    const quantizer q(aabb{vec3(0, -1, 5), vec3(1, 1, 5)}, 10);
    CHECK(q(0.0f, 0) == 0u);
    CHECK(q(1.0f, 0) == 1023u);        // the top lands one past the last cell: clamped
    CHECK(q(0.49999f, 0) == 511u);
    CHECK(q(0.5f, 0) == 512u);
    CHECK(q(-7.0f, 0) == 0u);          // outside the box: clamped
    CHECK(q(1e30f, 1) == 1023u);
    CHECK(q(5.0f, 2) == 0u);           // extent 0
    CHECK(q(std::numeric_limits<float>::quiet_NaN(), 0) == 0u);
    const quantizer wide(aabb{vec3(-3e38f), vec3(3e38f)}, 21);  // the extent overflows float, not double
    CHECK(wide(3e38f, 0) == (1u << 21) - 1);
    CHECK(wide(0.0f, 0) == 1u << 20);
}

TEST_CASE("ch07 Morton: the codes phase sets non-finite primitives aside and codes the others", "[ch07]") {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    std::vector<aabb> boxes = {{vec3(0), vec3(1)}, {vec3(nan), vec3(1)}, {vec3(3), vec3(4)}, {vec3(0), vec3(inf)},
                               {vec3(1, 0, 0), vec3(2, 1, 1)}, aabb::empty()};
    std::vector<vec3> centroids;
    for (const aabb& b : boxes) centroids.push_back(b.centroid());
    for (const bool pdep : {false, true}) {
        const morton_codes c = compute_morton_codes(boxes, centroids, 21, pdep);
        CHECK(c.ids == std::vector<std::uint32_t>{0, 2, 4});
        CHECK(c.loose == std::vector<std::uint32_t>{1, 3, 5});
        REQUIRE(c.keys.size() == 3);
        CHECK(c.keys[0] == 0u);                              // the box's minimum corner
        CHECK(c.keys[1] == (std::uint64_t(1) << 63) - 1);    // its maximum corner: the last cell
        CHECK(c.keys[2] == morton63((1u << 21) / 3, 0, 0));  // x = 1.5 of [0.5, 3.5]: a third
    }
    // Every centroid in one plane, then in one point: the flat axes give 0 bits.
    const std::vector<aabb> flat = {{vec3(0, 2, 0), vec3(1, 2, 1)}, {vec3(2, 2, 2), vec3(3, 2, 3)}};
    const std::vector<vec3> flat_c = {flat[0].centroid(), flat[1].centroid()};
    const morton_codes f = compute_morton_codes(flat, flat_c, 10);
    CHECK(f.keys == std::vector<std::uint64_t>{0, morton30(1023, 0, 1023)});
    const std::vector<vec3> same = {vec3(1), vec3(1)};
    CHECK(compute_morton_codes(flat, same, 10).keys == std::vector<std::uint64_t>{0, 0});
    CHECK(compute_morton_codes({}, {}, 10).keys.empty());
}
