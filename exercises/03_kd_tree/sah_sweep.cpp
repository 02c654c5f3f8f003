// Exercise 03.1 SAH event sweep (8 points). Read: J. D. MacDonald and K. S. Booth, "Heuristics for ray
// tracing using space subdivision", The Visual Computer 6(3), 1990; I. Wald and V. Havran, "On building
// fast kd-trees for ray tracing, and on doing that in O(N log N)", 2006 (section 4).
#include "strahl/ch03/sah.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch03 {

// Step 1, the cost of one plane. Split `box` at `pos` on `axis` into a left box (max[axis] = pos) and a
// right box (min[axis] = pos); P_L and P_R are their surface areas divided by box's. The cost is
//   C_T + C_I (P_L n_left + P_R n_right),
// times (1 - empty_bonus) when n_left or n_right is 0. A box of zero surface area: return inf.
float split_cost(const aabb& box, int axis, float pos, std::size_t n_left, std::size_t n_right, const sah_params& p) {
    STRAHL_TODO("03.1 SAH event sweep");
}

// Step 2, the event sweep. The events are sorted (position, then end < planar < start). Keep three counts:
// N_L (wholly left of the current plane; starts at 0), N_R (still reaching right of it; starts at n),
// and at each distinct position p count the ends, planars and starts there, then
//   N_R -= ends + planars;
//   if p lies strictly inside the box on this axis: cost with the planar triangles on the left,
//     split_cost(box, axis, p, N_L + planars, N_R), and on the right, split_cost(..., N_L, N_R + planars);
//     keep the cheaper (left at equal cost) if it beats the best so far (strictly: the lowest p wins ties);
//   N_L += planars + starts.
// Return the best as a split_candidate (axis set even when nothing was found, cost = inf then), with
// n_left = N_L and n_right = N_R at that plane (planar ones in neither) and n_planar = planars.
split_candidate sah_sweep(std::span<const event> events, int axis, const aabb& box, std::size_t n,
                          const sah_params& p) {
    STRAHL_TODO("03.1 SAH event sweep");
}

}  // namespace strahl::ch03
