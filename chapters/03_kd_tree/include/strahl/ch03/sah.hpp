// The surface area heuristic over split events, and how a triangle's box falls against a plane.
//   J. D. MacDonald and K. S. Booth, "Heuristics for ray tracing using space subdivision", The Visual
//   Computer 6(3), 1990 (the SAH);
//   I. Wald and V. Havran, "On building fast kd-trees for ray tracing, and on doing that in O(N log N)",
//   IEEE Symposium on Interactive Ray Tracing, 2006 (events, the sweep, planar triangles, the empty bonus).
#pragma once
#include "strahl/aabb.hpp"
#include <cstddef>
#include <cstdint>
#include <span>

namespace strahl::ch03 {

// The cost model. A leaf of n triangles costs C_I n; a split costs C_T plus, for each child, the
// probability that a ray through the node enters the child (area ratio) times C_I times its triangles.
// empty_bonus (Wald and Havran's lambda, as a discount): a split with one empty child costs (1 - empty_bonus)
// times as much, which favours cutting off empty space. 0 switches the option off.
struct sah_params {
    float c_traversal = 1.0f;     // C_T
    float c_intersect = 1.5f;     // C_I
    float empty_bonus = 0.2f;
};

// An event: where a triangle's box (clipped to the node's box) starts or ends on one axis, or where a
// triangle lies flat in a plane of that axis (planar). Sorted by position, and at equal positions
// end < planar < start, the order the sweep needs.
enum class event_type : std::uint8_t { end = 0, planar = 1, start = 2 };
struct event {
    float pos;
    event_type type;
};
inline bool operator<(const event& a, const event& b) {
    return a.pos < b.pos || (a.pos == b.pos && a.type < b.type);
}

// The best plane found on one axis. cost = +inf when no plane strictly inside the box exists.
// n_left and n_right count the triangles on each side, planar ones NOT included; n_planar counts those
// lying in the plane, and planar_left says on which side they go (the cheaper one; left at equal cost).
struct split_candidate {
    float cost = inf;
    int axis = 0;
    float pos = 0.0f;
    std::size_t n_left = 0, n_right = 0, n_planar = 0;
    bool planar_left = true;
};

// Exercise 03.1, step 1 "the cost of one plane": the SAH cost of splitting `box` at `pos` on `axis` with
// n_left and n_right triangles on the two sides (empty bonus applied when one side holds none).
float split_cost(const aabb& box, int axis, float pos, std::size_t n_left, std::size_t n_right, const sah_params& p);

// Exercise 03.1, step 2 "the event sweep": the cheapest plane on `axis` for a node with box `box` holding
// n triangles, given their events on that axis, sorted. Only planes strictly inside the box count.
split_candidate sah_sweep(std::span<const event> events, int axis, const aabb& box, std::size_t n,
                          const sah_params& p);

// Exercise 03.2 "classify": where a triangle with box b goes when its node splits at pos on axis. A box
// ending at or before the plane goes left, one starting at or after it right, one reaching across both
// (a straddling reference, counted once more); a box lying in the plane (b.min == b.max == pos) goes to the
// side planar_left names.
enum class side : std::uint8_t { left, right, both };
side classify(const aabb& b, int axis, float pos, bool planar_left);

}  // namespace strahl::ch03
