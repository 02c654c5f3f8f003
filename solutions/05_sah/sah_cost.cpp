// Exercise 05.1 the SAH cost of a split. J. D. MacDonald and K. S. Booth, "Heuristics for ray tracing
// using space subdivision", The Visual Computer 6(3), 1990; J. Goldsmith and J. Salmon, IEEE CG&A 1987.
#include "strahl/ch05/sah.hpp"

namespace strahl::ch05 {

float split_cost(const sah_costs& c, float area_parent, float area_left, std::size_t n_left, float area_right,
                 std::size_t n_right) {
    // One traversal step at P, then each child's primitives, weighted by the chance a ray through P meets it.
    const float p_left = area_left / area_parent, p_right = area_right / area_parent;
    return c.traversal + c.intersection * (p_left * float(n_left) + p_right * float(n_right));
}

}  // namespace strahl::ch05
