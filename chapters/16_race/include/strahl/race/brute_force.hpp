// Brute force: every ray against every triangle with chapter 01's triangle test (exercise 01.3's
// Moeller-Trumbore, from the solutions). It defines the right answer: every course structure must return
// exactly what it returns, hit for hit, bit for bit, on the same rays.
#pragma once
#include "strahl/accel.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include <memory>

namespace strahl::race {

class brute_force final : public per_ray_accel<brute_force> {
public:
    std::string name() const override { return "brute"; }
    void build(const scene& s) override;
    std::size_t memory_bytes() const override { return triangles_->memory_bytes(); }

    // Every triangle in id order; see brute_force.cpp.
    template <class Stats>
    hit closest(const ray& query, Stats& stats) const;
    template <class Stats>
    bool any(const ray& query, Stats& stats) const;

private:
    // The mesh's triangles in id order (none before build(): every ray misses).
    std::unique_ptr<ch01::triangle_set> triangles_ = std::make_unique<ch01::triangle_set>(triangle_mesh{});
};

}  // namespace strahl::race
