// Chapter 04's BVH behind the course's accel interface, generic over the primitive set: the build sees
// only the set's boxes and centroids, the traversal (traverse.hpp) is handed the set's leaf test.
// (Kay and Kajiya 1986; Goldsmith and Salmon 1987; pbrt-v4, section 7.3.)
#include "strahl/ch04/accel.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch04/traverse.hpp"
#include <cmath>

namespace strahl::ch04 {

namespace {

template <class Set>
class bvh_accel_t final : public per_ray_accel<bvh_accel_t<Set>, bvh_accel_base> {
public:
    bvh_accel_t(bool is_virtual, const bvh_build_params& p) : virtual_(is_virtual), params_(p) {}

    std::string name() const override {
        return std::string("ch04-") + to_string(params_.split) + (virtual_ ? "-virtual" : "");
    }
    const bvh& tree() const override { return tree_; }

    void build(const scene& s) override {
        set_ = std::make_unique<Set>(s.mesh);
        std::vector<aabb> boxes(set_->size());
        std::vector<vec3> centroids(set_->size());
        for (std::size_t i = 0; i < boxes.size(); ++i) boxes[i] = set_->bounds(i), centroids[i] = boxes[i].centroid();
        tree_ = build_bvh(boxes, centroids, params_);
    }

    std::size_t memory_bytes() const override {
        return tree_.memory_bytes() + tree_.loose.size() * 4 + (set_ ? set_->memory_bytes() : 0);
    }

    // The per-ray queries (per_ray_accel turns them into batches): tree_query.hpp's closest and any hit,
    // handed this tree's traversal; its leaves are ranges of the reference array.
    template <class Stats>
    hit closest(const ray& query, Stats& stats) const {
        if (!set_) return hit{};
        return tree_closest(*set_, tree_.loose, query, stats, [&](ray& r, auto&& leaf) { walk(r, stats, leaf); });
    }
    template <class Stats>
    bool any(const ray& query, Stats& stats) const {
        if (!set_) return false;
        return tree_any(*set_, tree_.loose, query, stats, [&](ray& r, auto&& leaf) { walk(r, stats, leaf); });
    }

private:
    template <class Stats, class Leaf>
    void walk(ray& r, Stats& stats, Leaf& leaf) const {
        traverse(tree_, r, stats, [&](std::uint32_t first, std::uint32_t count) {
            return leaf(tree_.prim_ids.data() + first, count);
        });
    }

    bool virtual_;
    bvh_build_params params_;
    std::unique_ptr<Set> set_;
    bvh tree_;
};

}  // namespace

std::unique_ptr<bvh_accel_base> make_bvh_accel(bool virtual_primitives, const bvh_build_params& params) {
    if (virtual_primitives) return std::make_unique<bvh_accel_t<ch01::object_set>>(true, params);
    return std::make_unique<bvh_accel_t<ch01::triangle_set>>(false, params);
}

std::unique_ptr<strahl::accel> make_accel(bool virtual_primitives, split_method split) {
    bvh_build_params p;
    p.split = split;
    return make_bvh_accel(virtual_primitives, p);
}

}  // namespace strahl::ch04
