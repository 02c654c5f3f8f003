// Least-significant-digit radix sort of (key, id) pairs: one stable counting sort per digit, lowest digit
// first. After the pass over digit d the pairs are sorted by digits 0..d, because every pass is stable.
// O(passes * (n + 2^digit_bits)) work, no comparisons.
//   H. H. Seward, "Information sorting in the application of electronic digital computers to business
//   operations", MIT 1954 (counting sort, LSD radix sort);
//   N. Satish, M. Harris and M. Garland, "Designing efficient sorting algorithms for manycore GPUs", IPDPS
//   2009 (per-block histograms, one prefix sum over digit-major counts, per-block stable scatter).
//
// Why 8 bits per digit: each pass scatters into 2^digit_bits output streams. With 256 of them, the
// histogram (1 KiB of counters) and one cache line being filled per stream (16 KiB) stay within L1, and
// the TLB covers the pages written to; and the parallel sort's serial prefix sum runs over chunks x 256
// counters. 11 bits (3 passes for a 30-bit code instead of 4, 6 instead of 8 for 63 bits) saves passes
// but scatters into 2048 streams, which no longer fit L1, and makes that prefix sum 8 times longer. On one
// thread the fewer passes win here (the chapter's program measures both: sort.csv); 8 stays the default.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>

namespace strahl::ch07 {

struct radix_sort_params {
    int key_bits = 64;    // keys lie below 2^key_bits (30 for 30-bit codes): the passes sort the low
                          // ceil(key_bits / digit_bits) * digit_bits bits only
    int digit_bits = 8;   // bits per pass, in [1, 16]: ceil(key_bits / digit_bits) passes
    std::size_t parallel_threshold = std::size_t(1) << 16;  // radix_sort: fewer pairs sort on one thread
};

// Exercise 07.2 "one radix pass": the stable counting sort of n = keys_in.size() pairs (keys_in[i],
// ids_in[i]) by the digit (key >> shift) & (2^digit_bits - 1), written to keys_out and ids_out:
//   1. histogram: the number of keys per digit value;
//   2. exclusive prefix sum: the first output position of each digit value;
//   3. scatter, in input order: each pair to its digit's next free position (stable: pairs with equal
//      digits keep their relative order).
// The four spans have the same size; input and output do not overlap. digit_bits in [1, 16].
void radix_pass(std::span<const std::uint64_t> keys_in, std::span<const std::uint32_t> ids_in,
                std::span<std::uint64_t> keys_out, std::span<std::uint32_t> ids_out, int shift, int digit_bits);

// The whole sort on one thread: radix_pass per digit, ping-ponging between the arrays and a scratch copy.
// Sorts keys and ids together, stably, by the keys (keys below 2^key_bits).
void radix_sort_serial(std::span<std::uint64_t> keys, std::span<std::uint32_t> ids, const radix_sort_params& p = {});

// The same sort on TBB's threads: per pass, the pairs cut into fixed chunks (their number depends on n only,
// not on the threads); a histogram per chunk in parallel; one exclusive prefix sum over the counts in
// digit-major, chunk-minor order (so chunk c's pairs of digit v follow chunks 0..c-1's of the same digit);
// a stable scatter per chunk in parallel. The result equals radix_sort_serial's, bit for bit.
void radix_sort_parallel(std::span<std::uint64_t> keys, std::span<std::uint32_t> ids, const radix_sort_params& p = {});

// radix_sort_parallel from p.parallel_threshold pairs up, radix_sort_serial below (where starting tasks
// costs more than it saves). The builders' sort.
void radix_sort(std::span<std::uint64_t> keys, std::span<std::uint32_t> ids, const radix_sort_params& p = {});

}  // namespace strahl::ch07
