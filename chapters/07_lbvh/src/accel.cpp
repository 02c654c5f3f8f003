// Chapter 07's builder behind chapter 04's BVH accel, walked by chapter 05's fast traversal.
#include "strahl/ch07/accel.hpp"
#include "strahl/ch05/accel.hpp"

namespace strahl::ch07 {

std::unique_ptr<ch04::bvh_accel_base> make_accel(const lbvh_params& params) {
    return ch05::make_bvh_accel(false, "ch07-" + to_string(params) + "-fast",
                                [params](std::span<const aabb> b, std::span<const vec3> c) { return build_lbvh(b, c, params); },
                                ch05::walk_kind::fast);
}

}  // namespace strahl::ch07
