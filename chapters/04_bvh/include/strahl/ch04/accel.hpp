// Chapter 04's BVH behind the course's accel interface (common/include/strahl/accel.hpp), over plain
// triangles ("ch04-median", "ch04-spatial") or chapter 01's virtual objects ("ch04-median-virtual",
// "ch04-spatial-virtual"). The race registers them.
#pragma once
#include "strahl/accel.hpp"
#include "strahl/ch04/bvh.hpp"
#include <memory>

namespace strahl::ch04 {

std::unique_ptr<strahl::accel> make_accel(bool virtual_primitives, split_method split = split_method::object_median);

// The same with build parameters, and access to the tree for the program and the tests.
class bvh_accel_base : public strahl::accel {
public:
    virtual const bvh& tree() const = 0;
};
std::unique_ptr<bvh_accel_base> make_bvh_accel(bool virtual_primitives, const bvh_build_params& params = {});

}  // namespace strahl::ch04
