// Chapter 05's SAH BVHs behind the course's accel interface: chapter 04's flat tree, built by
// build_sah_bvh, over plain triangles or chapter 01's virtual objects, walked either by chapter 04's
// traversal ("ch05-sweep", "ch05-binned16", ... : only the tree differs from chapter 04's rows) or by
// fast_traverse.hpp's ("ch05-binned16-fast"). The race registers them.
#pragma once
#include "strahl/ch04/accel.hpp"
#include "strahl/ch05/sah.hpp"

namespace strahl::ch05 {

enum class walk_kind { chapter04, fast };

std::unique_ptr<ch04::bvh_accel_base> make_accel(bool virtual_primitives, const sah_build_params& params = {},
                                                 walk_kind walk = walk_kind::chapter04);

// Chapter 04's accel over the trees `builder` builds, named `name`, walked by chapter 04's traversal or by
// the fast one (for later chapters' trees: chapter 06's refined trees, walked fast).
std::unique_ptr<ch04::bvh_accel_base> make_bvh_accel(bool virtual_primitives, std::string name,
                                                     ch04::bvh_builder builder, walk_kind walk);

}  // namespace strahl::ch05
