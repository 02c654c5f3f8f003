// The six steps' structures (steps.hpp), as class templates: where each is compiled decides what the
// compiler can inline into its walk, so steps 2, 5 and 6 are instantiated in the same file as exercises
// 11.1 and 11.2 (steps_impl.hpp, included at the end of leaf_tests.cpp), steps 1, 3 and 4 in src/steps.cpp,
// where the triangle test is a call into another file.
//
// All share chapter 05's binned SAH tree, chapter 05's fast walk, and tree_query.hpp's rules around it
// (loose primitives first, brute force for rays no tree can place). Each keeps every primitive in "slots":
// steps 1 and 2 index slots by primitive id; steps 3 to 6 keep their arrays in leaf order and record each
// slot's id, which the tie rule and the hit need.
#pragma once
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch01/shapes.hpp"
#include "strahl/ch05/fast_traverse.hpp"
#include "strahl/ch05/sah.hpp"
#include "strahl/ch11/shapes.hpp"
#include "strahl/ch11/steps.hpp"
#include "strahl/ch11/triangles.hpp"
#include "strahl/ch11/type_sorted.hpp"
#include "strahl/inlining.hpp"
#include "strahl/tree_query.hpp"

namespace strahl::ch11 {

// What the renderer needs about a closest hit: the point, the unit normal turned towards the ray, the
// material id (chapter 01's world::closest_hit computes the same).
struct surface {
    hit h;
    vec3 p{0.0f}, n{0.0f};
    std::uint32_t material = 0;
};

// Chapter 05's binned SAH tree over the primitives' boxes (the same boxes in every step: the same tree).
ch04::bvh build_tree(std::span<const aabb> boxes);

// ---- Steps 1 and 2: a set indexed by primitive id, leaves of ids (chapter 04's leaf layout) ----

// Step 1's set: chapter 01's objects, a virtual call per test.
class virtual_set {
public:
    explicit virtual_set(const std::vector<shape>& shapes);
    std::size_t size() const { return objects_.size(); }
    aabb bounds(std::size_t i) const { return objects_[i]->bounds(); }
    bool intersect(std::uint32_t i, ray& r, hit& best) const {
        hit h;
        return objects_[i]->intersect(r, h) && ch01::record_closest(i, h.t, h.u, h.v, r, best);
    }
    bool occludes(std::uint32_t i, const ray& r) const {
        hit h;
        return objects_[i]->intersect(r, h);
    }
    vec3 normal(std::uint32_t i, const vec3& p, const hit& h) const { return objects_[i]->normal(p, h); }
    std::size_t memory_bytes() const;

private:
    std::vector<std::unique_ptr<ch01::primitive>> objects_;
};

// Step 2's set: the variant array, exercise 11.1's visit per test.
class variant_set {
public:
    explicit variant_set(std::vector<shape> shapes) : shapes_(std::move(shapes)) {}
    std::size_t size() const { return shapes_.size(); }
    aabb bounds(std::size_t i) const { return ch11::bounds(shapes_[i]); }
    bool intersect(std::uint32_t i, ray& r, hit& best) const {
        float t, u, v;
        return ch11::intersect(shapes_[i], r, t, u, v) && ch01::record_closest(i, t, u, v, r, best);
    }
    bool occludes(std::uint32_t i, const ray& r) const {
        float t, u, v;
        return ch11::intersect(shapes_[i], r, t, u, v);
    }
    vec3 normal(std::uint32_t i, const vec3& p, const hit&) const { return normal_at(shapes_[i], p); }
    std::size_t memory_bytes() const { return shapes_.size() * sizeof(shape); }

private:
    std::vector<shape> shapes_;
};

// The shared part of every step: name, material ids, the tree, the renderer's surface.
template <class Derived>
class step_base : public per_ray_accel<Derived, step_accel> {
public:
    step_base(step s, bool with_shapes) : step_(s), with_shapes_(with_shapes) {}
    std::string name() const override { return std::string("ch11-") + info(step_).name; }
    const ch04::bvh& tree() const override { return tree_; }
    std::optional<double> sah_cost() const override { return ch04::sah_tree_cost(tree_, 1.0f, 1.0f); }

