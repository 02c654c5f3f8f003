// REFINE: a built flat BVH into the index form, ROTATE passes or REINSERT iterations until a fixed point
// or the iteration budget, and back into chapter 04's flat nodes.
//   A. Kensler, "Tree rotations for improving bounding volume hierarchies", IEEE Symposium on Interactive
//   Ray Tracing 2008;
//   J. Bittner, M. Hapala and V. Havran, "Fast insertion-based optimization of bounding volume
//   hierarchies", Computer Graphics Forum 32(1), 2013.
// Steps: 1. UNFLATTEN; 2. iterate (a pass of rotations or a batch of reinsertions) to a fixed point or the
// budget; 3. FLATTEN; 4. KEEP the result only if its SAH cost is not higher (a safety net:
// every move lowers the cost, but the sums are rounded).
#include "strahl/ch06/refine.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <cmath>

namespace strahl::ch06 {

refine_stats refine(ch04::bvh& tree, const refine_params& params) {
    refine_stats s;
    s.before = s.after = ch05::tree_cost(tree, params.costs);
    if (tree.nodes.size() < 3) return s;  // an empty tree, a leaf, or a root with two leaves: nothing to move
    const timer clock;
    // Step 1, UNFLATTEN.
    refine_tree t = to_refine_tree(tree);
    std::size_t inner = 0;
    for (const refine_node& n : t.nodes) inner += n.is_leaf() ? 0 : 1;
    const auto batch = std::max<std::size_t>(1, std::size_t(std::ceil(double(params.batch_fraction) * double(inner))));
    // Step 2, iterate to a fixed point (a rotation pass, or a whole round of reinsertion batches, that
    // moves nothing) or the budget.
    std::vector<std::uint8_t> tried;
    std::size_t round_moves = 0;
    for (int i = 0; i < params.max_iterations; ++i) {
        ++s.iterations;
        if (params.method == refine_method::rotations) {
            const std::size_t moves = rotation_pass(t, params.costs.traversal, params.max_depth);
            s.moves += moves;
            if (moves == 0) break;
        } else {
            const reinsertion_result r = reinsertion_pass(t, batch, params.max_depth, tried);
            s.moves += r.moves;
            round_moves += r.moves;
            if (r.round_over) {
                if (round_moves == 0) break;
                round_moves = 0;
            }
        }
    }
    // Step 3, FLATTEN.
    ch04::bvh out = to_bvh(t, tree);
    s.ms = clock.milliseconds();
    // Step 4, KEEP it unless it came out worse.
    const double after = ch05::tree_cost(out, params.costs);
    if (after <= s.before) {
        tree = std::move(out);
        s.after = after;
    }
    return s;
}

}  // namespace strahl::ch06
