// Exercise 07.3 the split search (7 points). Read: radix_tree.hpp; T. Karras, "Thinking parallel, part III:
// tree construction on the GPU", NVIDIA developer blog 2012 (findSplit).
#include "strahl/ch07/radix_tree.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch07 {

// 07.3: the last index g of the left half of [first, last] (first < last): codes[first..g] share more
// than countl_zero(codes[first] ^ codes[last]) leading bits with codes[first], codes[g+1..last] do not.
// Equal codes[first] and codes[last]: the middle, first + (last - first) / 2.
// Hint: binary search with a step that halves (rounding up) each round, starting at first: move to
// first + step whenever that index is below last and still shares the longer prefix.
// Why does a binary search work here: what does sorting say about where the differing bit flips?
// Step by step: HINTS.md, 07.3.
std::uint32_t find_split(std::span<const std::uint64_t> codes, std::uint32_t first, std::uint32_t last) {
    STRAHL_TODO("07.3 the split search");
}

}  // namespace strahl::ch07