    // The renderer's queries (no counting, no virtual call).
    bool closest_surface(const ray& r, surface& s) const {
        not_counting none;
        const hit h = static_cast<const Derived&>(*this).closest(r, none);
        if (!h.found()) return false;
        s.h = h;
        s.p = r.at(h.t);
        s.n = static_cast<const Derived&>(*this).normal(h.prim, s.p, h);
        if (glm::dot(s.n, r.dir) > 0.0f) s.n = -s.n;  // two-sided: face the incoming ray
        s.material = materials_[h.prim];
        return true;
    }
    bool occluded_ray(const ray& r) const {
        not_counting none;
        return static_cast<const Derived&>(*this).any(r, none);
    }

protected:
    std::vector<shape> shapes_of(const scene& s) {
        // The frame of everything the structure holds: the spheres and planes too where it takes them.
        this->set_frame(with_shapes_ ? ray_frame::of_scene(s) : ray_frame(s.mesh.bounds()));
        materials_ = make_material_ids(s, with_shapes_);
        return make_shapes(s, with_shapes_);
    }
    std::size_t base_bytes() const { return tree_.memory_bytes() + tree_.loose.size() * 4; }

    step step_;
    bool with_shapes_;
    std::vector<std::uint32_t> materials_;  // by primitive id (for the renderer; not counted as the structure's)
    ch04::bvh tree_;
};

template <class Set>
class indexed_accel final : public step_base<indexed_accel<Set>> {
    using base = step_base<indexed_accel<Set>>;

public:
    using base::base;

    void build(const scene& s) override {
        set_ = std::make_unique<Set>(this->shapes_of(s));
        std::vector<aabb> boxes(set_->size());
        for (std::size_t i = 0; i < boxes.size(); ++i) boxes[i] = set_->bounds(i);
        this->tree_ = build_tree(boxes);
    }
    std::size_t memory_bytes() const override { return this->base_bytes() + (set_ ? set_->memory_bytes() : 0); }

    template <class Stats>
    STRAHL_FLATTEN hit closest(const ray& query, Stats& stats) const {
        if (!set_) return hit{};
        return tree_closest(*set_, this->tree_.loose, query, stats, [&](ray& r, auto&& leaf) { walk(r, stats, leaf); });
    }
    template <class Stats>
    STRAHL_FLATTEN bool any(const ray& query, Stats& stats) const {
        if (!set_) return false;
        return tree_any(*set_, this->tree_.loose, query, stats, [&](ray& r, auto&& leaf) { walk(r, stats, leaf); });
    }
    vec3 normal(std::uint32_t id, const vec3& p, const hit& h) const { return set_->normal(id, p, h); }

private:
    template <class Stats, class Leaf>
    void walk(ray& r, Stats& stats, Leaf& leaf) const {
        ch05::fast_traverse(this->tree_, r, stats, [&](std::uint32_t first, std::uint32_t count) {
            return leaf(this->tree_.prim_ids.data() + first, count);
        });
    }

    std::unique_ptr<Set> set_;
};

// ---- Steps 3 to 6: arrays in leaf order, tested by slot ----

// The fallback's view of a step's slots (loose primitives, rays no tree can place): slot k's test through
// the step's own per-type code, recording the slot's primitive id. Used off the hot path only.
template <class Step>
struct slot_set {
    const Step& step;
    std::size_t size() const { return step.slot_count(); }
    bool intersect(std::uint32_t k, ray& r, hit& best) const {
        float t, u, v;
        return step.test_slot(k, r, t, u, v) && ch01::record_closest(step.slot_id(k), t, u, v, r, best);
    }
    bool occludes(std::uint32_t k, const ray& r) const {
        float t, u, v;
        return step.test_slot(k, r, t, u, v);
    }
};

// Step 3. Slots: the triangles, then the spheres, then the planes, each array in leaf order (the loose
// primitives, which no leaf holds, at the ends). A leaf node's offset is its index in leaves_.
class sorted_accel final : public step_base<sorted_accel> {
public:
    using step_base::step_base;

    void build(const scene& s) override;
    std::size_t memory_bytes() const override {
        return base_bytes() + prims_.memory_bytes() + leaves_.size() * sizeof(sorted_leaf);
    }

    template <class Stats>
    STRAHL_FLATTEN hit closest(const ray& query, Stats& stats) const {
        return tree_closest_with(slot_set<sorted_accel>{*this}, loose_, query, stats, [&](ray& r, hit& best) {
            ch05::fast_traverse(tree_, r, stats, [&](std::uint32_t leaf, std::uint32_t) {
                test_leaf(leaves_[leaf], r, stats, [&](std::uint32_t id, float t, float u, float v) {
                    ch01::record_closest(id, t, u, v, r, best);
                    return false;
                });
                return false;
            });
        });
    }
    template <class Stats>
    STRAHL_FLATTEN bool any(const ray& query, Stats& stats) const {
        return tree_any_with(slot_set<sorted_accel>{*this}, loose_, query, stats, [&](ray& r) {
            bool found = false;
            ch05::fast_traverse(tree_, r, stats, [&](std::uint32_t leaf, std::uint32_t) {
                return found = test_leaf(leaves_[leaf], r, stats, [](std::uint32_t, float, float, float) { return true; });
            });
            return found;
        });
    }
    vec3 normal(std::uint32_t id, const vec3& p, const hit&) const { return normal_at(shapes_by_id_[id], p); }

