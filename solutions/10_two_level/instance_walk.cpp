// Exercise 10.3 the two-level walk (4 points). Read: two_level.hpp, and any() and blocks() in
// chapters/10_two_level/src/two_level.cpp (the any-hit walk, the model for this one); I. Wald, C. Benthin
// and P. Slusallek, "A simple and practical method for interactive ray tracing of dynamic scenes",
// Saarland University, 2002, section 3; pbrt-v4, section 7.1.5 (instances).
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch01/shapes.hpp"
#include "strahl/ch05/fast_traverse.hpp"
#include "strahl/ch10/object_ray.hpp"
#include "strahl/ch10/two_level.hpp"
#include "strahl/tree_query.hpp"

namespace strahl::ch10 {

// Instance k's mesh, for the world ray r (its tmax the closest hit so far): the ray moved into object space,
// chapter 05's walk through the mesh's tree, each hit recorded under its flattened id; r.tmax follows.
template <class Stats>
void two_level::visit(std::uint32_t k, ray& r, hit& best, Stats& stats) const {
    const instance_data& inst = instances_[k];
    const mesh_data& m = meshes_[inst.mesh];
    ray o = inst.identity ? r : to_object(r, inst.to_object);
    o.tmax = r.tmax;
    const auto test = [&](std::uint32_t id) {
        float t, u, v;
        stats.prim_test();
        const auto& tri = m.triangles[id];
        if (ch01::intersect_triangle(o, tri[0], tri[1], tri[2], t, u, v) &&
            ch01::record_closest(inst.first_id + id, t, u, v, o, best))
            best.inst = k;
    };
    for (const std::uint32_t id : m.tree.loose) test(id);
    if (!placeable(o)) {
        // A ray the object space cannot place (a transform that shrinks the direction to nothing): every
        // triangle of the mesh, as brute force does.
        for (std::uint32_t id = 0; id < m.triangles.size(); ++id) test(id);
    } else if (!m.tree.nodes.empty()) {
        ch05::fast_traverse(m.tree, o, stats, [&](std::uint32_t first, std::uint32_t count) {
            for (std::uint32_t j = 0; j < count; ++j) test(m.tree.prim_ids[first + j]);
            return false;
        });
    }
    r.tmax = o.tmax;
}

template <class Stats>
hit two_level::closest(const ray& query, Stats& stats) const {
    stats.ray();
    hit best;
    if (!(query.tmin < query.tmax)) return best;
    ray r = query;
    if (!placeable(r)) {
        // Brute force's answer: every instance in order (visit() then tests every triangle of each).
        for (std::uint32_t k = 0; k < instances_.size(); ++k) visit(k, r, best, stats);
        return best;
    }
    if (!top_.nodes.empty())
        ch05::fast_traverse(top_, r, stats, [&](std::uint32_t first, std::uint32_t count) {
            for (std::uint32_t j = 0; j < count; ++j) visit(top_.prim_ids[first + j], r, best, stats);
            return false;
        });
    // Instances whose world box is not finite (a mesh of loose triangles only) sit outside the top level.
    for (const std::uint32_t k : top_.loose) visit(k, r, best, stats);
    return best;
}

template hit two_level::closest(const ray&, not_counting&) const;
template hit two_level::closest(const ray&, counting&) const;

}  // namespace strahl::ch10
