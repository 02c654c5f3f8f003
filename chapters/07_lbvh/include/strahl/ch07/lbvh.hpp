// The linear BVH (LBVH): sort the primitives along the Morton curve, read the hierarchy off the sorted
// codes' bits, fit the boxes bottom up, collapse small subtrees into leaves by the SAH. Every phase is a
// linear pass or a sort, and all but the last run in parallel. The tree is chapter 04's flat 32-byte node
// array, so chapter 05's fast traversal walks it unchanged.
//   C. Lauterbach, M. Garland, S. Sengupta, D. Luebke and D. Manocha, "Fast BVH construction on GPUs",
//   Eurographics 2009 (the LBVH);
//   T. Karras, "Maximizing parallelism in the construction of BVHs, octrees, and k-d trees", HPG 2012
//   (inner nodes in parallel, boxes bottom up with one atomic counter per node).
// The builder sees only boxes and centroids, as chapters 04 and 05's do.
#pragma once
#include "strahl/ch04/bvh.hpp"
#include "strahl/ch05/sah.hpp"
#include "strahl/ch07/radix_tree.hpp"
#include "strahl/scene.hpp"
#include <span>
#include <string>
#include <vector>

namespace strahl::ch07 {

enum class hierarchy_method : std::uint8_t {
    lecture,  // top down, binary search for the highest differing bit ("lbvh" in the race's names)
    karras,   // every inner node in parallel (Karras 2012)
};

struct lbvh_params {
    int bits_per_axis = 10;  // 10 (30-bit codes) or 21 (63-bit codes)
    hierarchy_method hierarchy = hierarchy_method::lecture;
    bool use_pdep = false;   // the codes by BMI2's pdep where available (morton.hpp), else by shifts
    // The collapse: a subtree of at most max_leaf primitives becomes one leaf where the SAH prices it
    // lower as a leaf (C_I * N * A) than as it stands (C_T * A + its children's costs). Chapter 05's
    // constants, C_T = C_I = 1 by default; max_leaf 4 (clamped to [1, 255]): the radix tree's leaves are
    // single primitives, and a small bound keeps Morton-order mistakes (far-apart neighbours) in small
    // leaves.
    ch05::sah_costs costs;
    int max_leaf = 4;
    // No leaf deeper than this (the traversal's stack). A radix tree is as deep as its codes have distinct
    // prefixes: up to 63 bits plus 32 index bits. Where a subtree would reach below it, that subtree is
    // rebuilt from depth max_depth - 32 down by halving its range (32 halvings split any range to single
    // primitives). Clamped to [33, ch04::bvh_max_depth]; lower than the default only for the tests.
    int max_depth = ch04::bvh_max_depth;
};
std::string to_string(const lbvh_params& p);  // "lbvh30", "karras63", ...
// The four builders the chapter compares: both hierarchy forms with 30- and 63-bit codes, default otherwise.
std::vector<lbvh_params> lbvh_variants();

// What every builder sees: one box and one centroid per triangle of the mesh (as chapter 04's accel hands
// them over).
struct builder_inputs {
    std::vector<aabb> boxes;
    std::vector<vec3> centroids;
    explicit builder_inputs(const triangle_mesh& mesh);
};

// Milliseconds per phase, and what the codes did, for the chapter's program.
struct lbvh_report {
    double codes_ms = 0, sort_ms = 0, hierarchy_ms = 0, boxes_ms = 0, collapse_ms = 0;
    std::size_t duplicate_codes = 0;  // sorted codes equal to their predecessor (counted after the timing)
    std::size_t rebalanced = 0;       // subtrees rebuilt by halving to respect max_depth
};

// BUILD-LBVH: codes (morton.hpp), radix sort (radix_sort.hpp), hierarchy (radix_tree.hpp), boxes,
// collapse into the flat tree. stats.build_ms covers all five phases.
ch04::bvh build_lbvh(std::span<const aabb> boxes, std::span<const vec3> centroids, const lbvh_params& params = {},
                     lbvh_report* report = nullptr);

// The boxes phase: the box of every inner node, bottom up in parallel. A thread per leaf climbs towards
// the root; at each inner node an atomic counter says whether its other child is done: the first to
// arrive stops there, the second unites the two children's boxes and climbs on. leaf_boxes[k]: leaf k's box
// (the box of the k-th primitive in sorted order).
std::vector<aabb> fit_boxes(const radix_tree& tree, std::span<const aabb> leaf_boxes);

}  // namespace strahl::ch07
