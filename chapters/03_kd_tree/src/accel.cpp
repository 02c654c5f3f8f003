// Chapter 03's k-d tree behind the course's accel interface, generic over the primitive set: the build
// sees only the set's boxes, the traversal (traverse.hpp) is handed the set's leaf test.
#include "strahl/ch03/accel.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch03/traverse.hpp"
#include <cmath>

namespace strahl::ch03 {

namespace {

template <class Set>
class kd_accel final : public per_ray_accel<kd_accel<Set>, kd_accel_base> {
public:
    kd_accel(bool is_virtual, const kd_build_params& p) : virtual_(is_virtual), params_(p) {}

    std::string name() const override { return virtual_ ? "ch03-kd-virtual" : "ch03-kd"; }
    const kd_tree& tree() const override { return tree_; }

    void build(const scene& s) override {
        set_ = std::make_unique<Set>(s.mesh);
        this->set_frame(ray_frame(s.mesh.bounds()));
        std::vector<aabb> boxes(set_->size());
        for (std::size_t i = 0; i < boxes.size(); ++i) boxes[i] = set_->bounds(i);
        tree_ = build_kd_tree(boxes, params_);
    }

    std::size_t memory_bytes() const override {
        return tree_.memory_bytes() + tree_.loose.size() * 4 + (set_ ? set_->memory_bytes() : 0);
    }
    std::optional<double> sah_cost() const override { return tree_.sah_cost(); }

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
        traverse(tree_, r, stats, [&](std::uint32_t first, std::uint32_t count, float, float) {
            return leaf(tree_.prim_refs.data() + first, count);
        });
    }

    bool virtual_;
    kd_build_params params_;
    std::unique_ptr<Set> set_;
    kd_tree tree_;
};

}  // namespace

std::unique_ptr<kd_accel_base> make_kd_accel(bool virtual_primitives, const kd_build_params& params) {
    if (virtual_primitives) return std::make_unique<kd_accel<ch01::object_set>>(true, params);
    return std::make_unique<kd_accel<ch01::triangle_set>>(false, params);
}

std::unique_ptr<strahl::accel> make_accel(bool virtual_primitives) { return make_kd_accel(virtual_primitives); }

}  // namespace strahl::ch03
