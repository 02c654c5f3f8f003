// Chapter 03's k-d tree behind the course's accel interface (common/include/strahl/accel.hpp), over
// plain triangles ("ch03-kd") or chapter 01's virtual objects ("ch03-kd-virtual"). The race registers both.
#pragma once
#include "strahl/accel.hpp"
#include "strahl/ch03/kd_tree.hpp"
#include <memory>

namespace strahl::ch03 {

std::unique_ptr<strahl::accel> make_accel(bool virtual_primitives);

// The same with build parameters, and access to the tree for the program and the tests.
class kd_accel_base : public strahl::accel {
public:
    virtual const kd_tree& tree() const = 0;
};
std::unique_ptr<kd_accel_base> make_kd_accel(bool virtual_primitives, const kd_build_params& params = {});

}  // namespace strahl::ch03
