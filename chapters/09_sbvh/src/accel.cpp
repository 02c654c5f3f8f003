// The SBVH behind the accel interface: chapter 04's bvh_accel_t over plain triangles, its builder handed the
// mesh (build_sbvh), walked by chapter 05's fast traversal and answered by tree_query.hpp's closest and any
// hit. A leaf may hold a triangle that another leaf holds too: the closest-hit rule (ray.hpp's closer)
// keeps the first of two equal hits, and an any-hit query stops at the first, so the answers are brute
// force's. This class adds only the build's report.
#include "strahl/ch09/accel.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch04/bvh_accel.hpp"
#include "strahl/ch05/fast_traverse.hpp"

namespace strahl::ch09 {

namespace {

class sbvh_accel final : public ch04::bvh_accel_t<ch01::triangle_set, ch05::fast_walk, sbvh_accel_base> {
public:
    sbvh_accel(const sbvh_params& p, std::string name)
        : bvh_accel_t(std::move(name), [this, p](const triangle_mesh& mesh) { return build_sbvh(mesh, p, &report_); }) {}
    // The builder writes this object's report: neither copied nor moved.
    sbvh_accel(const sbvh_accel&) = delete;
    sbvh_accel& operator=(const sbvh_accel&) = delete;

    const sbvh_report& report() const override { return report_; }

private:
    sbvh_report report_;
};

}  // namespace

std::unique_ptr<sbvh_accel_base> make_accel(const sbvh_params& params, std::string name) {
    if (name.empty()) name = "ch09-" + to_string(params) + "-fast";
    return std::make_unique<sbvh_accel>(params, std::move(name));
}

}  // namespace strahl::ch09
