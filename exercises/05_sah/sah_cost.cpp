// Exercise 05.1 the SAH cost of a split (2 points). Read: J. D. MacDonald and K. S. Booth, "Heuristics
// for ray tracing using space subdivision", The Visual Computer 6(3), 1990; the chapter's README.
#include "strahl/ch05/sah.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch05 {

// Goal: the expected cost of splitting P into the leaves L and R:
//   C = C_T + C_I * (A(L) / A(P) * N_L + A(R) / A(P) * N_R)
// with C_T = c.traversal, C_I = c.intersection, A(P) = area_parent > 0.
// Hint: one line; convert the counts to float before multiplying.
// Why: why is A(L) / A(P) the chance that a ray through P also meets L, and what does that assume about
// the rays?
// Step by step: HINTS.md, 05.1.
float split_cost(const sah_costs& c, float area_parent, float area_left, std::size_t n_left, float area_right,
                 std::size_t n_right) {
    STRAHL_TODO("05.1 SAH cost of a split");
}

}  // namespace strahl::ch05
