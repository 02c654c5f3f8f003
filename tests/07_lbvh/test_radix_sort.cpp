// Exercise 07.2 one radix pass (7 points), and beyond the points: the whole sort, serial and parallel,
// against std::stable_sort.
#include "strahl/ch07/radix_sort.hpp"
#include "strahl/parallel.hpp"
#include "strahl/rng.hpp"
#include "differences.hpp"
#include <algorithm>
#include <catch2/catch.hpp>
#include <numeric>
#include <vector>

using namespace strahl;
using namespace strahl::ch07;
using test::first_difference;

namespace {

struct pairs {
    std::vector<std::uint64_t> keys;
    std::vector<std::uint32_t> ids;
};

pairs numbered(std::vector<std::uint64_t> keys) {
    pairs p{std::move(keys), {}};
    p.ids.resize(p.keys.size());
    std::iota(p.ids.begin(), p.ids.end(), 0u);
    return p;
}

// std::stable_sort of the pairs by f(key).
template <class F>
pairs stable_sorted(const pairs& in, F&& f) {
    std::vector<std::uint32_t> order(in.keys.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return f(in.keys[a]) < f(in.keys[b]); });
    pairs out;
    for (const std::uint32_t k : order) out.keys.push_back(in.keys[k]), out.ids.push_back(in.ids[k]);
    return out;
}

pairs random_pairs(std::size_t n, std::uint64_t seed, std::uint64_t mask = ~std::uint64_t(0)) {
    pcg32 g(seed);
    std::vector<std::uint64_t> keys(n);
    for (std::uint64_t& k : keys) k = ((std::uint64_t(g.next_u32()) << 32) | g.next_u32()) & mask;
    return numbered(std::move(keys));
}

pairs one_pass(const pairs& in, int shift, int bits) {
    pairs out{std::vector<std::uint64_t>(in.keys.size()), std::vector<std::uint32_t>(in.ids.size())};
    radix_pass(in.keys, in.ids, out.keys, out.ids, shift, bits);
    return out;
}

}  // namespace

TEST_CASE("07.2 radix pass: a hand-sorted example, stable among equal digits", "[ch07][pts:3]") {
    const pairs in = numbered({0x21, 0x10, 0x31, 0x20, 0x11, 0x1f});
    // Digit 4..7: 2, 1, 3, 2, 1, 1. Equal digits keep their order (ids 1, 4, 5 and 0, 3).
    const pairs out = one_pass(in, 4, 4);
    CHECK(out.keys == std::vector<std::uint64_t>{0x10, 0x11, 0x1f, 0x21, 0x20, 0x31});
    CHECK(out.ids == std::vector<std::uint32_t>{1, 4, 5, 0, 3, 2});
    // Digit 0..3: 1, 0, 1, 0, 1, 15.
    const pairs low = one_pass(in, 0, 4);
    CHECK(low.ids == std::vector<std::uint32_t>{1, 3, 0, 2, 4, 5});
    const pairs none = one_pass(numbered({}), 0, 8);
    CHECK(none.keys.empty());
}

TEST_CASE("07.2 radix pass: random keys, any digit, equals std::stable_sort by that digit", "[ch07][pts:4]") {
    const pairs in = random_pairs(3000, 5);
    const pairs few = random_pairs(3000, 6, 0x0303030303030303ull);  // many equal digits
    for (const pairs* p : {&in, &few})
        for (const auto& [shift, bits] : {std::pair{0, 8}, {8, 8}, {56, 8}, {3, 11}, {53, 11}, {63, 1}, {0, 16}}) {
            INFO("shift " << shift << ", " << bits << " bits");
            const std::uint64_t mask = (std::uint64_t(1) << bits) - 1;
            const pairs want = stable_sorted(*p, [&](std::uint64_t k) { return (k >> shift) & mask; });
            const pairs got = one_pass(*p, shift, bits);
            CHECK(first_difference(got.keys, want.keys) == -1);
            CHECK(first_difference(got.ids, want.ids) == -1);
        }
}

namespace {

void check_sorts(const pairs& in, const radix_sort_params& p) {
    const std::uint64_t mask = p.key_bits == 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << p.key_bits) - 1;
    const pairs want = stable_sorted(in, [&](std::uint64_t k) { return k & mask; });
    pairs serial = in, parallel = in;
    radix_sort_serial(serial.keys, serial.ids, p);
    CHECK(first_difference(serial.keys, want.keys) == -1);
    CHECK(first_difference(serial.ids, want.ids) == -1);
    for (const int threads : {1, 2}) {
        const thread_limit limit(threads);
        parallel = in;
        radix_sort_parallel(parallel.keys, parallel.ids, p);
        CHECK(first_difference(parallel.keys, serial.keys) == -1);
        CHECK(first_difference(parallel.ids, serial.ids) == -1);
    }
}

}  // namespace

TEST_CASE("ch07 radix sort: serial and parallel equal std::stable_sort on keys made to break them", "[ch07]") {
    radix_sort_params p;
    for (const int digit : {8, 11, 3}) {
        p.digit_bits = digit;
        INFO(digit << " bits per digit");
        // 10^5 pairs for 8-bit digits, fewer (still more than one chunk of 2^15) for the others.
        const std::size_t big = digit == 8 ? 100000 : 40000;
        for (const std::size_t n : {0, 1, 2, 3, 1000}) check_sorts(random_pairs(n, n + 1), p);
        check_sorts(random_pairs(big, 9), p);
        check_sorts(random_pairs(big, 10, 0xf00000000000000full), p);         // many duplicates
        check_sorts(numbered(std::vector<std::uint64_t>(big, 42)), p);        // all equal
        pairs sorted = random_pairs(big, 11), reversed;
        std::sort(sorted.keys.begin(), sorted.keys.end());
        check_sorts(sorted, p);
        reversed = numbered(std::vector<std::uint64_t>(sorted.keys.rbegin(), sorted.keys.rend()));
        check_sorts(reversed, p);
    }
    // 30-bit codes: only four passes of 8 bits (or three of 11).
    p.key_bits = 30;
    for (const int digit : {8, 11}) {
        p.digit_bits = digit;
        check_sorts(random_pairs(100000, 12, (1u << 30) - 1), p);
    }
}

TEST_CASE("ch07 radix sort: the dispatch sorts below and above the threshold", "[ch07]") {
    radix_sort_params p;
    p.parallel_threshold = 1000;
    for (const std::size_t n : {999, 1000, 5000}) {
        pairs a = random_pairs(n, 3), b = a;
        radix_sort(a.keys, a.ids, p);
        radix_sort_serial(b.keys, b.ids, p);
        CHECK(first_difference(a.ids, b.ids) == -1);
        CHECK(std::is_sorted(a.keys.begin(), a.keys.end()));
    }
    pairs bad = random_pairs(10, 1);
    bad.ids.pop_back();
    CHECK_THROWS_AS(radix_sort(bad.keys, bad.ids, p), std::invalid_argument);
}
