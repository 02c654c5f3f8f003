// Exercise 03.1 SAH event sweep (8 points). Read: J. D. MacDonald and K. S. Booth, "Heuristics for ray
// tracing using space subdivision", The Visual Computer 6(3), 1990; I. Wald and V. Havran, "On building
// fast kd-trees for ray tracing, and on doing that in O(N log N)", 2006 (section 4).
#include "strahl/ch03/sah.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch03 {

// Goal, part 1: the SAH cost of splitting `box` at `pos` on `axis` with n_left and n_right triangles on the
// two sides: C_T + C_I (P_L n_left + P_R n_right), P_L and P_R the children's surface areas over box's,
// times (1 - empty_bonus) when n_left or n_right is 0. A box of zero surface area: inf.
// Hint: the children are copies of box, the left with max[axis] = pos, the right with min[axis] = pos.
// Why: why give a split with an empty child a bonus, when the formula already charges that child nothing?
// Step by step: HINTS.md, 03.1.
float split_cost(const aabb& box, int axis, float pos, std::size_t n_left, std::size_t n_right, const sah_params& p) {
    STRAHL_TODO("03.1 SAH event sweep");
}

// Goal, part 2: the cheapest plane on `axis` over the sorted events (position, then end < planar < start) of
// n triangles, as a split_candidate: cost, pos, n_left and n_right at that plane (planar triangles in
// neither), n_planar, and the side the planar triangles go to (the cheaper, left at equal cost). Only planes
// strictly inside the box count; the lowest position wins ties; nothing found: axis set, cost inf.
// Hint: keep N_L (starts at 0) and N_R (starts at n): at each distinct position, the triangles ending or
// lying there leave N_R before the cost is taken, those lying or starting there join N_L after.
// Why: why does one sweep over sorted events price all the candidate planes in linear time, where counting
// the triangles on each side of each plane afresh would take quadratic time?
// Step by step: HINTS.md, 03.1.
split_candidate sah_sweep(std::span<const event> events, int axis, const aabb& box, std::size_t n,
                          const sah_params& p) {
    STRAHL_TODO("03.1 SAH event sweep");
}

}  // namespace strahl::ch03
