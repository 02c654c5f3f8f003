// Chapter 06's refined BVHs behind the course's accel interface: a start tree (chapter 04's object median
// or chapter 05's binned SAH with 16 bins) refined by rotations or reinsertion, then chapter 04's flat
// nodes and traversal (or chapter 05's fast traversal: "-fast"), over plain triangles ("ch06-median-rotated",
// "ch06-binned16-reinserted", ...) or chapter 01's virtual objects. The race registers them.
#pragma once
#include "strahl/ch04/accel.hpp"
#include "strahl/ch05/accel.hpp"
#include "strahl/ch06/refine.hpp"
#include <memory>

namespace strahl::ch06 {

// The start tree's builder, then refine(tree, params); name "ch06-<start>-<rotated|reinserted>".
ch04::bvh build_refined_bvh(std::span<const aabb> boxes, std::span<const vec3> centroids, const refine_params& params);
// walk: chapter 04's traversal, or chapter 05's fast one (the name then ends in "-fast").
std::unique_ptr<ch04::bvh_accel_base> make_accel(bool virtual_primitives, const refine_params& params = {},
                                                 ch05::walk_kind walk = ch05::walk_kind::chapter04);

}  // namespace strahl::ch06
