// Exercise 07.2 one radix pass (7 points). Read: radix_sort.hpp.
#include "strahl/ch07/radix_sort.hpp"
#include <vector>

namespace strahl::ch07 {

// 07.2: the stable counting sort of the pairs by one digit.
void radix_pass(std::span<const std::uint64_t> keys_in, std::span<const std::uint32_t> ids_in,
                std::span<std::uint64_t> keys_out, std::span<std::uint32_t> ids_out, int shift, int digit_bits) {
    const std::uint64_t mask = (std::uint64_t(1) << digit_bits) - 1;
    // 1. Histogram.
    std::vector<std::uint32_t> next(std::size_t(mask) + 1, 0u);
    for (const std::uint64_t k : keys_in) ++next[(k >> shift) & mask];
    // 2. Exclusive prefix sum: next[v] becomes the first position of digit v.
    std::uint32_t sum = 0;
    for (std::uint32_t& c : next) {
        const std::uint32_t count = c;
        c = sum;
        sum += count;
    }
    // 3. Stable scatter, in input order.
    for (std::size_t i = 0; i < keys_in.size(); ++i) {
        const std::uint32_t to = next[(keys_in[i] >> shift) & mask]++;
        keys_out[to] = keys_in[i];
        ids_out[to] = ids_in[i];
    }
}

}  // namespace strahl::ch07
