// Chapter 07's LBVH behind the course's accel interface: chapter 04's flat tree built by build_lbvh, over
// plain triangles, walked by chapter 05's fast traversal ("ch07-lbvh30-fast", "ch07-karras63-fast", ...).
// The race registers them.
#pragma once
#include "strahl/ch04/accel.hpp"
#include "strahl/ch07/lbvh.hpp"
#include <memory>

namespace strahl::ch07 {

std::unique_ptr<ch04::bvh_accel_base> make_accel(const lbvh_params& params = {});

}  // namespace strahl::ch07