    std::size_t slot_count() const;
    std::uint32_t slot_id(std::uint32_t k) const;
    bool test_slot(std::uint32_t k, const ray& r, float& t, float& u, float& v) const;

private:
    // One loop per type, no branch on the type inside; found(id, t, u, v) returns true to stop.
    template <class Stats, class Found>
    bool test_leaf(const sorted_leaf& l, const ray& r, Stats& stats, Found&& found) const {
        float t, u, v;
        for (std::uint32_t k = l.first[0], e = k + l.count[0]; k < e; ++k) {
            const triangle_shape& tri = prims_.triangles[k];
            stats.prim_test();
            if (ch01::intersect_triangle(r, tri.v0, tri.v1, tri.v2, t, u, v) && found(prims_.ids[0][k], t, u, v))
                return true;
        }
        for (std::uint32_t k = l.first[1], e = k + l.count[1]; k < e; ++k) {
            stats.prim_test();
            if (ch01::intersect_sphere(r, prims_.spheres[k].center, prims_.spheres[k].radius, t) &&
                found(prims_.ids[1][k], t, 0.0f, 0.0f))
                return true;
        }
        for (std::uint32_t k = l.first[2], e = k + l.count[2]; k < e; ++k) {
            stats.prim_test();
            if (ch01::intersect_plane(r, prims_.planes[k].normal, prims_.planes[k].offset, t) &&
                found(prims_.ids[2][k], t, 0.0f, 0.0f))
                return true;
        }
        return false;
    }

    sorted_primitives prims_;
    std::vector<sorted_leaf> leaves_;
    std::vector<std::uint32_t> loose_;    // slots of the loose primitives
    std::vector<shape> shapes_by_id_;     // for the renderer's normals (not counted as the structure's)
};

// Steps 4 to 6. Slots: the triangles in leaf order (loose ones at the end), then the spheres, then the
// planes; the spheres and planes, and loose triangles, are tested by every ray before the walk (their own
// loop). Storage: std::vector<edge_triangle> (array of structures) or edge_triangles_soa.
template <class Storage, step Step>
class triangle_accel final : public step_base<triangle_accel<Storage, Step>> {
    using base = step_base<triangle_accel<Storage, Step>>;

public:
    using base::base;

    void build(const scene& s) override {
        const std::vector<shape> shapes = this->shapes_of(s);
        const std::size_t n_tri = s.mesh.triangle_count();
        std::vector<aabb> boxes(n_tri);
        for (std::size_t i = 0; i < n_tri; ++i) boxes[i] = ch11::bounds(shapes[i]);
        this->tree_ = build_tree(boxes);
        // The triangles in leaf order (the tree's id array), the loose ones after them.
        tris_ = Storage{};
        ids_.clear(), loose_.clear(), spheres_.clear(), planes_.clear();
        slot_of_.assign(n_tri, 0);
        const auto add = [&](std::uint32_t id) {
            const triangle_shape& t = std::get<triangle_shape>(shapes[id]);
            slot_of_[id] = std::uint32_t(ids_.size());
            tris_.push_back(make_edge_triangle(t.v0, t.v1, t.v2));
            ids_.push_back(id);
        };
        for (const std::uint32_t id : this->tree_.prim_ids) add(id);
        for (const std::uint32_t id : this->tree_.loose) loose_.push_back(std::uint32_t(ids_.size())), add(id);
        for (std::uint32_t id = std::uint32_t(n_tri); id < shapes.size(); ++id) {
            if (const auto* sp = std::get_if<sphere_shape>(&shapes[id])) spheres_.push_back({*sp, id});
            if (const auto* pl = std::get_if<plane_shape>(&shapes[id])) planes_.push_back({*pl, id});
        }
        for (std::size_t k = ids_.size(); k < slot_count(); ++k) loose_.push_back(std::uint32_t(k));
    }
    std::size_t memory_bytes() const override {
        return this->tree_.nodes.size() * sizeof(ch04::bvh_node) + storage_bytes() + ids_.size() * 4 +
               loose_.size() * 4 + spheres_.size() * sizeof(spheres_[0]) + planes_.size() * sizeof(planes_[0]);
    }

