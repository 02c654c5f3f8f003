// Exercise 13.1 the greedy collapse's choice (4 points). Read: I. Wald, C. Benthin and S. Boulos, "Getting
// rid of packets: efficient SIMD single-ray traversal using multi-branching BVHs", IEEE RT 2008, section 3.
#include "strahl/ch13/wide_bvh.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch13 {

// The inner child of largest surface area, the lowest index among equals; -1 when every child is a leaf.
// Hint: a leaf cannot be opened; an area may be 0 (a flat box) and still be the largest.
// Why the largest? Think of what the SAH says about the chance that a ray enters a box.
int child_to_open(std::span<const float> areas, std::span<const bool> leaf) {
    STRAHL_TODO("13.1 the child to open");
}

}  // namespace strahl::ch13
