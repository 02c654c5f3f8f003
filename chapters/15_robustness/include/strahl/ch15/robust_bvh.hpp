// Chapter 15's structures: one tree (chapter 05's binned SAH build over the triangles' boxes), walked with
// one of five triangle tests and one of three box tests, so that each choice's cost and accuracy can be
// measured alone. The walk is chapter 05's (both children tested at the parent, nearer first); the box
// tests differ in how they treat rounding:
//   plain:        t = (plane - org) / dir per plane, nothing widened: a ray through a box's edge or corner
//                 can find t_near a little above t_far and miss the box (and every triangle in it);
//   conservative: the same with the far distance widened by 1 + 2 gamma(3) (Ize 2013; pbrt-v4's
//                 Bounds3::IntersectP): the rounding bound of the three operations, so no box the exact ray
//                 meets is missed;
//   fast:         chapter 05's fast walk: the fast slab test (the origin's terms moved once per ray) and
//                 the ray's slack (tree_query.hpp), which also covers the triangle test's own error in t,
//                 so that the answers equal brute force's with the same test.
#pragma once
#include "strahl/inlining.hpp"
#include "strahl/accel.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch01/shapes.hpp"
#include "strahl/ch05/fast_traverse.hpp"
#include "strahl/ch05/sah.hpp"
#include "strahl/ch11/triangles.hpp"
#include "strahl/ch15/watertight.hpp"
#include "strahl/tree_query.hpp"
#include <array>
#include <string>
#include <vector>

namespace strahl::ch15 {

enum class test_kind { mt, mt_epsilon, mt_edges, watertight, watertight_double };
enum class box_kind { plain, conservative, fast };

inline constexpr test_kind all_tests[] = {test_kind::mt, test_kind::mt_epsilon, test_kind::mt_edges,
                                          test_kind::watertight, test_kind::watertight_double};
inline constexpr box_kind all_boxes[] = {box_kind::plain, box_kind::conservative, box_kind::fast};

// Short names (used in structure names and CSV files) and one-line descriptions.
const char* name(test_kind k);
const char* describe(test_kind k);
const char* name(box_kind k);

// The triangles of a mesh and test K on them, with chapter 01's closest-hit rule (record_closest). A test
// that needs a per-ray set-up (the watertight test's shear) gets it from prepare(); the forms without a
// context make it per call (brute force, and tree_query's fallbacks): the same answers.
template <test_kind K>
class triangle_tests {
public:
    struct context {
        shear s;
    };
    explicit triangle_tests(const triangle_mesh& mesh) : tris_(mesh.triangle_count()) {
        for (std::size_t i = 0; i < tris_.size(); ++i) tris_[i] = mesh.triangle(i);
        if constexpr (K == test_kind::mt_edges) {
            edges_.resize(tris_.size());
            for (std::size_t i = 0; i < tris_.size(); ++i)
                edges_[i] = ch11::make_edge_triangle(tris_[i][0], tris_[i][1], tris_[i][2]);
        }
    }
    std::size_t size() const { return tris_.size(); }
    aabb bounds(std::size_t i) const { return aabb().grow(tris_[i][0]).grow(tris_[i][1]).grow(tris_[i][2]); }
    const std::array<vec3, 3>& triangle(std::size_t i) const { return tris_[i]; }

