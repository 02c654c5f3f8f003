// Exercise 13.1 the greedy collapse's choice (4 points). Read: I. Wald, C. Benthin and S. Boulos, "Getting
// rid of packets: efficient SIMD single-ray traversal using multi-branching BVHs", IEEE RT 2008, section 3.
#include "strahl/ch13/wide_bvh.hpp"

namespace strahl::ch13 {

// The inner child of largest surface area, the lowest index among equals; -1 when every child is a leaf.
// The larger a child's box, the likelier a ray enters it (the SAH's probability): opening it saves the most
// visits of a node that would only pass the ray on.
int child_to_open(std::span<const float> areas, std::span<const bool> leaf) {
    int best = -1;
    for (std::size_t k = 0; k < areas.size(); ++k)
        if (!leaf[k] && (best < 0 || areas[k] > areas[std::size_t(best)])) best = int(k);
    return best;
}

}  // namespace strahl::ch13
