// Chapter 04's BVH behind the course's accel interface, generic over the primitive set: the build sees
// only the set's boxes and centroids, the traversal (traverse.hpp) is handed the set's leaf test.
// (Kay and Kajiya 1986; Goldsmith and Salmon 1987; pbrt-v4, section 7.3.)
#include "strahl/ch04/accel.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch04/bvh_accel.hpp"
#include "strahl/ch04/traverse.hpp"

namespace strahl::ch04 {

namespace {

// Chapter 04's traversal as bvh_accel_t's Walk.
struct near_first_walk {
    template <class Stats, class Leaf>
    void operator()(const bvh& tree, ray& r, Stats& stats, Leaf&& leaf) const {
        traverse(tree, r, stats, leaf);
    }
};

}  // namespace

std::unique_ptr<bvh_accel_base> make_bvh_accel(bool virtual_primitives, std::string name, bvh_builder builder) {
    if (virtual_primitives)
        return std::make_unique<bvh_accel_t<ch01::object_set, near_first_walk>>(true, std::move(name), std::move(builder));
    return std::make_unique<bvh_accel_t<ch01::triangle_set, near_first_walk>>(false, std::move(name), std::move(builder));
}

std::unique_ptr<bvh_accel_base> make_bvh_accel(bool virtual_primitives, const bvh_build_params& params) {
    return make_bvh_accel(virtual_primitives, std::string("ch04-") + to_string(params.split),
                          [params](std::span<const aabb> b, std::span<const vec3> c) { return build_bvh(b, c, params); });
}

std::unique_ptr<strahl::accel> make_accel(bool virtual_primitives, split_method split) {
    bvh_build_params p;
    p.split = split;
    return make_bvh_accel(virtual_primitives, p);
}

}  // namespace strahl::ch04
