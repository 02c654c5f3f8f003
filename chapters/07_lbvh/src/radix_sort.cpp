// LSD radix sort of (key, id) pairs, on one thread (exercise 07.2's pass per digit) and on TBB's threads
// (per-chunk histograms and scatters; Satish, Harris and Garland 2009).
#include "strahl/ch07/radix_sort.hpp"
#include "strahl/parallel.hpp"
#include <algorithm>
#include <stdexcept>
#include <vector>

namespace strahl::ch07 {

namespace {

void check(std::span<std::uint64_t> keys, std::span<std::uint32_t> ids, const radix_sort_params& p) {
    if (keys.size() != ids.size()) throw std::invalid_argument("radix sort: one id per key");
    if (p.digit_bits < 1 || p.digit_bits > 16) throw std::invalid_argument("radix sort: digit_bits in [1, 16]");
    if (p.key_bits < 0 || p.key_bits > 64) throw std::invalid_argument("radix sort: key_bits in [0, 64]");
}

int passes(const radix_sort_params& p) { return (p.key_bits + p.digit_bits - 1) / p.digit_bits; }

// Runs pass(in, out, shift) per digit between the caller's arrays and a scratch copy, and leaves the result
// in the caller's arrays.
template <class Pass>
void ping_pong(std::span<std::uint64_t> keys, std::span<std::uint32_t> ids, const radix_sort_params& p, Pass&& pass) {
    std::vector<std::uint64_t> keys2(keys.size());
    std::vector<std::uint32_t> ids2(ids.size());
    std::span<std::uint64_t> k_in = keys, k_out = keys2;
    std::span<std::uint32_t> i_in = ids, i_out = ids2;
    for (int d = 0; d < passes(p); ++d) {
        pass(k_in, i_in, k_out, i_out, d * p.digit_bits);
        std::swap(k_in, k_out), std::swap(i_in, i_out);
    }
    if (k_in.data() != keys.data()) {  // an odd number of passes: the result lies in the scratch copy
        std::copy(k_in.begin(), k_in.end(), keys.begin());
        std::copy(i_in.begin(), i_in.end(), ids.begin());
    }
}

}  // namespace

void radix_sort_serial(std::span<std::uint64_t> keys, std::span<std::uint32_t> ids, const radix_sort_params& p) {
    check(keys, ids, p);
    if (keys.size() < 2) return;
    ping_pong(keys, ids, p, [&](auto k_in, auto i_in, auto k_out, auto i_out, int shift) {
        radix_pass(k_in, i_in, k_out, i_out, shift, p.digit_bits);
    });
}

void radix_sort_parallel(std::span<std::uint64_t> keys, std::span<std::uint32_t> ids, const radix_sort_params& p) {
    check(keys, ids, p);
    const std::size_t n = keys.size();
    if (n < 2) return;
    // Fixed chunks of about 2^13 pairs (at most 256 of them): the same cut whatever the thread count, and
    // enough chunks for the threads to share evenly (3 chunks on 2 threads would leave one idle a third of
    // the time).
    const std::size_t chunks = std::clamp<std::size_t>((n + 8191) / 8192, 1, 256);
    const std::size_t chunk = (n + chunks - 1) / chunks;
    const std::size_t buckets = std::size_t(1) << p.digit_bits;
    std::vector<std::uint32_t> offsets(chunks * buckets);  // row c: chunk c's counts, then its first positions
    ping_pong(keys, ids, p, [&](auto k_in, auto i_in, auto k_out, auto i_out, int shift) {
        const std::uint64_t mask = buckets - 1;
        const std::uint64_t* keys_from = k_in.data();
        const std::uint32_t* ids_from = i_in.data();
        std::uint64_t* keys_to = k_out.data();
        std::uint32_t* ids_to = i_out.data();
        // 1. A histogram per chunk, in parallel.
        parallel_for_chunks(chunks, 1, [&](std::size_t c0, std::size_t c1) {
            for (std::size_t c = c0; c < c1; ++c) {
                std::uint32_t* h = offsets.data() + c * buckets;
                std::fill(h, h + buckets, 0u);
                const std::size_t end = std::min(n, (c + 1) * chunk);
                for (std::size_t i = c * chunk; i < end; ++i) ++h[(keys_from[i] >> shift) & mask];
            }
        });
        // 2. The exclusive prefix sum, digit-major and chunk-minor: chunk c writes its digit-v pairs after
        //    every pair of a lower digit and after chunks 0..c-1's digit-v pairs.
        std::uint32_t sum = 0;
        for (std::size_t v = 0; v < buckets; ++v)
            for (std::size_t c = 0; c < chunks; ++c) {
                const std::uint32_t count = offsets[c * buckets + v];
                offsets[c * buckets + v] = sum;
                sum += count;
            }
        // 3. The stable scatter per chunk, in parallel: each chunk in input order into its own positions.
        parallel_for_chunks(chunks, 1, [&](std::size_t c0, std::size_t c1) {
            for (std::size_t c = c0; c < c1; ++c) {
                std::uint32_t* next = offsets.data() + c * buckets;
                const std::size_t end = std::min(n, (c + 1) * chunk);
                for (std::size_t i = c * chunk; i < end; ++i) {
                    const std::uint64_t key = keys_from[i];
                    const std::uint32_t to = next[(key >> shift) & mask]++;
                    keys_to[to] = key;
                    ids_to[to] = ids_from[i];
                }
            }
        });
    });
}

void radix_sort(std::span<std::uint64_t> keys, std::span<std::uint32_t> ids, const radix_sort_params& p) {
    if (keys.size() >= p.parallel_threshold)
        radix_sort_parallel(keys, ids, p);
    else
        radix_sort_serial(keys, ids, p);
}

}  // namespace strahl::ch07
