// Exercise 06.2 the best rotation at a node, applied (10 points). Read: A. Kensler, "Tree rotations for
// improving bounding volume hierarchies", IEEE Symposium on Interactive Ray Tracing 2008, section 3.
#include "strahl/ch06/refine.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch06 {

// Evaluate the four rotations at the inner node n (at depth `depth`) and apply the best one if it helps:
//   best = {rotation::none, 0};
//   for each rotation, in enum order (L <-> RL, L <-> RR, R <-> LL, R <-> LR):
//     changed = R for the first two, L for the last two; incoming = n's other child;
//     skip it if changed is a leaf (the rotation cannot be done);
//     skip it if depth + 2 + height(incoming) > max_depth (the incoming subtree moves two levels below n);
//     stays = changed's child that is not taken (RR, RL, LR, LL in that order);
//     delta = C_T * (A(box(incoming) u box(stays)) - A(box(changed))), exercise 06.1's formula (written
//       out here, not called: each exercise is graded on its own);
//     keep it if delta < best.delta (strictly: only a lower cost counts, and the first of equals wins);
//   if best.r is not none, apply it: `leaves` is changed's child that is taken;
//     t.replace_child(n, incoming, leaves); t.replace_child(changed, leaves, incoming);
//     then t.refit(changed) and t.refit(n) (in that order: n's height needs changed's);
//   return best.
rotation_choice apply_best_rotation(refine_tree& t, std::uint32_t n, int depth, int max_depth, float c_traversal) {
    STRAHL_TODO("06.2 best rotation");
}

}  // namespace strahl::ch06
