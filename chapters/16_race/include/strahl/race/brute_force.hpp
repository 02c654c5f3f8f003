// Brute force: every ray against every triangle with chapter 01's triangle test (exercise 01.3's
// Moeller-Trumbore, from the solutions). It defines the right answer: every course structure must return
// exactly what it returns, hit for hit, bit for bit, on the same rays.
#pragma once
#include "strahl/accel.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include <memory>

namespace strahl::race {

class brute_force final : public accel {
public:
    std::string name() const override { return "brute"; }
    void build(const scene& s) override;
    void intersect(std::span<const ray> rays, std::span<hit> hits) const override;
    void occluded(std::span<const ray> rays, std::span<std::uint8_t> blocked) const override;
    std::optional<counter_values> intersect_counted(std::span<const ray> rays, std::span<hit> hits) const override;
    std::optional<counter_values> occluded_counted(std::span<const ray> rays,
                                                   std::span<std::uint8_t> blocked) const override;
    std::size_t memory_bytes() const override { return triangles_->memory_bytes(); }

private:
    template <class Stats>
    void closest(std::span<const ray> rays, std::span<hit> hits, Stats& stats) const;
    template <class Stats>
    void any(std::span<const ray> rays, std::span<std::uint8_t> blocked, Stats& stats) const;

    // The mesh's triangles in id order (none before build(): every ray misses).
    std::unique_ptr<ch01::triangle_set> triangles_ = std::make_unique<ch01::triangle_set>(triangle_mesh{});
};

}  // namespace strahl::race
