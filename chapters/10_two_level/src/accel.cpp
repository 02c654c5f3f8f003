// Chapter 10's accels (accel.hpp): per-ray queries of two_level and instanced_brute, through the ray frame
// of the world box every instance's vertices span.
#include "strahl/ch10/accel.hpp"

namespace strahl::ch10 {

namespace {
class two_level_accel final : public per_ray_accel<two_level_accel, two_level_accel_base> {
public:
    explicit two_level_accel(two_level_config c) : structure_(std::move(c)) {}
    std::string name() const override { return "ch10-two-level"; }
    void build(const scene& s) override {
        structure_.build(instances_of(s));
        set_frame(ray_frame(structure_.bounds()));
    }
    std::size_t memory_bytes() const override { return structure_.memory_bytes(); }
    std::optional<double> sah_cost() const override { return structure_.sah_cost(); }
    two_level& structure() override { return structure_; }

    template <class Stats>
    hit closest(const ray& r, Stats& stats) const { return structure_.closest(r, stats); }
    template <class Stats>
    bool any(const ray& r, Stats& stats) const { return structure_.any(r, stats); }

private:
    two_level structure_;
};

class brute_accel final : public per_ray_accel<brute_accel> {
public:
    std::string name() const override { return "ch10-brute-instanced"; }
    void build(const scene& s) override {
        brute_.build(instances_of(s));
        set_frame(ray_frame(brute_.bounds()));
    }
    std::size_t memory_bytes() const override { return brute_.memory_bytes(); }

    template <class Stats>
    hit closest(const ray& r, Stats& stats) const { return brute_.closest(r, stats); }
    template <class Stats>
    bool any(const ray& r, Stats& stats) const { return brute_.any(r, stats); }

private:
    instanced_brute brute_;
};
}  // namespace

std::unique_ptr<two_level_accel_base> make_accel(two_level_config config) {
    return std::make_unique<two_level_accel>(std::move(config));
}
std::unique_ptr<strahl::accel> make_brute_accel() { return std::make_unique<brute_accel>(); }

}  // namespace strahl::ch10
