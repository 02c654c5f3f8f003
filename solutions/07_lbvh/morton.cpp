// Exercise 07.1 the bit expansion (6 points). Read: morton.hpp; C. Lauterbach et al., "Fast BVH construction
// on GPUs", Eurographics 2009, section 4.1.
#include "strahl/ch07/morton.hpp"

namespace strahl::ch07 {

// 07.1: bit k of v (k < 10) to bit 3k. Each step halves the distance the bits still have to travel: after
// the shift by 16, bits 8-9 sit 16 above bits 0-7; after 8, groups of 4 bits lie 8 apart; after 4 and 2,
// single bits lie 3 apart. The masks keep only the moved copies in their new places.
std::uint32_t expand_bits10(std::uint32_t v) {
    v &= 0x3ffu;
    v = (v | v << 16) & 0x030000ffu;
    v = (v | v << 8) & 0x0300f00fu;
    v = (v | v << 4) & 0x030c30c3u;
    v = (v | v << 2) & 0x09249249u;
    return v;
}

}  // namespace strahl::ch07
