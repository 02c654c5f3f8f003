// Chapter 08's builders behind the course's accel interface: each builds a binary tree (HLBVH, PLOC) or
// restructures chapter 07's LBVH (TRBVH, ATRBVH), FLATTEN writes chapter 04's nodes, chapter 05's fast
// traversal walks them ("ch08-hlbvh-fast", "ch08-ploc16-fast", "ch08-trbvh-fast", ...). The race and the
// chapter's program take them from variants().
#pragma once
#include "strahl/ch04/accel.hpp"
#include "strahl/ch08/binary_tree.hpp"
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace strahl::ch08 {

// One builder of the chapter: its name ("hlbvh", "ploc16", "trbvh", ...), what it is, and the build from
// boxes and centroids to the flattened tree.
struct variant {
    std::string name, description;
    std::function<ch04::bvh(std::span<const aabb>, std::span<const vec3>)> build;
};
std::vector<variant> variants();

// The race's structure "ch08-NAME-fast".
std::unique_ptr<ch04::bvh_accel_base> make_accel(const variant& v);

}  // namespace strahl::ch08