    template <class Stats>
    STRAHL_FLATTEN hit closest(const ray& query, Stats& stats) const {
        return tree_closest_with(slot_set<triangle_accel>{*this}, loose_, query, stats, [&](ray& r, hit& best) {
            ch05::fast_traverse(this->tree_, r, stats, [&](std::uint32_t first, std::uint32_t count) {
                for (std::uint32_t k = first; k < first + count; ++k) {
                    float t, u, v;
                    stats.prim_test();
                    if (test_triangle(k, r, t, u, v)) ch01::record_closest(ids_[k], t, u, v, r, best);
                }
                return false;
            });
        });
    }
    template <class Stats>
    STRAHL_FLATTEN bool any(const ray& query, Stats& stats) const {
        return tree_any_with(slot_set<triangle_accel>{*this}, loose_, query, stats, [&](ray& r) {
            bool found = false;
            ch05::fast_traverse(this->tree_, r, stats, [&](std::uint32_t first, std::uint32_t count) {
                for (std::uint32_t k = first; k < first + count && !found; ++k) {
                    float t, u, v;
                    stats.prim_test();
                    found = test_triangle(k, r, t, u, v);
                }
                return found;
            });
            return found;
        });
    }
    // A triangle's normal from its edges: cross(e1, e2) is chapter 01's cross(v1 - v0, v2 - v0).
    vec3 normal(std::uint32_t id, const vec3& p, const hit&) const {
        if (id < slot_of_.size()) {
            const edge_triangle t = triangle_at(slot_of_[id]);
            const vec3 c = glm::cross(t.e1, t.e2);
            const float len = glm::length(c);
            return len > 0.0f ? c / len : vec3(0.0f, 0.0f, 1.0f);
        }
        for (const auto& s : spheres_)
            if (s.id == id) return normal_at(shape(s.s), p);
        for (const auto& pl : planes_)
            if (pl.id == id) return pl.p.normal;
        return vec3(0.0f, 0.0f, 1.0f);
    }

    std::size_t slot_count() const { return ids_.size() + spheres_.size() + planes_.size(); }
    std::uint32_t slot_id(std::uint32_t k) const {
        if (k < ids_.size()) return ids_[k];
        k -= std::uint32_t(ids_.size());
        return k < spheres_.size() ? spheres_[k].id : planes_[k - spheres_.size()].id;
    }
    bool test_slot(std::uint32_t k, const ray& r, float& t, float& u, float& v) const {
        if (k < ids_.size()) return test_triangle(k, r, t, u, v);
        k -= std::uint32_t(ids_.size());
        u = v = 0.0f;
        if (k < spheres_.size()) return ch01::intersect_sphere(r, spheres_[k].s.center, spheres_[k].s.radius, t);
        const plane_shape& p = planes_[k - spheres_.size()].p;
        return ch01::intersect_plane(r, p.normal, p.offset, t);
    }

private:
    edge_triangle triangle_at(std::uint32_t k) const { return tris_[k]; }
    // Exercise 11.2's test on slot k: a call where this is compiled apart from leaf_tests.cpp (step 4),
    // inlined where it is compiled with it (steps 5 and 6).
    bool test_triangle(std::uint32_t k, const ray& r, float& t, float& u, float& v) const {
        if constexpr (std::is_same_v<Storage, edge_triangles_soa>) {
            const vec3 v0(tris_.c[0][k], tris_.c[1][k], tris_.c[2][k]);
            const vec3 e1(tris_.c[3][k], tris_.c[4][k], tris_.c[5][k]);
            const vec3 e2(tris_.c[6][k], tris_.c[7][k], tris_.c[8][k]);
            return intersect_edges(r, v0, e1, e2, t, u, v);
        } else {
            const edge_triangle& e = tris_[k];
            return intersect_edges(r, e.v0, e.e1, e.e2, t, u, v);
        }
    }
    std::size_t storage_bytes() const {
        if constexpr (std::is_same_v<Storage, edge_triangles_soa>)
            return tris_.memory_bytes();
        else
            return tris_.size() * sizeof(edge_triangle);
    }

    struct sphere_slot {
        sphere_shape s;
        std::uint32_t id;
    };
    struct plane_slot {
        plane_shape p;
        std::uint32_t id;
    };
    Storage tris_;
    std::vector<std::uint32_t> ids_;      // slot -> triangle id
    std::vector<std::uint32_t> loose_;    // slots tested by every ray: loose triangles, spheres, planes
    std::vector<sphere_slot> spheres_;
    std::vector<plane_slot> planes_;
    std::vector<std::uint32_t> slot_of_;  // triangle id -> slot (the renderer's normals only)
};

// One type per step (the Step argument), so that each is compiled in one file only: steps 4 and 5 are the
// same code, compiled where the triangle test is a call and where it is inlined.
using triangles_accel = triangle_accel<std::vector<edge_triangle>, step::triangles_only>;
using inlined_accel = triangle_accel<std::vector<edge_triangle>, step::inlined>;
using soa_accel = triangle_accel<edge_triangles_soa, step::soa>;

}  // namespace strahl::ch11
