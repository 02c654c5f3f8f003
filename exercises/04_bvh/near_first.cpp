// Exercise 04.3 near child first (5 points). Read: M. Pharr, W. Jakob and G. Humphreys, pbrt-v4, 2023,
// section 7.3.5 (the ordered traversal of the flattened BVH).
#include "strahl/ch04/traverse.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch04 {

// The inner node `node` sits at nodes[index]. Its left child is nodes[index + 1] (depth-first layout), its
// right child nodes[node.offset]. Return {near, far}: the left child first when dir[node.axis] has its sign
// bit clear (+0 included), the right one first when it is set (-0 included; std::signbit).
child_order ordered_children(std::uint32_t index, const bvh_node& node, const vec3& dir) {
    STRAHL_TODO("04.3 near child first");
}

}  // namespace strahl::ch04
