// Exercise 07.3 the split search (7 points). Read: radix_tree.hpp; T. Karras, "Thinking parallel, part III:
// tree construction on the GPU", NVIDIA developer blog 2012 (findSplit).
#include "strahl/ch07/radix_tree.hpp"

namespace strahl::ch07 {

// 07.3: the last index of the left half of [first, last].
std::uint32_t find_split(std::span<const std::uint64_t> codes, std::uint32_t first, std::uint32_t last) {
    const std::uint64_t a = codes[first], b = codes[last];
    if (a == b) return first + (last - first) / 2;  // equal codes: the middle
    const int common = std::countl_zero(a ^ b);
    // Binary search for the last index whose code shares more than `common` leading bits with a: the
    // candidate moves right by halving steps while it stays on the 0 side of the differing bit.
    std::uint32_t split = first, step = last - first;
    do {
        step = (step + 1) >> 1;
        const std::uint32_t candidate = split + step;
        if (candidate < last && std::countl_zero(a ^ codes[candidate]) > common) split = candidate;
    } while (step > 1);
    return split;
}

}  // namespace strahl::ch07
