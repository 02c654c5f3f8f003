// The bounding volume hierarchy's flat form and its top-down builder. The builder sees only boxes and
// centroids (one per primitive), never the primitives themselves.
//   T. L. Kay and J. T. Kajiya, "Ray tracing complex scenes", SIGGRAPH 1986 (bounding volumes, the slabs);
//   J. Goldsmith and J. Salmon, "Automatic creation of object hierarchies for ray tracing", IEEE CG&A 1987;
//   M. Pharr, W. Jakob and G. Humphreys, "Physically Based Rendering", 4th ed. (pbrt-v4), 2023, section 7.3
//   (the median splits, the flattening into a depth-first node array).
#pragma once
#include "strahl/aabb.hpp"
#include <cstdint>
#include <span>
#include <vector>

namespace strahl::ch04 {

// One node in 32 bytes:
//   bytes  0-11: the box's minimum corner (3 floats);
//   bytes 12-23: the box's maximum corner (3 floats);
//   bytes 24-27: offset: a leaf's first entry in prim_ids; an inner node's second (right) child. The first
//                (left) child of an inner node is always the next node: index + 1 (depth-first order);
//   bytes 28-29: count: the leaf's number of primitives (1 or more); 0 marks an inner node;
//   byte  30:    axis: the inner node's split axis (0, 1, 2), which the traversal's near-first order reads;
//   byte  31:    padding. 32 bytes: a node never straddles two 64-byte cache lines where the array
//                starts on one (siblings need not share a line: the right child lies after the left subtree).
struct bvh_node {
    float bmin[3];
    float bmax[3];
    std::uint32_t offset;
    std::uint16_t count;
    std::uint8_t axis;
    std::uint8_t pad;

    bool is_leaf() const { return count > 0; }
    aabb box() const { return {vec3(bmin[0], bmin[1], bmin[2]), vec3(bmax[0], bmax[1], bmax[2])}; }
};
static_assert(sizeof(bvh_node) == 32, "the node layout is 32 bytes");

enum class split_method : std::uint8_t {
    object_median,   // half of the primitives on each side, by centroid, along the centroid box's longest axis
    spatial_median,  // the middle of the centroid box's longest axis (falls back to the object median)
};
const char* to_string(split_method m);

struct bvh_build_params {
    split_method split = split_method::object_median;
    int leaf_size = 4;  // a node with at most this many primitives becomes a leaf (clamped to [1, 255])
};

// Depth bound: below depth spatial_depth_limit the spatial median gives way to the object median, which
// halves every range, so no tree is deeper than spatial_depth_limit + 32 (and the traversal stack fits).
inline constexpr int spatial_depth_limit = 48;
inline constexpr int bvh_max_depth = spatial_depth_limit + 34;

struct bvh_stats {
    std::size_t primitives = 0, inner = 0, leaves = 0, max_leaf = 0;
    int depth = 0;
    double build_ms = 0.0;
};

// Whether a tree can place a primitive: its box and centroid finite, the box not empty. The builders leave
// the others out of the tree ("loose"): every ray tests them.
inline bool fits_in_tree(const aabb& box, const vec3& centroid) {
    return is_finite(box.min) && is_finite(box.max) && is_finite(centroid) && !box.is_empty();
}

struct bvh {
    aabb bounds;                           // the root's box
    std::vector<bvh_node> nodes;           // nodes[0] is the root (absent for an empty tree)
    std::vector<std::uint32_t> prim_ids;   // leaf contents: the primitive ids, partitioned in place by the build
    std::vector<std::uint32_t> loose;      // primitives with a non-finite box: not in the tree, tested by every ray
    bvh_stats stats;

    // Nodes and the index array: known before the build, as N primitives give at most 2N - 1 nodes.
    std::size_t memory_bytes() const { return nodes.size() * sizeof(bvh_node) + prim_ids.size() * 4; }
};

// BUILD-HIERARCHY, top down: primitive i has box boxes[i] and centroid centroids[i].
bvh build_bvh(std::span<const aabb> boxes, std::span<const vec3> centroids, const bvh_build_params& params = {});

// Exercise 04.2 "partition": one step of the build. ids is the node's range of the index array (2 or more
// entries). Chooses the longest axis of the box around the range's centroids and splits there:
//   object median: the entries are reordered in place (std::nth_element, by centroid on the axis, ties by
//     id) so that the first n/2 have centroids no greater than the rest; mid = n / 2;
//   spatial median: the entries are reordered in place (std::partition) so that those with centroid below
//     the middle of the centroid box's axis come first; mid = their number; where that leaves one side
//     empty, the object median's answer instead;
//   all centroids equal (the centroid box is a point): nothing reordered, mid = n / 2 (split in half).
// Returns the axis and mid, with 0 < mid < n always.
struct split_result {
    int axis = 0;
    std::size_t mid = 0;
};
split_result partition_split(std::span<std::uint32_t> ids, std::span<const vec3> centroids, split_method m);

// The SAH cost of the tree (chapter 05 defines and explains it), normalised by the root's area:
//   C_T * sum over inner nodes of A(n)/A(root) + C_I * sum over leaves of N(l) A(l)/A(root).
// Here so that every BVH row in the race, medians included, reports it. 0 for an empty tree; a root of
// area 0 counts every ratio as 1.
double sah_tree_cost(const bvh& tree, float c_traversal, float c_intersection);

// The boxes of the nodes at depths [first_level, last_level] (the root is depth 0), for drawing.
struct level_box {
    int level;
    aabb box;
};
std::vector<level_box> level_boxes(const bvh& tree, int first_level, int last_level);

}  // namespace strahl::ch04
