// Chapter 13's wide BVHs behind the course's accel interface: a binary tree from chapter 05 (or 06), collapsed
// into N-wide nodes with leaves in blocks of M triangles, walked by wide_traverse.hpp. The race registers them.
#pragma once
#include "strahl/accel.hpp"
#include "strahl/ch04/accel.hpp"
#include "strahl/ch13/child_order.hpp"
#include "strahl/ch13/wide_bvh.hpp"
#include <memory>
#include <string>

namespace strahl::ch13 {

struct wide_config {
    int width = 8;        // N: children per node, 4, 8 or 16
    int block = 4;        // M: triangles per leaf block, 4 or 8
    collapse_config collapse;
    bool any_hit_nearest = false;  // any hit: visit the nearest child first (as closest hit does), or the
                                   // children in stored order (the default: no sorting)
    child_order order = child_order::collapsed;  // how nodes store their children (child_order.hpp): the
                                                 // any-hit walk's order
    bool octant_order = false;     // closest hit in each node's order for the ray's octant (order_by_octant;
                                   // width 8), not by the entry distances
    bool quantized = false;        // nodes quantised to bytes (quantized_node.hpp): width 8, blocks of 8
    bool watertight = false;       // chapter 15's watertight test in the leaves (width 8 or 16, blocks of 4)
                                   // instead of Moeller-Trumbore
};

// The widths this build runs with intrinsics (simd::native), for the programs' headers: "SSE2 4, AVX 8, ...".
std::string simd_widths();

// Extra access for the program and the tests: the collapse's figures. (The binary tree it collapsed is not
// kept: the wide tree and its blocks are all the structure holds.)
class wide_accel_base : public accel {
public:
    virtual const collapse_stats& stats() const = 0;
};

// name: the race's row name; builder: the binary tree (ch04::bvh_builder over boxes and centroids).
// Throws std::invalid_argument for a width or block size the course does not build.
std::unique_ptr<wide_accel_base> make_accel(std::string name, ch04::bvh_builder builder, const wide_config& config);

// The same for a builder that needs the triangles themselves (chapter 09's SBVH splits them), not only their
// boxes (ch04::mesh_bvh_builder): builder(mesh) gives the binary tree, whose leaves may reference a triangle
// more than once.
std::unique_ptr<wide_accel_base> make_accel_from_mesh(std::string name, ch04::mesh_bvh_builder builder,
                                                      const wide_config& config);

}  // namespace strahl::ch13
