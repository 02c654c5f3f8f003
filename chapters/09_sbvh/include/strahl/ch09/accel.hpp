// Chapter 09's SBVH behind the course's accel interface: chapter 04's flat tree built by build_sbvh, which
// needs the triangles themselves (not only their boxes, as chapter 04's bvh_builder gets), walked by
// chapter 05's fast traversal over plain triangles ("ch09-sbvh-fast"). The race registers it.
#pragma once
#include "strahl/ch04/accel.hpp"
#include "strahl/ch09/sbvh.hpp"
#include <memory>

namespace strahl::ch09 {

class sbvh_accel_base : public ch04::bvh_accel_base {
public:
    virtual const sbvh_report& report() const = 0;  // what the last build did
};

// name: the race's row name; empty: "ch09-" + to_string(params) + "-fast".
std::unique_ptr<sbvh_accel_base> make_accel(const sbvh_params& params = {}, std::string name = "");

}  // namespace strahl::ch09
