// Chapter 04's BVH behind the course's accel interface, generic over the primitive set and the traversal:
// the build sees only the set's boxes and centroids; the traversal (Walk) is handed the set's leaf test.
// Chapter 04 instantiates it with its own traversal (traverse.hpp), chapter 05 with its faster one.
// (Kay and Kajiya 1986; Goldsmith and Salmon 1987; pbrt-v4, section 7.3.)
#pragma once
#include "strahl/ch04/accel.hpp"
#include "strahl/tree_query.hpp"
#include <memory>
#include <string>
#include <vector>

namespace strahl::ch04 {

// Walk: a default-constructible type with
//   template <class Stats, class Leaf> void operator()(const bvh&, ray& r, Stats&, Leaf&& leaf) const;
// which calls leaf(first, count) for the leaves r reaches (prim_ids[first, first + count)) and stops when
// leaf returns true.
// Base: bvh_accel_base, or an interface derived from it, which a class derived from this one completes
// (chapter 09's SBVH adds its build report).
template <class Set, class Walk, class Base = bvh_accel_base>
class bvh_accel_t : public per_ray_accel<bvh_accel_t<Set, Walk, Base>, Base> {
public:
    bvh_accel_t(bool is_virtual, std::string name, bvh_builder builder)
        : name_(std::move(name) + (is_virtual ? "-virtual" : "")), builder_(std::move(builder)) {}
    // A builder that is handed the mesh itself (accel.hpp's mesh_bvh_builder).
    bvh_accel_t(std::string name, mesh_bvh_builder builder) : name_(std::move(name)), mesh_builder_(std::move(builder)) {}

    std::string name() const override { return name_; }
    const bvh& tree() const override { return tree_; }

    void build(const scene& s) override {
        set_ = std::make_unique<Set>(s.mesh);
        this->set_frame(ray_frame(s.mesh.bounds()));
        if (mesh_builder_) {
            tree_ = mesh_builder_(s.mesh);
            return;
        }
        std::vector<aabb> boxes(set_->size());
        std::vector<vec3> centroids(set_->size());
        for (std::size_t i = 0; i < boxes.size(); ++i) boxes[i] = set_->bounds(i), centroids[i] = boxes[i].centroid();
        tree_ = builder_(boxes, centroids);
    }

    std::optional<double> sah_cost() const override {
        if (!set_) return std::nullopt;
        return sah_tree_cost(tree_, 1.0f, 1.0f);
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
        Walk{}(tree_, r, stats, [&](std::uint32_t first, std::uint32_t count) {
            return leaf(tree_.prim_ids.data() + first, count);
        });
    }

    std::string name_;
    bvh_builder builder_;
    mesh_bvh_builder mesh_builder_;  // where set, builder_ is not used
    std::unique_ptr<Set> set_;
    bvh tree_;
};

}  // namespace strahl::ch04
