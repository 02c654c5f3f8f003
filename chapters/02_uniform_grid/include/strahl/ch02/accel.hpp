// Chapter 02's grid behind the course's one interface (common/include/strahl/accel.hpp), over plain
// triangles ("ch02-grid") or chapter 01's virtual objects ("ch02-grid-virtual"). The race registers both.
#pragma once
#include "strahl/accel.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch02/tri_box.hpp"
#include "strahl/ch02/uniform_grid.hpp"
#include <memory>
#include <optional>

namespace strahl::ch02 {

template <class Set>
class grid_accel final : public strahl::accel {
public:
    explicit grid_accel(grid_options opt = {}) : opt_(opt) {}

    std::string name() const override {
        return std::is_same_v<Set, ch01::object_set> ? "ch02-grid-virtual" : "ch02-grid";
    }

    void build(const scene& s) override {
        set_.emplace(s.mesh);
        const triangle_mesh& mesh = s.mesh;
        // Exact overlap (an option the chapter measures): the triangle itself against the cell's box.
        grid_.build(*set_, opt_, [&mesh](std::uint32_t i, const aabb& cell) {
            const auto v = mesh.triangle(i);
            return triangle_overlaps_box(v[0], v[1], v[2], cell);
        });
    }

    void intersect(std::span<const ray> rays, std::span<hit> hits) const override {
        not_counting quiet;
        closest(rays, hits, quiet);
    }
    void occluded(std::span<const ray> rays, std::span<std::uint8_t> blocked) const override {
        not_counting quiet;
        any(rays, blocked, quiet);
    }
    std::optional<counter_values> intersect_counted(std::span<const ray> rays, std::span<hit> hits) const override {
        counting c;
        closest(rays, hits, c);
        return c.values();
    }
    std::optional<counter_values> occluded_counted(std::span<const ray> rays,
                                                   std::span<std::uint8_t> blocked) const override {
        counting c;
        any(rays, blocked, c);
        return c.values();
    }
    std::size_t memory_bytes() const override {
        return grid_.memory_bytes() + (set_ ? set_->memory_bytes() : 0);
    }

    const uniform_grid& grid() const { return grid_; }

private:
    template <class Stats>
    void closest(std::span<const ray> rays, std::span<hit> hits, Stats& stats) const {
        for (std::size_t i = 0; i < rays.size(); ++i) {
            hits[i] = hit{};
            if (set_) grid_.intersect(*set_, rays[i], hits[i], stats);
        }
    }
    template <class Stats>
    void any(std::span<const ray> rays, std::span<std::uint8_t> blocked, Stats& stats) const {
        for (std::size_t i = 0; i < rays.size(); ++i)
            blocked[i] = set_ && grid_.occluded(*set_, rays[i], stats) ? 1 : 0;
    }

    grid_options opt_;
    std::optional<Set> set_;
    uniform_grid grid_;
};

// The grid over triangle_set (false) or object_set (true), with default options.
std::unique_ptr<strahl::accel> make_accel(bool virtual_primitives);
std::unique_ptr<strahl::accel> make_accel(bool virtual_primitives, const grid_options& opt);

}  // namespace strahl::ch02
