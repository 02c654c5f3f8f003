// The surface area heuristic (SAH): the expected cost of a tree for rays that are uniformly distributed
// over directions and positions, and the two top-down builders that minimise it greedily, one split at a
// time: the full sweep over sorted centroids, and binning.
//   J. Goldsmith and J. Salmon, "Automatic creation of object hierarchies for ray tracing", IEEE CG&A 1987;
//   J. D. MacDonald and K. S. Booth, "Heuristics for ray tracing using space subdivision", The Visual
//   Computer 6(3), 1990 (the cost model);
//   I. Wald, "On fast construction of SAH-based bounding volume hierarchies", IEEE Symposium on
//   Interactive Ray Tracing 2007 (binning: k bins over the centroid box, one pass, prefix/suffix sweeps).
// Both builders see only boxes and centroids, and write chapter 04's flat tree (32-byte nodes), which
// chapter 04's traversal walks unchanged.
#pragma once
#include "strahl/ch04/bvh.hpp"
#include <cstdint>
#include <limits>
#include <span>
#include <string>

namespace strahl::ch05 {

// The cost model's two constants, in the same (arbitrary) unit:
//   C_T: the cost of one traversal step (visiting a node: its box test);
//   C_I: the cost of one primitive intersection test.
// Only their ratio matters for the shape of the tree; C_T = C_I = 1 is the default (on this course's
// triangle test a node visit and a triangle test cost about the same; the chapter measures the ratio).
struct sah_costs {
    float traversal = 1.0f;     // C_T
    float intersection = 1.0f;  // C_I
};

// Exercise 05.1 "SAH cost of a split": the expected cost of splitting a node P with surface area
// area_parent (> 0) into children L and R holding n_left and n_right primitives, the children taken as
// leaves (the lecture's equation):
//   C = C_T + C_I * (A(L) / A(P) * N_L + A(R) / A(P) * N_R)
// A(L) / A(P) is the probability that a ray meeting P also meets L.
float split_cost(const sah_costs& c, float area_parent, float area_left, std::size_t n_left, float area_right,
                 std::size_t n_right);

// The cost of a leaf with n primitives: C_I * n. A node becomes a leaf when this is no more than the best
// split's cost (the SAH's termination rule) and n is no more than the build's max_leaf.
inline float leaf_cost(const sah_costs& c, std::size_t n) { return c.intersection * float(n); }

// The SAH cost of a whole built tree, normalised by the root's area (the tree's expected cost per ray
// that meets the root box):
//   C(T) = C_T * sum over inner nodes n of A(n)/A(root) + C_I * sum over leaves l of N(l) * A(l)/A(root).
// An empty tree costs 0; a root of area 0 (all primitives in one point) counts every ratio as 1.
double tree_cost(const ch04::bvh& tree, const sah_costs& c = {});

// ---- Binning ----

// k bins of equal width over the centroid box's extent [lo, hi] on one axis (hi > lo):
// scale = k / (hi - lo), so bin b covers [lo + b / scale, lo + (b + 1) / scale).
struct bin_mapping {
    float lo = 0.0f;
    float scale = 1.0f;
    int k = 1;
};
inline bin_mapping make_bin_mapping(float lo, float hi, int k) { return {lo, float(k) / (hi - lo), k}; }

// Exercise 05.2 "bin assignment": the bin of centroid coordinate c: int(scale * (c - lo)), clamped to
// [0, k - 1]. The clamp matters at the top: c == hi maps to k (one past the last bin), and rounding in
// scale * (c - lo) can give k for c just below hi; both belong to bin k - 1. Clamp the float before
// converting it (a float outside int's range, or NaN, has no defined conversion): NaN goes to bin 0.
// The same function decides the binning and the partition, so the two always agree.
int bin_index(const bin_mapping& m, float c);

// One bin: the box around the boxes (not the centroids) of the primitives it holds, and their number.
struct bin {
    aabb box;
    std::uint32_t count = 0;
};

// A boundary between bins: index b puts bins [0, b) on the left and [b, k) on the right (0 < b < k).
// index 0 with cost +inf: no boundary leaves both sides non-empty.
struct bin_split {
    int index = 0;
    float cost = std::numeric_limits<float>::infinity();
};

// Exercise 05.3 "prefix and suffix sweeps": the boundary with the lowest SAH cost (exercise 05.1's formula)
// over bins (k >= 1 of them), in two linear sweeps instead of k - 1 separate unions:
//   the suffix sweep, right to left: grow a box and a count over bins k-1 .. b, and store the box's area
//     in right_area[b] (right_area holds at least k floats; it is scratch) and the count as you need it;
//   the prefix sweep, left to right: grow a box and a count over bins 0 .. b-1, and at each boundary b
//     evaluate C_T + C_I * (A(L) N_L + A(R) N_R) / area_parent.
// Boundaries with an empty side (N_L == 0 or N_R == 0) are skipped; among equal costs the lowest index
// wins. The full sweep is the same sweep with one primitive per "bin", in sorted centroid order.
bin_split best_boundary(std::span<const bin> bins, std::span<float> right_area, const sah_costs& c,
                        float area_parent);

// ---- The builders ----

enum class sah_method : std::uint8_t {
    sweep,   // every boundary between sorted centroids, on all three axes: O(N log^2 N), the best greedy SAH
    binned,  // k bins per axis over the centroid box (Wald 2007): O(N log N) with a small constant
};

struct sah_build_params {
    sah_method method = sah_method::binned;
    int bins = 16;       // binned only: k, clamped to [2, 256]
    sah_costs costs;     // C_T and C_I for the splits and the termination
    int max_leaf = 8;    // never a leaf with more primitives than this (clamped to [1, 255]) ...
                         // ... unless no split exists: all centroids in one point, where the range is halved
};
std::string to_string(const sah_build_params& p);  // "sweep", "binned16", ...

// The top-down SAH build. Per node: the node's box; the best split (sweep or bins, all three axes); a leaf
// if C_I * N <= that split's cost and N <= max_leaf (or N == 1); otherwise the in-place partition of the
// index array at the split and the two halves, left first. The nodes are written straight into the flat
// depth-first array (no pointer form). Below depth ch04::spatial_depth_limit the object median takes over,
// so the depth stays within ch04::bvh_max_depth whatever the input.
ch04::bvh build_sah_bvh(std::span<const aabb> boxes, std::span<const vec3> centroids,
                        const sah_build_params& params = {});

// The binned build engineered for speed (fast_build.cpp): the same tree as build_sah_bvh with
// sah_method::binned, node for node, built with exercises 05.2 and 05.3 inlined and all three axes binned
// at once in SIMD. Given sah_method::sweep it calls build_sah_bvh.
ch04::bvh build_sah_bvh_fast(std::span<const aabb> boxes, std::span<const vec3> centroids,
                             const sah_build_params& params = {});

}  // namespace strahl::ch05
