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
class grid_accel final : public per_ray_accel<grid_accel<Set>> {
public:
    explicit grid_accel(grid_options opt = {}) : opt_(opt) {}

    std::string name() const override {
        return std::is_same_v<Set, ch01::object_set> ? "ch02-grid-virtual" : "ch02-grid";
    }

    void build(const scene& s) override {
        set_.emplace(s.mesh);
        this->set_frame(ray_frame(s.mesh.bounds()));
        const triangle_mesh& mesh = s.mesh;
        // Exact overlap (an option the chapter measures): the triangle itself against the cell's box.
        grid_.build(*set_, opt_, [&mesh](std::uint32_t i, const aabb& cell) {
            const auto v = mesh.triangle(i);
            return triangle_overlaps_box(v[0], v[1], v[2], cell);
        });
    }

    std::size_t memory_bytes() const override {
        return grid_.memory_bytes() + (set_ ? set_->memory_bytes() : 0);
    }

    const uniform_grid& grid() const { return grid_; }

    // The per-ray queries (per_ray_accel turns them into batches).
    template <class Stats>
    hit closest(const ray& r, Stats& stats) const {
        hit best;
        if (set_) grid_.intersect(*set_, r, best, stats);
        return best;
    }
    template <class Stats>
    bool any(const ray& r, Stats& stats) const {
        return set_ && grid_.occluded(*set_, r, stats);
    }

private:
    grid_options opt_;
    std::optional<Set> set_;
    uniform_grid grid_;
};

// The grid over triangle_set (false) or object_set (true), with default options.
std::unique_ptr<strahl::accel> make_accel(bool virtual_primitives);
std::unique_ptr<strahl::accel> make_accel(bool virtual_primitives, const grid_options& opt);

}  // namespace strahl::ch02
