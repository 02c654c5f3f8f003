// Chapter 06's refined trees behind chapter 04's BVH accel: only the builder changes (the start tree's
// builder, then refine); nodes, traversal and leaf tests are chapter 04's.
//   A. Kensler, IEEE Symposium on Interactive Ray Tracing 2008 (rotations);
//   J. Bittner, M. Hapala and V. Havran, Computer Graphics Forum 2013 (reinsertion).
#include "strahl/ch06/accel.hpp"
#include "strahl/timer.hpp"
#include <string>

namespace strahl::ch06 {

ch04::bvh build_refined_bvh(std::span<const aabb> boxes, std::span<const vec3> centroids, const refine_params& params) {
    const timer clock;
    ch04::bvh t = params.start == start_tree::median ? ch04::build_bvh(boxes, centroids)
                                                     : ch05::build_sah_bvh(boxes, centroids);
    refine(t, params);
    t.stats.build_ms = clock.milliseconds();  // the whole build: start tree and refinement
    return t;
}

std::unique_ptr<ch04::bvh_accel_base> make_accel(bool virtual_primitives, const refine_params& params,
                                                 ch05::walk_kind walk) {
    const std::string name = std::string("ch06-") + to_string(params.start) + "-" + to_string(params.method) +
                             (walk == ch05::walk_kind::fast ? "-fast" : "");
    return ch05::make_bvh_accel(virtual_primitives, name, [params](std::span<const aabb> b, std::span<const vec3> c) {
        return build_refined_bvh(b, c, params);
    }, walk);
}

}  // namespace strahl::ch06
