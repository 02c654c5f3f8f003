// A wide tree's queries under tree_query.hpp's rules, written once for the structures that walk chapter 13's
// tree one ray at a time: chapter 13's accel, and chapters 12 and 14's packet tracers for the rays they
// trace alone. block_lane_set answers what the walk cannot (loose triangles, rays no tree can place) from
// the leaves' own blocks, so that no structure keeps a second copy of its triangles.
#pragma once
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch13/block_test.hpp"
#include "strahl/ch13/wide_traverse.hpp"
#include "strahl/tree_query.hpp"
#include <cmath>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

namespace strahl::ch13 {

// The leaves' triangles as the primitive set of tree_query.hpp's rules (loose primitives, and rays no tree
// can place, which brute force answers), so that the structure keeps no second copy of its triangles: index
// k below lanes() is lane k % M of block k / M (a lane past its leaf's end repeats the leaf's last triangle:
// the same answer twice), index lanes() + j the j-th loose triangle (non-finite, left out of the tree, kept
// here in a block of its own). Every test is the leaves' own block test, Moeller-Trumbore on the edges or
// chapter 15's watertight test on the corners, on a block whose lanes all hold the one triangle: these
// answers are the lanes' bits.
template <int N, int M, bool Watertight>
class block_lane_set {
public:
    using block_t = std::conditional_t<Watertight, vertex_block<M>, triangle_block<M>>;

    template <class Node>
    block_lane_set(const wide_bvh<N, M, Node>& tree, const std::vector<vertex_block<M>>& corners, const triangle_mesh& mesh)
        : blocks_(&tree.blocks), corners_(&corners) {
        for (const std::uint32_t id : tree.loose) {
            const auto p = mesh.triangle(id);
            block_t b;
            for (int lane = 0; lane < M; ++lane) {
                if constexpr (Watertight) {
                    for (int c = 0; c < 3; ++c)
                        for (int a = 0; a < 3; ++a) b.v[c][a][lane] = p[c][a];
                } else {
                    const vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];  // as exercise 01.3 computes them
                    for (int a = 0; a < 3; ++a) b.v0[a][lane] = p[0][a], b.e1[a][lane] = e1[a], b.e2[a][lane] = e2[a];
                    b.id[lane] = id;
                }
            }
            loose_indices_.push_back(std::uint32_t(lanes() + loose_.size()));
            loose_.push_back(b);
            loose_ids_.push_back(id);
        }
    }
    std::size_t lanes() const { return blocks_->size() * M; }
    std::size_t size() const { return lanes() + loose_.size(); }
    // The loose triangles' indices in this set (for tree_query.hpp's loose list).
    std::span<const std::uint32_t> loose() const { return loose_indices_; }
    std::size_t memory_bytes() const { return loose_.size() * (sizeof(block_t) + 8); }

    bool intersect(std::uint32_t k, ray& r, hit& best) const {
        float t, u, v;
        return test(k, r, t, u, v) && ch01::record_closest(id(k), t, u, v, r, best);
    }
    bool occludes(std::uint32_t k, const ray& r) const {
        float t, u, v;
        return test(k, r, t, u, v);
    }

private:
    std::uint32_t id(std::uint32_t k) const {
        return k < lanes() ? (*blocks_)[k / M].id[k % M] : loose_ids_[k - lanes()];
    }
    // Lane `lane` of block b in every lane.
    static block_t broadcast(const block_t& b, int lane) {
        block_t out;
        for (int l = 0; l < M; ++l) {
            if constexpr (Watertight) {
                for (int c = 0; c < 3; ++c)
                    for (int a = 0; a < 3; ++a) out.v[c][a][l] = b.v[c][a][lane];
            } else {
                for (int a = 0; a < 3; ++a)
                    out.v0[a][l] = b.v0[a][lane], out.e1[a][l] = b.e1[a][lane], out.e2[a][l] = b.e2[a][lane];
                out.id[l] = b.id[lane];
            }
        }
        return out;
    }
    bool test(std::uint32_t k, const ray& r, float& t, float& u, float& v) const {
        const std::size_t in = lanes();
        const block_t b = k >= in ? loose_[k - in] : broadcast(block_source(k / M), int(k % M));
        simd::vfloat<M> tl, ul, vl;
        unsigned bits;
        if constexpr (Watertight) bits = simd::movemask(intersect_block_watertight(b, shear_lanes<M>(r), r.tmin, r.tmax, tl, ul, vl));
        else bits = simd::movemask(intersect_block(b, ray_lanes<M>(r), r.tmin, r.tmax, tl, ul, vl));
        if (!(bits & 1u)) return false;
        t = tl[0], u = ul[0], v = vl[0];
        return true;
    }
    const block_t& block_source(std::size_t i) const {
        if constexpr (Watertight) return (*corners_)[i];
        else return (*blocks_)[i];
    }

    const huge_vector<triangle_block<M>>* blocks_;  // the tree's
    const std::vector<vertex_block<M>>* corners_;
    std::vector<block_t> loose_;
    std::vector<std::uint32_t> loose_ids_, loose_indices_;
};

// Closest hit: loose triangles and rays no tree can place through `set`, every other ray through
// walk(r, leaf) (wide_traverse, or robust_walk), which calls leaf(ref) for each leaf it reaches;
// test(block, lanes, tmin, tmax, t, u, v) is the leaves' block test on the lanes Lanes(r) makes once per ray.
template <class Lanes, int N, int M, class Node, class Set, class Stats, class Test, class Walk>
hit wide_closest(const wide_bvh<N, M, Node>& tree, const Set& set, const ray& query, Stats& stats, Test&& test, Walk&& walk) {
    return tree_closest_with(set, set.loose(), query, stats, [&](ray& r, hit& best) {
        const Lanes lanes(r);
        walk(r, [&](std::uint32_t ref) {
            const triangle_block<M>* b = &tree.blocks[leaf_first(ref)];
            for (std::uint32_t k = leaf_blocks(ref); k-- > 0; ++b) {
                stats.prim_test(M);
                simd::vfloat<M> t, u, v;
                unsigned bits = simd::movemask(test(*b, lanes, r.tmin, r.tmax, t, u, v));
                if (bits == 0) continue;
                alignas(64) float ts[M], us[M], vs[M];
                t.store(ts), u.store(us), v.store(vs);
                for (; bits != 0; bits &= bits - 1) {
                    const int i = std::countr_zero(bits);
                    ch01::record_closest(b->id[i], ts[i], us[i], vs[i], r, best);
                }
            }
            return false;
        });
    });
}

// Any hit, the whole query ending at the first blocker: as above, walk(r, leaf) in the order the caller
// chooses.
template <class Lanes, int N, int M, class Node, class Set, class Stats, class Test, class Walk>
bool wide_any(const wide_bvh<N, M, Node>& tree, const Set& set, const ray& query, Stats& stats, Test&& test, Walk&& walk) {
    return tree_any_with(set, set.loose(), query, stats, [&](ray& r) {
        const Lanes lanes(r);
        bool found = false;
        walk(r, [&](std::uint32_t ref) {
            const triangle_block<M>* b = &tree.blocks[leaf_first(ref)];
            for (std::uint32_t k = leaf_blocks(ref); k-- > 0 && !found; ++b) {
                stats.prim_test(M);
                simd::vfloat<M> t, u, v;
                found = simd::any(test(*b, lanes, r.tmin, r.tmax, t, u, v));
            }
            return found;
        });
        return found;
    });
}

}  // namespace strahl::ch13
