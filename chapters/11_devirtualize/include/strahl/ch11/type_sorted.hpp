// Step 3 of chapter 11: primitives sorted by type. Instead of one array of variants and a jump per
// primitive, one array per type, and each leaf a range in each: the leaf test is three loops, each over
// one type, with no branch on the type inside. The tree is the same; only what a leaf points at changes.
//   I. Wald, "Realtime Ray Tracing and Interactive Global Illumination", 2004, section 7.1 (one primitive
//   type per leaf); M. Pharr, W. Jakob and G. Humphreys, pbrt-v4, 2023, section 7.1 (primitives by type).
#pragma once
#include "strahl/ch11/shapes.hpp"
#include <array>
#include <span>

namespace strahl::ch11 {

// One leaf: for each type (shape's index: triangle, sphere, plane), the range [first, first + count) of
// that type's array.
struct sorted_leaf {
    std::array<std::uint32_t, shape_types> first{};
    std::array<std::uint32_t, shape_types> count{};
};

// The per-type arrays, in leaf order, each entry with its primitive id (for the tie rule and the hit).
struct sorted_primitives {
    std::vector<triangle_shape> triangles;
    std::vector<sphere_shape> spheres;
    std::vector<plane_shape> planes;
    std::array<std::vector<std::uint32_t>, shape_types> ids;  // ids[type][k]: the id of that array's entry k

    std::size_t memory_bytes() const {
        std::size_t n = triangles.size() * sizeof(triangle_shape) + spheres.size() * sizeof(sphere_shape) +
                        planes.size() * sizeof(plane_shape);
        for (const auto& v : ids) n += v.size() * 4;
        return n;
    }
};

// Exercise 11.3 (exercises/11_devirtualize/sort_by_type.cpp): one leaf's primitives, by type. `leaf` lists
// the leaf's primitive ids (indices into `shapes`) in the tree's order. Appends them to out's arrays, all
// triangles first, then all spheres, then all planes, each type keeping the order of `leaf`, with their
// ids in out.ids; returns the leaf's range in each array (an empty range starts at that array's end).
sorted_leaf sort_leaf_by_type(std::span<const std::uint32_t> leaf, std::span<const shape> shapes,
                              sorted_primitives& out);

}  // namespace strahl::ch11
