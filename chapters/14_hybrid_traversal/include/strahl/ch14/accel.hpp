// Chapter 14's hybrid tracer behind the course's accel interface: chapter 12's packets on chapter 13's
// 8-wide tree, each ray leaving its packet for chapter 13's single-ray walk where the packet has fallen apart.
// It is a chapter 12 packet tracer (packet_accel_base: the same queries, lane statistics and renderer); its
// per-ray figure is where the ray left its packet.
#pragma once
#include "strahl/ch12/accel.hpp"
#include "strahl/ch13/child_order.hpp"
#include <memory>
#include <string>

namespace strahl::ch14 {

// The switch: a ray leaves its packet where the packet reaches a node with this many active lanes or fewer.
// 0: never (chapter 12's wide walk); K: at the root (every ray alone, chapter 13's walk).
// automatic: per packet, from its coherence (packet_threshold, exercise 14.2).
inline constexpr int automatic = -1;

struct hybrid_config {
    int lanes = 16;              // K: 8 (4x2 tiles) or 16 (4x4 tiles)
    int tile_w = 4, tile_h = 4;  // tile_w * tile_h = K
    int image_width = 0;         // as chapter 12's packet_config
    int threshold = automatic;   // 0 .. K, or automatic
    // Strict: boxes tested from tmin itself, not from tmin - slack (below). Not exact: a triangle whose box
    // lies just behind tmin, which the triangle test's rounding may still hit at t >= tmin, goes untested;
    // the rays started on a surface no longer test the flat boxes around their origin. Embree's trade; the
    // race counts the rays that differ from brute force.
    bool strict = false;
    // The any-hit order of the lone walk (chapter 13's child_order.hpp): leaves first, then larger boxes, for
    // rays without end; collapsed: the stored order for every ray ("-stored" in the race).
    ch13::child_order order = ch13::child_order::leaves_then_area;
    ch04::mesh_bvh_builder builder{};  // as chapter 12's packet_config::builder (empty: chapter 05's binned SAH)
    // Closest hit of the rays that leave: each node's children in its order for the ray's octant (chapter
    // 13's order_by_octant), not sorted by entry distance.
    bool octant_order = false;
};

// One line: "hybrid, 16 lanes, 4x4 tiles, leave at <= 4 lanes" (or "... threshold per packet"), and
// "; strict boxes, tested from tmin (not exact)" for the strict variant, "; lone rays in the octant's
// order" for octant_order.
std::string describe(const hybrid_config& c);
std::string threshold_name(int threshold);

// K = 8 with 4x2 tiles, K = 16 with 4x4 tiles; threshold 0 .. K or automatic. Throws std::invalid_argument
// naming what is built for another.
std::unique_ptr<ch12::packet_accel_base> make_accel(std::string name, const hybrid_config& config);

// The coherence estimate's inputs, per packet (packet_threshold below): whether every active lane points
// into one octant, and the spread of the lanes' unit directions (the largest over the axes of the range of
// that axis's component, 0 for parallel rays, up to 2).
struct coherence {
    bool one_octant = true;
    float spread = 0.0f;
};

// The rule's bound, measured (chapter 14's program, NOTES.md): camera rays through a 4x4 tile spread by
// 0.015 to 0.03, shadow rays towards one light by 0.01 to 0.3, diffuse rays point into several octants.
// A packet in one octant with a spread below `tight` stays together down to a quarter of its lanes; any
// other, to half of them.
struct threshold_rule {
    float tight = 0.05f;
};

}  // namespace strahl::ch14