    context prepare(const ray& r) const {
        if constexpr (K == test_kind::watertight) return {make_shear(r.dir)};
        else return {};
    }
    STRAHL_ALWAYS_INLINE bool test(std::uint32_t i, const ray& r, const context& c, float& t, float& u,
                                   float& v) const {
        const std::array<vec3, 3>& p = tris_[i];
        if constexpr (K == test_kind::mt) return ch01::intersect_triangle(r, p[0], p[1], p[2], t, u, v);
        else if constexpr (K == test_kind::mt_epsilon) return intersect_mt_epsilon(r, p[0], p[1], p[2], t, u, v);
        else if constexpr (K == test_kind::mt_edges)
            return ch11::intersect_edges(r, edges_[i].v0, edges_[i].e1, edges_[i].e2, t, u, v);
        else if constexpr (K == test_kind::watertight) return intersect_watertight(r, c.s, p[0], p[1], p[2], t, u, v);
        else return intersect_watertight_double(r, p[0], p[1], p[2], t, u, v);
    }
    bool intersect(std::uint32_t i, ray& r, const context& c, hit& best) const {
        float t, u, v;
        return test(i, r, c, t, u, v) && ch01::record_closest(i, t, u, v, r, best);
    }
    bool occludes(std::uint32_t i, const ray& r, const context& c) const {
        float t, u, v;
        return test(i, r, c, t, u, v);
    }
    bool intersect(std::uint32_t i, ray& r, hit& best) const { return intersect(i, r, prepare(r), best); }
    bool occludes(std::uint32_t i, const ray& r) const { return occludes(i, r, prepare(r)); }
    std::size_t memory_bytes() const { return tris_.size() * sizeof(tris_[0]) + edges_.size() * sizeof(ch11::edge_triangle); }

private:
    std::vector<std::array<vec3, 3>> tris_;
    std::vector<ch11::edge_triangle> edges_;
};

// The plain slab test: chapter 05's robust_slab without its widening.
struct plain_slab : ch05::plane_choice {
    vec3 org, inv_dir;
    explicit plain_slab(const ray& r) : plane_choice(r.dir), org(r.org), inv_dir(1.0f / r.dir) {}
    STRAHL_ALWAYS_INLINE float entry(const ch04::bvh_node& n, float t0, float t1) const {
        const float* planes = n.bmin;
        for (int a = 0; a < 3; ++a) {
            const float near = (planes[near_plane[a]] - org[a]) * inv_dir[a];
            const float far = (planes[far_plane[a]] - org[a]) * inv_dir[a];
            t0 = near > t0 ? near : t0;
            t1 = far < t1 ? far : t1;
        }
        return t0 <= t1 ? t0 : inf;
    }
};

// The walk with box test B: leaf(first, count) as chapter 05's walk_with calls it.
template <box_kind B, class Stats, class Leaf>
void walk(const ch04::bvh& tree, ray& r, Stats& stats, Leaf&& leaf) {
    if (tree.nodes.empty()) return;
    if constexpr (B == box_kind::plain) ch05::walk_with(tree, plain_slab(r), 0.0f, r, stats, leaf);
    else if constexpr (B == box_kind::conservative) ch05::walk_with(tree, ch05::robust_slab(r), 0.0f, r, stats, leaf);
    else ch05::fast_traverse(tree, r, stats, leaf);
}

// Brute force with test K: every triangle, the oracle of the structures below with the same test.
template <test_kind K>
class brute_tests final : public per_ray_accel<brute_tests<K>> {
public:
    std::string name() const override { return std::string("brute-") + ch15::name(K); }
    void build(const scene& s) override {
        set_ = triangle_tests<K>(s.mesh);
        this->set_frame(ray_frame(s.mesh.bounds()));
    }
    template <class Stats>
    hit closest(const ray& query, Stats& stats) const {
        stats.ray();
        hit best;
        if (!(query.tmin < query.tmax)) return best;
        ray r = query;
        const auto c = set_.prepare(r);
        for (std::uint32_t i = 0; i < set_.size(); ++i) stats.prim_test(), set_.intersect(i, r, c, best);
        return best;
    }
    template <class Stats>
    bool any(const ray& r, Stats& stats) const {
        stats.ray();
        if (!(r.tmin < r.tmax)) return false;
        const auto c = set_.prepare(r);
        for (std::uint32_t i = 0; i < set_.size(); ++i)
            if (stats.prim_test(), set_.occludes(i, r, c)) return true;
        return false;
    }
    std::size_t memory_bytes() const override { return set_.memory_bytes(); }

private:
    triangle_tests<K> set_{triangle_mesh{}};
};

// Chapter 05's binned SAH tree with triangle test K and box test B.
template <test_kind K, box_kind B>
class robust_bvh final : public per_ray_accel<robust_bvh<K, B>> {
public:
    std::string name() const override { return std::string("ch15-") + ch15::name(K) + "-" + ch15::name(B); }
    void build(const scene& s) override {
        set_ = triangle_tests<K>(s.mesh);
        this->set_frame(ray_frame(s.mesh.bounds()));
        std::vector<aabb> boxes(set_.size());
        std::vector<vec3> centroids(set_.size());
        for (std::size_t i = 0; i < boxes.size(); ++i) boxes[i] = set_.bounds(i), centroids[i] = boxes[i].centroid();
        tree_ = ch05::build_sah_bvh_fast(boxes, centroids);
    }
    template <class Stats>
    hit closest(const ray& query, Stats& stats) const {
        return tree_closest_with(set_, tree_.loose, query, stats, [&](ray& r, hit& best) {
            const auto c = set_.prepare(r);
            walk<B>(tree_, r, stats, [&](std::uint32_t first, std::uint32_t count) {
                for (std::uint32_t k = 0; k < count; ++k)
                    stats.prim_test(), set_.intersect(tree_.prim_ids[first + k], r, c, best);
                return false;
            });
        });
    }
    template <class Stats>
    bool any(const ray& query, Stats& stats) const {
        return tree_any_with(set_, tree_.loose, query, stats, [&](ray& r) {
            const auto c = set_.prepare(r);
            bool found = false;
            walk<B>(tree_, r, stats, [&](std::uint32_t first, std::uint32_t count) {
                for (std::uint32_t k = 0; k < count; ++k)
                    if (stats.prim_test(), set_.occludes(tree_.prim_ids[first + k], r, c)) return found = true;
                return false;
            });
            return found;
        });
    }
    std::size_t memory_bytes() const override { return tree_.memory_bytes() + set_.memory_bytes(); }
    std::optional<double> sah_cost() const override { return ch04::sah_tree_cost(tree_, 1.0f, 1.0f); }
    // The plain box test loses rays through boxes' edges and corners: not exact, by design (the race counts
    // its differences as it counts Embree's).
    bool exact() const override { return B != box_kind::plain; }
    const ch04::bvh& tree() const { return tree_; }

private:
    triangle_tests<K> set_{triangle_mesh{}};
    ch04::bvh tree_;
};

}  // namespace strahl::ch15
