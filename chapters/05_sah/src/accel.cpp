// Chapter 05's builders behind chapter 04's BVH accel: the builder changes, and optionally the traversal;
// nodes and leaf tests are chapter 04's.
#include "strahl/ch05/accel.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch04/bvh_accel.hpp"
#include "strahl/ch05/fast_traverse.hpp"

namespace strahl::ch05 {

std::unique_ptr<ch04::bvh_accel_base> make_bvh_accel(bool virtual_primitives, std::string name,
                                                     ch04::bvh_builder builder, walk_kind walk) {
    if (walk == walk_kind::chapter04) return ch04::make_bvh_accel(virtual_primitives, std::move(name), std::move(builder));
    if (virtual_primitives)
        return std::make_unique<ch04::bvh_accel_t<ch01::object_set, fast_walk>>(true, std::move(name), std::move(builder));
    return std::make_unique<ch04::bvh_accel_t<ch01::triangle_set, fast_walk>>(false, std::move(name), std::move(builder));
}

std::unique_ptr<ch04::bvh_accel_base> make_accel(bool virtual_primitives, const sah_build_params& params,
                                                 walk_kind walk) {
    const std::string name = "ch05-" + to_string(params);
    if (walk == walk_kind::chapter04)
        return make_bvh_accel(virtual_primitives, name, [params](std::span<const aabb> b, std::span<const vec3> c) {
            return build_sah_bvh(b, c, params);
        }, walk);
    // The fast row: the same tree from the fast builder, walked by the fast traversal.
    return make_bvh_accel(virtual_primitives, name + "-fast", [params](std::span<const aabb> b, std::span<const vec3> c) {
        return build_sah_bvh_fast(b, c, params);
    }, walk);
}

}  // namespace strahl::ch05
