// The split bounding volume hierarchy (SBVH): chapter 05's top-down binned SAH build, where a node's
// children may also be cut by a plane through space (a spatial split, as a k-d tree's) instead of by the
// list of its primitives (an object split). A triangle that crosses the plane is then referenced by both
// children, each with the box of its own part: the children's boxes no longer overlap, at the price of
// more references. The tree is chapter 04's flat one; prim_ids may hold a triangle several times (once
// per leaf its parts reach), which the course's closest-hit rule (nearer t, then lower id) makes harmless.
//   M. Stich, H. Friedrich and A. Dietrich, "Spatial splits in bounding volume hierarchies", HPG 2009
//   (the algorithm: object split, overlap test, chopped binning, reference unsplitting);
//   V. Havran, "Heuristic ray shooting algorithms", PhD thesis, 2000 (spatial splits by the SAH: k-d trees);
//   E. Popov, J. Guenther, H.-P. Seidel and P. Slusallek, "Object partitioning considered harmful: space
//   subdivision for BVHs", HPG 2009 (the same idea, the same year).
#pragma once
#include "strahl/ch04/bvh.hpp"
#include "strahl/ch05/sah.hpp"
#include "strahl/scene.hpp"
#include <string>

namespace strahl::ch09 {

struct sbvh_params {
    // The overlap threshold alpha: a node tries a spatial split only where its best object split's
    // children overlap in a box of surface area more than alpha times the root's,
    //   lambda = A(L intersect R) / A(root) > alpha.
    // alpha = 1: never (chapter 05's binned tree); alpha = 0: wherever the children overlap at all. The
    // paper's choice, 1e-5, tries spatial splits high in the tree and rarely deep down.
    float alpha = 1e-5f;
    int object_bins = 16;   // k of the object split's binning (chapter 05's; nodes of at most k are swept exactly)
    int spatial_bins = 16;  // k of chopped binning over the node's box, on every axis; clamped to [2, 256]
    // The reference budget: at most budget * (the triangles in the tree) references in all, so that the
    // index array (4 bytes each) and the nodes (at most 2 per reference, 32 bytes each) are known before
    // the build. Spatial splits stop, and unsplitting takes over, when it is spent. At least 1.
    float budget = 1.5f;
    bool unsplit = true;    // reference unsplitting (the paper's section 4.5); false: every straddler splits
    ch05::sah_costs costs;  // C_T and C_I, as chapter 05's
    int max_leaf = 8;       // as chapter 05's: a leaf holds at most this many references (clamped to [1, 255])
};
std::string to_string(const sbvh_params& p);  // "sbvh", or "sbvh-a1e-3-b2" where alpha or budget differ

// What a build did, for the program and the tests.
struct sbvh_report {
    std::size_t triangles = 0;      // in the tree (loose ones excluded)
    std::size_t references = 0;     // in the leaves: prim_ids.size()
    std::size_t budget = 0;         // the most references the budget allowed
    std::size_t spatial_splits = 0, object_splits = 0, median_splits = 0;
    std::size_t spatial_tried = 0;  // nodes whose overlap was above alpha (chopped binning ran)
    std::size_t unsplit = 0;        // straddling references put wholly on one side instead of split
};

// BUILD-SBVH, top down from the root's references (one per triangle whose box fits in a tree; the others go
// to `loose`, as chapter 04's), per node:
//   STEP 1, object split: chapter 05's best binned (or, up to object_bins references, swept) SAH split of
//     the references by their boxes' centroids;
//   STEP 2, overlap: lambda = A(L intersect R) / A(root) of that split's children;
//   STEP 3, spatial split, where lambda > alpha and the budget allows: chopped binning (exercise 09.2)
//     on each axis over the node's box, the triangles clipped by exercise 09.1, and a sweep for the best
//     boundary (spatial_split.hpp);
//   STEP 4, the cheaper split, or a leaf (chapter 05's termination: C_I N no more than the split's cost,
//     N <= max_leaf);
//   STEP 5, distribute: object split by bins; spatial split per reference: wholly left, wholly right, or
//     straddling: split into its two clipped parts, or (unsplitting) put wholly on the side where that
//     costs less than splitting it;
//   STEP 6, children, left first, into chapter 04's flat depth-first array.
// Below depth ch04::spatial_depth_limit only object medians (which halve): the depth stays within
// ch04::bvh_max_depth whatever the input.
ch04::bvh build_sbvh(const triangle_mesh& mesh, const sbvh_params& params = {}, sbvh_report* report = nullptr);

}  // namespace strahl::ch09
