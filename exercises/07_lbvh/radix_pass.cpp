// Exercise 07.2 one radix pass (7 points). Read: radix_sort.hpp.
#include "strahl/ch07/radix_sort.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch07 {

// 07.2: the stable counting sort of the pairs (keys_in[i], ids_in[i]) by the digit
// (key >> shift) & (2^digit_bits - 1), into keys_out and ids_out: histogram, exclusive prefix sum, scatter.
// Hint: after the prefix sum, the count of digit v is replaced by the number of keys with a smaller digit:
// the position where the first key with digit v goes. Scatter in input order, incrementing it.
// Why must each pass be stable for the whole sort (lowest digit first) to be right?
// Step by step: HINTS.md, 07.2.
void radix_pass(std::span<const std::uint64_t> keys_in, std::span<const std::uint32_t> ids_in,
                std::span<std::uint64_t> keys_out, std::span<std::uint32_t> ids_out, int shift, int digit_bits) {
    STRAHL_TODO("07.2 one radix pass");
}

}  // namespace strahl::ch07
