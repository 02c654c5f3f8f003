// Exercise 10.2 refit (6 points). Read: refit.hpp; Wald, Boulos and Shirley 2007, section 4.
#include "strahl/ch10/refit.hpp"

namespace strahl::ch10 {

void refit(ch04::bvh& tree, std::span<const aabb> boxes) {
    // Last node first: in the depth-first array both children of node i lie after i.
    for (std::size_t i = tree.nodes.size(); i-- > 0;) {
        ch04::bvh_node& n = tree.nodes[i];
        aabb box;
        if (n.is_leaf()) {
            for (std::uint32_t k = 0; k < n.count; ++k) box.grow(boxes[tree.prim_ids[n.offset + k]]);
        } else {
            box = unite(tree.nodes[i + 1].box(), tree.nodes[n.offset].box());
        }
        for (int a = 0; a < 3; ++a) n.bmin[a] = box.min[a], n.bmax[a] = box.max[a];
    }
    tree.bounds = tree.nodes.empty() ? aabb() : tree.nodes[0].box();
}

}  // namespace strahl::ch10
