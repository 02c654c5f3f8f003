// The wide BVH behind the accel interface (accel.hpp): per ray, tree_query.hpp's rules (loose primitives,
// rays no tree can place), then the wide walk with the block test at its leaves.
//
// Included once, at the end of traversal.cpp (exercises 13.2 and 13.3), so that the walk is compiled in the
// same translation unit as the student's node test and ordered push, and inlines them.
#pragma once
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch13/accel.hpp"
#include "strahl/ch13/block_test.hpp"
#include "strahl/ch13/wide_queries.hpp"
#include <cmath>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace strahl::ch13 {

namespace {

// Watertight: the leaves' blocks tested by chapter 15's watertight test (on the corners, vertex_block),
// else by Moeller-Trumbore (on the edges, triangle_block).
// Node: wide_node<N>, or qnode<N> for the quantised tree (quantized_node.hpp).
template <int N, int M, bool Watertight = false, class Node = wide_node<N>>
class wide_accel final : public per_ray_accel<wide_accel<N, M, Watertight, Node>, wide_accel_base> {
public:
    wide_accel(std::string name, ch04::mesh_bvh_builder builder, const wide_config& c)
        : name_(std::move(name)), builder_(std::move(builder)), config_(c.collapse), order_(c.order),
          any_nearest_(c.any_hit_nearest), octant_(c.octant_order) {}

    std::string name() const override { return name_; }
    const collapse_stats& stats() const override { return tree_.stats; }

    // The binary tree is built, collapsed and dropped: the wide tree and its blocks are all the structure keeps
    // (with the corners for the watertight test, and the few loose triangles).
    void build(const scene& s) override {
        set_.reset();
        this->set_frame(ray_frame(s.mesh.bounds()));
        {
            const ch04::bvh binary = builder_(s.mesh);
            wide_bvh<N, M> wide = collapse<N, M>(binary, s.mesh, config_);
            order_children(wide, order_);
            if constexpr (N == 8)
                if (octant_) order_by_octant(wide);
            if constexpr (std::is_same_v<Node, wide_node<N>>) tree_ = std::move(wide);
            else tree_ = quantize(wide);
        }
        corners_.clear();
        if constexpr (Watertight) {
            corners_.resize(tree_.blocks.size());
            for (std::size_t k = 0; k < corners_.size(); ++k)
                for (int lane = 0; lane < M; ++lane) {
                    const auto p = s.mesh.triangle(tree_.blocks[k].id[lane]);
                    for (int c = 0; c < 3; ++c)
                        for (int a = 0; a < 3; ++a) corners_[k].v[c][a][lane] = p[c][a];
                }
        }
        set_ = std::make_unique<block_lane_set<N, M, Watertight>>(tree_, corners_, s.mesh);
    }
    std::optional<double> sah_cost() const override {
        if (!set_) return std::nullopt;
        return tree_.stats.sah;
    }
    // Everything it keeps: the wide tree and its blocks, the watertight test's corners, the loose triangles.
    std::size_t memory_bytes() const override {
        return tree_.memory_bytes() + (set_ ? set_->memory_bytes() : 0) + corners_.size() * sizeof(vertex_block<M>);
    }

    // tree_query.hpp's rules (loose primitives, rays no tree can place) around the wide walk
    // (wide_queries.hpp).
    template <class Stats>
    hit closest(const ray& query, Stats& stats) const {
        if (!set_) return hit{};
        return wide_closest<lanes_t>(tree_, *set_, query, stats, block_test(), [&](ray& r, auto&& leaf) {
            if constexpr (N == 8 && std::is_same_v<Node, wide_node<N>>)
                if (octant_) return wide_traverse<visit_order::octant>(tree_, r, stats, leaf);
            wide_traverse<visit_order::nearest>(tree_, r, stats, leaf);
        });
    }

