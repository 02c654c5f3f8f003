// The wide BVH behind the accel interface (accel.hpp): per ray, tree_query.hpp's rules (loose primitives,
// rays no tree can place), then the wide walk with the block test at its leaves.
//
// Included once, at the end of traversal.cpp (exercises 13.2 and 13.3), so that the walk is compiled in the
// same translation unit as the student's node test and ordered push, and inlines them.
#pragma once
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch13/accel.hpp"
#include "strahl/ch13/block_test.hpp"
#include "strahl/ch13/wide_traverse.hpp"
#include "strahl/tree_query.hpp"
#include <stdexcept>

namespace strahl::ch13 {

namespace {

template <int N, int M>
class wide_accel final : public per_ray_accel<wide_accel<N, M>, wide_accel_base> {
public:
    wide_accel(std::string name, ch04::bvh_builder builder, const wide_config& c)
        : name_(std::move(name)), builder_(std::move(builder)), config_(c.collapse), any_nearest_(c.any_hit_nearest) {}

    std::string name() const override { return name_; }
    const collapse_stats& stats() const override { return tree_.stats; }
    const ch04::bvh& binary_tree() const override { return binary_; }

    void build(const scene& s) override {
        set_ = std::make_unique<ch01::triangle_set>(s.mesh);
        std::vector<aabb> boxes(set_->size());
        std::vector<vec3> centroids(set_->size());
        for (std::size_t i = 0; i < boxes.size(); ++i) boxes[i] = set_->bounds(i), centroids[i] = boxes[i].centroid();
        binary_ = builder_(boxes, centroids);
        tree_ = collapse<N, M>(binary_, s.mesh, config_);
    }
    std::optional<double> sah_cost() const override {
        if (!set_) return std::nullopt;
        return tree_.stats.sah;
    }
    // The wide tree and its blocks; the triangle set is kept for loose primitives and unplaceable rays.
    std::size_t memory_bytes() const override { return tree_.memory_bytes() + (set_ ? set_->memory_bytes() : 0); }

    // tree_query.hpp's rules (loose primitives, rays no tree can place) around the wide walk.
    template <class Stats>
    hit closest(const ray& query, Stats& stats) const {
        if (!set_) return hit{};
        return tree_closest_with(*set_, tree_.loose, query, stats, [&](ray& r, hit& best) {
            const ray_lanes<M> lanes(r);
            wide_traverse<visit_order::nearest>(tree_, r, stats, [&](std::uint32_t ref) {
                const triangle_block<M>* b = &tree_.blocks[leaf_first(ref)];
                for (std::uint32_t k = leaf_blocks(ref); k-- > 0; ++b) {
                    stats.prim_test(M);
                    simd::vfloat<M> t, u, v;
                    unsigned bits = simd::movemask(intersect_block(*b, lanes, r.tmin, r.tmax, t, u, v));
                    if (bits == 0) continue;
                    alignas(64) float ts[M], us[M], vs[M];
                    t.store(ts), u.store(us), v.store(vs);
                    for (; bits != 0; bits &= bits - 1) {
                        const int i = std::countr_zero(bits);
                        ch01::record_closest(b->id[i], ts[i], us[i], vs[i], r, best);
                    }
                }
                return false;
            });
        });
    }

    template <class Stats>
    bool any(const ray& query, Stats& stats) const {
        if (!set_) return false;
        return tree_any_with(*set_, tree_.loose, query, stats, [&](ray& r) {
            const ray_lanes<M> lanes(r);
            bool found = false;
            const auto leaf = [&](std::uint32_t ref) {
                const triangle_block<M>* b = &tree_.blocks[leaf_first(ref)];
                for (std::uint32_t k = leaf_blocks(ref); k-- > 0 && !found; ++b) {
                    stats.prim_test(M);
                    simd::vfloat<M> t, u, v;
                    found = simd::any(intersect_block(*b, lanes, r.tmin, r.tmax, t, u, v));
                }
                return found;
            };
            if (any_nearest_) wide_traverse<visit_order::nearest>(tree_, r, stats, leaf);
            else wide_traverse<visit_order::stored>(tree_, r, stats, leaf);
            return found;
        });
    }

private:
    std::string name_;
    ch04::bvh_builder builder_;
    collapse_config config_;
    bool any_nearest_ = false;
    std::unique_ptr<ch01::triangle_set> set_;
    ch04::bvh binary_;
    wide_bvh<N, M> tree_;
};

}  // namespace

std::unique_ptr<wide_accel_base> make_accel(std::string name, ch04::bvh_builder builder, const wide_config& c) {
    const int key = c.width * 100 + c.block;
    switch (key) {
    case 404: return std::make_unique<wide_accel<4, 4>>(std::move(name), std::move(builder), c);
    case 804: return std::make_unique<wide_accel<8, 4>>(std::move(name), std::move(builder), c);
    case 808: return std::make_unique<wide_accel<8, 8>>(std::move(name), std::move(builder), c);
    case 1604: return std::make_unique<wide_accel<16, 4>>(std::move(name), std::move(builder), c);
    case 1608: return std::make_unique<wide_accel<16, 8>>(std::move(name), std::move(builder), c);
    default:
        throw std::invalid_argument("wide BVH: nodes of " + std::to_string(c.width) + " and blocks of " +
                                    std::to_string(c.block) + " are not built (nodes of 4, 8 or 16; blocks of 4 or 8; "
                                    "not 4 with 8)");
    }
}

}  // namespace strahl::ch13

namespace strahl::ch13 {

// Out-of-line entries to the two exercises for the tests, which call them on their own (the exercises
// themselves are forced inline into the walk).
template <int N, bool Fused>
simd::vfloat<N> node_entry_out_of_line(const wide_node<N>& n, const wide_fast_slab<N, Fused>& s, float t0, float t1,
                                       simd::vmask<N>& hit) {
    return node_entry(n, s, t0, t1, hit);
}
template <int N>
std::uint32_t push_ordered_out_of_line(unsigned bits, const float* t, const std::uint32_t* child, stack_entry* stack,
                                       int& top) {
    return push_ordered<N>(bits, t, child, stack, top);
}
template simd::vfloat<4> node_entry_out_of_line<4, true>(const wide_node<4>&, const wide_fast_slab<4, true>&, float, float, simd::vmask<4>&);
template simd::vfloat<8> node_entry_out_of_line<8, true>(const wide_node<8>&, const wide_fast_slab<8, true>&, float, float, simd::vmask<8>&);
template simd::vfloat<16> node_entry_out_of_line<16, true>(const wide_node<16>&, const wide_fast_slab<16, true>&, float, float, simd::vmask<16>&);
template simd::vfloat<4> node_entry_out_of_line<4, false>(const wide_node<4>&, const wide_fast_slab<4, false>&, float, float, simd::vmask<4>&);
template simd::vfloat<8> node_entry_out_of_line<8, false>(const wide_node<8>&, const wide_fast_slab<8, false>&, float, float, simd::vmask<8>&);
template simd::vfloat<16> node_entry_out_of_line<16, false>(const wide_node<16>&, const wide_fast_slab<16, false>&, float, float, simd::vmask<16>&);
template std::uint32_t push_ordered_out_of_line<4>(unsigned, const float*, const std::uint32_t*, stack_entry*, int&);
template std::uint32_t push_ordered_out_of_line<8>(unsigned, const float*, const std::uint32_t*, stack_entry*, int&);
template std::uint32_t push_ordered_out_of_line<16>(unsigned, const float*, const std::uint32_t*, stack_entry*, int&);

}  // namespace strahl::ch13
