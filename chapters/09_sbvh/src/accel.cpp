// The SBVH behind the accel interface: a small variant of chapter 04's bvh_accel_t whose build hands the
// builder the mesh, walked by chapter 05's fast traversal and answered by tree_query.hpp's closest and any
// hit. A leaf may hold a triangle that another leaf holds too: the closest-hit rule (ray.hpp's closer)
// keeps the first of two equal hits, and an any-hit query stops at the first, so the answers are brute
// force's.
#include "strahl/ch09/accel.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch05/fast_traverse.hpp"
#include "strahl/tree_query.hpp"

namespace strahl::ch09 {

namespace {

class sbvh_accel final : public per_ray_accel<sbvh_accel, sbvh_accel_base> {
public:
    sbvh_accel(const sbvh_params& p, std::string name) : params_(p), name_(std::move(name)) {}

    std::string name() const override { return name_; }
    const ch04::bvh& tree() const override { return tree_; }
    const sbvh_report& report() const override { return report_; }

    void build(const scene& s) override {
        set_ = std::make_unique<ch01::triangle_set>(s.mesh);
        set_frame(ray_frame(s.mesh.bounds()));
        tree_ = build_sbvh(s.mesh, params_, &report_);
    }
    std::optional<double> sah_cost() const override {
        if (!set_) return std::nullopt;
        return ch04::sah_tree_cost(tree_, 1.0f, 1.0f);
    }
    std::size_t memory_bytes() const override {
        return tree_.memory_bytes() + tree_.loose.size() * 4 + (set_ ? set_->memory_bytes() : 0);
    }

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
        ch05::fast_traverse(tree_, r, stats, [&](std::uint32_t first, std::uint32_t count) {
            return leaf(tree_.prim_ids.data() + first, count);
        });
    }

    sbvh_params params_;
    std::string name_;
    std::unique_ptr<ch01::triangle_set> set_;
    ch04::bvh tree_;
    sbvh_report report_;
};

}  // namespace

std::unique_ptr<sbvh_accel_base> make_accel(const sbvh_params& params, std::string name) {
    if (name.empty()) name = "ch09-" + to_string(params) + "-fast";
    return std::make_unique<sbvh_accel>(params, std::move(name));
}

}  // namespace strahl::ch09