    template <class Stats>
    bool any(const ray& query, Stats& stats) const {
        if (!set_) return false;
        return wide_any<lanes_t>(tree_, *set_, query, stats, block_test(), [&](ray& r, auto&& leaf) {
            if (any_nearest_) wide_traverse<visit_order::nearest>(tree_, r, stats, leaf);
            // The node's own order for rays without end (camera, diffuse): measured to pay there; a segment
            // (a shadow ray to its light) keeps the stored order, which its own measurement prefers.
            else if (order_ != child_order::collapsed && std::isinf(r.tmax)) wide_traverse<visit_order::ranked>(tree_, r, stats, leaf);
            else wide_traverse<visit_order::stored>(tree_, r, stats, leaf);
        });
    }

private:
    using lanes_t = std::conditional_t<Watertight, shear_lanes<M>, ray_lanes<M>>;
    // The block test: Moeller-Trumbore on block b, or the watertight test on its corners.
    auto block_test() const {
        return [this](const triangle_block<M>& b, const lanes_t& lanes, float tmin, float tmax, simd::vfloat<M>& t,
                      simd::vfloat<M>& u, simd::vfloat<M>& v) {
            if constexpr (Watertight)
                return intersect_block_watertight(corners_[std::size_t(&b - tree_.blocks.data())], lanes, tmin, tmax, t, u, v);
            else return intersect_block(b, lanes, tmin, tmax, t, u, v);
        };
    }

    std::string name_;
    ch04::mesh_bvh_builder builder_;
    collapse_config config_;
    child_order order_ = child_order::collapsed;
    bool any_nearest_ = false;
    bool octant_ = false;
    wide_bvh<N, M, Node> tree_;
    std::vector<vertex_block<M>> corners_;  // watertight only: the corners of every block
    std::unique_ptr<block_lane_set<N, M, Watertight>> set_;  // the loose triangles and brute force's fallback
};

}  // namespace

// A box builder: the triangles' boxes (as chapter 01's triangle_set bounds them) and centroids handed to it.
std::unique_ptr<wide_accel_base> make_accel(std::string name, ch04::bvh_builder builder, const wide_config& c) {
    return make_accel_from_mesh(std::move(name), [builder = std::move(builder)](const triangle_mesh& mesh) {
        std::vector<aabb> boxes(mesh.triangle_count());
        std::vector<vec3> centroids(boxes.size());
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            const auto t = mesh.triangle(i);
            boxes[i] = aabb{}.grow(t[0]).grow(t[1]).grow(t[2]), centroids[i] = boxes[i].centroid();
        }
        return builder(boxes, centroids);
    }, c);
}

std::unique_ptr<wide_accel_base> make_accel_from_mesh(std::string name, ch04::mesh_bvh_builder builder, const wide_config& c) {
    const int key = c.width * 100 + c.block;
    if (c.octant_order && c.width != 8)
        throw std::invalid_argument("wide BVH: the order per ray octant is kept by nodes of 8");
    if (c.quantized && (key != 808 || c.watertight))
        throw std::invalid_argument("wide BVH: quantised nodes are built for nodes of 8 with blocks of 8, Moeller-Trumbore");
    if (c.watertight) {
        switch (key) {
        case 804: return std::make_unique<wide_accel<8, 4, true>>(std::move(name), std::move(builder), c);
        case 1604: return std::make_unique<wide_accel<16, 4, true>>(std::move(name), std::move(builder), c);
        default:
            throw std::invalid_argument("wide BVH: the watertight test is built for nodes of 8 or 16 with blocks of 4");
        }
    }
    switch (key) {
    case 404: return std::make_unique<wide_accel<4, 4>>(std::move(name), std::move(builder), c);
    case 804: return std::make_unique<wide_accel<8, 4>>(std::move(name), std::move(builder), c);
    case 808:
        if (c.quantized) return std::make_unique<wide_accel<8, 8, false, qnode<8>>>(std::move(name), std::move(builder), c);
        return std::make_unique<wide_accel<8, 8>>(std::move(name), std::move(builder), c);
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
