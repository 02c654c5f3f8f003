// Exercise 07.3 the split search (7 points): find_split against a linear scan of the definition.
#include "strahl/ch07/radix_tree.hpp"
#include "strahl/rng.hpp"
#include <algorithm>
#include <catch2/catch.hpp>
#include <vector>

using namespace strahl;
using namespace strahl::ch07;

namespace {

// The definition, one index at a time: the last index in [first, last) sharing more leading bits with
// codes[first] than codes[last] does; the middle for equal ends.
std::uint32_t split_slowly(const std::vector<std::uint64_t>& codes, std::uint32_t first, std::uint32_t last) {
    if (codes[first] == codes[last]) return first + (last - first) / 2;
    const int common = std::countl_zero(codes[first] ^ codes[last]);
    std::uint32_t g = first;
    for (std::uint32_t k = first; k < last; ++k)
        if (std::countl_zero(codes[first] ^ codes[k]) > common) g = k;
    return g;
}

std::vector<std::uint64_t> sorted_codes(std::size_t n, std::uint64_t seed, int bits) {
    pcg32 g(seed);
    std::vector<std::uint64_t> codes(n);
    for (std::uint64_t& c : codes) c = ((std::uint64_t(g.next_u32()) << 32) | g.next_u32()) >> (64 - bits);
    std::sort(codes.begin(), codes.end());
    return codes;
}

void check_ranges(const std::vector<std::uint64_t>& codes, std::uint64_t seed, int ranges) {
    pcg32 g(seed);
    const auto n = std::uint32_t(codes.size());
    for (int r = 0; r < ranges; ++r) {
        std::uint32_t a = g.next_bounded(n), b = g.next_bounded(n);
        if (a == b) continue;
        if (a > b) std::swap(a, b);
        INFO("range [" << a << ", " << b << "]: codes " << codes[a] << " .. " << codes[b]);
        REQUIRE(find_split(codes, a, b) == split_slowly(codes, a, b));
    }
}

}  // namespace

TEST_CASE("07.3 split search: random sorted codes, random ranges, equal the definition", "[ch07][pts:4]") {
    check_ranges(sorted_codes(2000, 1, 30), 2, 3000);
    check_ranges(sorted_codes(2000, 3, 63), 4, 3000);
    check_ranges(sorted_codes(300, 5, 64), 6, 2000);  // the top bit used too
    check_ranges(sorted_codes(3000, 7, 9), 8, 3000);  // few distinct codes: long runs of equal ones
    // The whole range of every prefix and suffix.
    const std::vector<std::uint64_t> c = sorted_codes(257, 9, 30);
    for (std::uint32_t k = 1; k < c.size(); ++k) {
        REQUIRE(find_split(c, 0, k) == split_slowly(c, 0, k));
        REQUIRE(find_split(c, k - 1, std::uint32_t(c.size() - 1)) == split_slowly(c, k - 1, std::uint32_t(c.size() - 1)));
    }
}

TEST_CASE("07.3 split search: two codes, equal codes at the middle, runs of equal codes", "[ch07][pts:3]") {
    const std::vector<std::uint64_t> two = {4, 5};
    CHECK(find_split(two, 0, 1) == 0u);
    const std::vector<std::uint64_t> same(10, 7);
    CHECK(find_split(same, 0, 9) == 4u);
    CHECK(find_split(same, 3, 4) == 3u);
    CHECK(find_split(same, 2, 9) == 5u);
    // 0b0100 x 5, 0b0110 x 2, 0b1000 x 3: the top differing bit of [0, 9] is bit 3: split after index 6.
    const std::vector<std::uint64_t> runs = {4, 4, 4, 4, 4, 6, 6, 8, 8, 8};
    CHECK(find_split(runs, 0, 9) == 6u);
    CHECK(find_split(runs, 0, 6) == 4u);  // bit 1 differs: after the run of 4s
    CHECK(find_split(runs, 5, 9) == 6u);
    CHECK(find_split(runs, 7, 9) == 8u);  // all equal: the middle
    // The differing bit at the top of a 64-bit word, and a range ending at the last index.
    const std::vector<std::uint64_t> top = {0, 1, 2, 0x8000000000000000ull, 0xffffffffffffffffull};
    CHECK(find_split(top, 0, 4) == 2u);
    CHECK(find_split(top, 3, 4) == 3u);
}
