// Exercise 07.1 the bit expansion (6 points). Read: morton.hpp; C. Lauterbach et al., "Fast BVH construction
// on GPUs", Eurographics 2009, section 4.1.
#include "strahl/ch07/morton.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch07 {

// 07.1: the low 10 bits of v spread to every third bit: bit k of v to bit 3k (k < 10), all other bits 0.
// Hint: four steps v = (v | v << s) & mask for s = 16, 8, 4, 2; write the bit positions each step must
// leave (e.g. after s = 16: bits 0-7 where they were, bits 8-9 moved up to 24-25) and read the mask off.
// expand_bits21 in morton.hpp does the same for 21 bits in five steps.
// Why interleave the bits at all: what do two codes sharing their first 3m bits say about the two points?
// Step by step: HINTS.md, 07.1.
std::uint32_t expand_bits10(std::uint32_t v) {
    STRAHL_TODO("07.1 the bit expansion");
}

}  // namespace strahl::ch07
