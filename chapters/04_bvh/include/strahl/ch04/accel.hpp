// Chapter 04's BVH behind the course's accel interface (common/include/strahl/accel.hpp), over plain
// triangles ("ch04-median", "ch04-spatial") or chapter 01's virtual objects ("ch04-median-virtual",
// "ch04-spatial-virtual"). The race registers them.
#pragma once
#include "strahl/accel.hpp"
#include "strahl/ch04/bvh.hpp"
#include <functional>
#include <memory>
#include <string>

namespace strahl::ch04 {

std::unique_ptr<strahl::accel> make_accel(bool virtual_primitives, split_method split = split_method::object_median);

// The same with build parameters, and access to the tree for the program and the tests.
class bvh_accel_base : public strahl::accel {
public:
    virtual const bvh& tree() const = 0;
};
std::unique_ptr<bvh_accel_base> make_bvh_accel(bool virtual_primitives, const bvh_build_params& params = {});

// Any builder that turns boxes and centroids into this flat tree (chapters 05 and 06 bring theirs), behind
// the same traversal: name is the race's row name, "-virtual" is appended for the virtual objects.
using bvh_builder = std::function<bvh(std::span<const aabb> boxes, std::span<const vec3> centroids)>;
std::unique_ptr<bvh_accel_base> make_bvh_accel(bool virtual_primitives, std::string name, bvh_builder builder);

// A builder that needs the triangles themselves, not only their boxes (chapter 09's SBVH splits them):
// builder(mesh) gives the tree, whose leaves may reference a triangle more than once. bvh_accel_t
// (bvh_accel.hpp) takes one over plain triangles; chapter 13 collapses its tree into wide nodes.
using mesh_bvh_builder = std::function<bvh(const triangle_mesh& mesh)>;

}  // namespace strahl::ch04
