// Chapter 04's BVH behind the course's accel interface, generic over the primitive set: the build sees
// only the set's boxes and centroids, the traversal (traverse.hpp) is handed the set's leaf test.
// (Kay and Kajiya 1986; Goldsmith and Salmon 1987; pbrt-v4, section 7.3.)
#include "strahl/ch04/accel.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch04/traverse.hpp"
#include <cmath>

namespace strahl::ch04 {

namespace {

// Rays the BVH cannot place (a NaN or Inf component, a zero or vanishing direction) get the answer of
// testing every primitive in id order: brute force's answer by definition, and no t-range arithmetic.
bool placeable(const ray& r) {
    const float d2 = glm::dot(r.dir, r.dir);
    return std::isfinite(r.org.x) && std::isfinite(r.org.y) && std::isfinite(r.org.z) && std::isfinite(d2) &&
           d2 > 1e-30f && glm::dot(r.org, r.org) < 1e36f;
}

template <class Set>
class bvh_accel_t final : public bvh_accel_base {
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

    void intersect(std::span<const ray> rays, std::span<hit> hits) const override {
        not_counting stats;
        for (std::size_t i = 0; i < rays.size(); ++i) hits[i] = closest(rays[i], stats);
    }
    void occluded(std::span<const ray> rays, std::span<std::uint8_t> blocked) const override {
        not_counting stats;
        for (std::size_t i = 0; i < rays.size(); ++i) blocked[i] = any(rays[i], stats) ? 1 : 0;
    }
    std::optional<counter_values> intersect_counted(std::span<const ray> rays, std::span<hit> hits) const override {
        counting stats;
        for (std::size_t i = 0; i < rays.size(); ++i) hits[i] = closest(rays[i], stats);
        return stats.values();
    }
    std::optional<counter_values> occluded_counted(std::span<const ray> rays,
                                                   std::span<std::uint8_t> blocked) const override {
        counting stats;
        for (std::size_t i = 0; i < rays.size(); ++i) blocked[i] = any(rays[i], stats) ? 1 : 0;
        return stats.values();
    }
    std::size_t memory_bytes() const override {
        return tree_.memory_bytes() + tree_.loose.size() * 4 + (set_ ? set_->memory_bytes() : 0);
    }

private:
    template <class Stats>
    hit closest(const ray& query, Stats& stats) const {
        stats.ray();
        hit best;
        if (!(query.tmin < query.tmax) || !set_) return best;  // an empty (or NaN) interval: a miss
        ray r = query;
        for (const std::uint32_t id : tree_.loose) stats.prim_test(), set_->intersect(id, r, best);
        if (!placeable(r)) {
            for (std::uint32_t id = 0; id < set_->size(); ++id) stats.prim_test(), set_->intersect(id, r, best);
            return best;
        }
        // The leaf test: every reference against r; each hit shrinks r.tmax (record_closest), which the
        // traversal reads to decide whether farther nodes can still hold a closer hit.
        traverse(tree_, r, stats, [&](std::uint32_t first, std::uint32_t count) {
            for (std::uint32_t k = first; k < first + count; ++k) {
                stats.prim_test();
                set_->intersect(tree_.prim_ids[k], r, best);
            }
            return false;
        });
        return best;
    }

    template <class Stats>
    bool any(const ray& query, Stats& stats) const {
        stats.ray();
        if (!(query.tmin < query.tmax) || !set_) return false;
        for (const std::uint32_t id : tree_.loose)
            if (stats.prim_test(), set_->occludes(id, query)) return true;
        if (!placeable(query)) {
            for (std::uint32_t id = 0; id < set_->size(); ++id)
                if (stats.prim_test(), set_->occludes(id, query)) return true;
            return false;
        }
        ray r = query;
        bool found = false;
        traverse(tree_, r, stats, [&](std::uint32_t first, std::uint32_t count) {
            for (std::uint32_t k = first; k < first + count && !found; ++k) {
                stats.prim_test();
                found = set_->occludes(tree_.prim_ids[k], query);
            }
            return found;
        });
        return found;
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
