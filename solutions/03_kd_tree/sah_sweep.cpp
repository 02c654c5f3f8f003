// Exercise 03.1 SAH event sweep. J. D. MacDonald and K. S. Booth, "Heuristics for ray tracing using space
// subdivision", The Visual Computer 6(3), 1990; I. Wald and V. Havran, "On building fast kd-trees for ray
// tracing, and on doing that in O(N log N)", IEEE Symposium on Interactive Ray Tracing, 2006 (section 4).
#include "strahl/ch03/sah.hpp"

namespace strahl::ch03 {

float split_cost(const aabb& box, int axis, float pos, std::size_t n_left, std::size_t n_right, const sah_params& p) {
    // Step 1, the cost of one plane: the children's boxes, their area ratios, C_T + C_I (P_L N_L + P_R N_R).
    const float area = box.surface_area();
    if (!(area > 0.0f)) return inf;
    aabb left = box, right = box;
    left.max[axis] = pos;
    right.min[axis] = pos;
    const float p_left = left.surface_area() / area, p_right = right.surface_area() / area;
    float cost = p.c_traversal + p.c_intersect * (p_left * float(n_left) + p_right * float(n_right));
    // The empty-space bonus: cutting off an empty child is cheaper than it looks.
    if (n_left == 0 || n_right == 0) cost *= 1.0f - p.empty_bonus;
    return cost;
}

split_candidate sah_sweep(std::span<const event> events, int axis, const aabb& box, std::size_t n,
                          const sah_params& p) {
    // Step 2, the event sweep: N_L triangles lie wholly left of the current plane, N_R still reach right
    // of it, N_P lie in it. Start with everything right; at each position, count the ends, planars and
    // starts there (they are sorted in that order).
    split_candidate best;
    best.axis = axis;
    std::size_t n_left = 0, n_right = n;
    std::size_t i = 0;
    while (i < events.size()) {
        const float pos = events[i].pos;
        std::size_t ends = 0, planars = 0, starts = 0;
        for (; i < events.size() && events[i].pos == pos && events[i].type == event_type::end; ++i) ++ends;
        for (; i < events.size() && events[i].pos == pos && events[i].type == event_type::planar; ++i) ++planars;
        for (; i < events.size() && events[i].pos == pos && events[i].type == event_type::start; ++i) ++starts;
        // Triangles ending here or lying in the plane no longer reach right of it.
        n_right -= ends + planars;
        // Only planes strictly inside the box split it; the planar triangles go to the cheaper side.
        if (pos > box.min[axis] && pos < box.max[axis]) {
            const float with_left = split_cost(box, axis, pos, n_left + planars, n_right, p);
            const float with_right = split_cost(box, axis, pos, n_left, n_right + planars, p);
            const bool planar_left = with_left <= with_right;
            const float cost = planar_left ? with_left : with_right;
            if (cost < best.cost) best = {cost, axis, pos, n_left, n_right, planars, planar_left};
        }
        // Past this plane: the planar triangles and those starting here lie left of the next one.
        n_left += planars + starts;
    }
    return best;
}

}  // namespace strahl::ch03
