// Exercise 10.3 the two-level walk (4 points). Read: two_level.hpp, and any() and blocks() in
// chapters/10_two_level/src/two_level.cpp (the any-hit walk, the model for this one); I. Wald, C. Benthin
// and P. Slusallek, "A simple and practical method for interactive ray tracing of dynamic scenes",
// Saarland University, 2002, section 3; pbrt-v4, section 7.1.5 (instances).
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch01/shapes.hpp"
#include "strahl/ch05/fast_traverse.hpp"
#include "strahl/ch10/object_ray.hpp"
#include "strahl/ch10/two_level.hpp"
#include "strahl/todo.hpp"
#include "strahl/tree_query.hpp"

namespace strahl::ch10 {

// Goal (the hand-off): instance k's part of the closest hit. The world ray r, its tmax the closest hit so
// far, moved into the instance's object space (to_object, exercise 10.1; the world ray itself where
// inst.identity), walked through mesh inst.mesh's tree with chapter 05's fast_traverse, each triangle j
// tested with chapter 01's test and a hit recorded under its flattened id inst.first_id + j and instance k
// (best.inst); the mesh's loose triangles tested too, and every triangle where the object ray is not
// placeable, as blocks() does. Afterwards r.tmax is the object ray's.
// Hint: ch01::record_closest(id, t, u, v, ray, best) keeps the nearer hit (the lower id on a tie) and
// shortens the ray it is given.
// Why: why can the object ray's tmax be copied back to the world ray as it is, and what does the top
// level's walk gain from it?
template <class Stats>
void two_level::visit(std::uint32_t k, ray& r, hit& best, Stats& stats) const {
    STRAHL_TODO("10.3 the two-level walk");
}

// Goal (the top level): the closest hit over every instance. stats.ray() once; no hit for an empty
// interval; a world ray that is not placeable visits every instance in order (brute force's answer);
// otherwise chapter 05's fast_traverse over top_, whose leaf test visits each instance the leaf names
// (top_.prim_ids), then the instances outside the top level (top_.loose).
// Hint: any() in two_level.cpp is the same walk for the any-hit query.
// Why: the top level's leaves hold instances, not triangles: what in fast_traverse lets a hit found in
// one instance skip the boxes of instances behind it?
// Step by step: HINTS.md, 10.3.
template <class Stats>
hit two_level::closest(const ray& query, Stats& stats) const {
    STRAHL_TODO("10.3 the two-level walk");
}

// (Given: the two instantiations the chapter's accel and tests use.)
template hit two_level::closest(const ray&, not_counting&) const;
template hit two_level::closest(const ray&, counting&) const;

}  // namespace strahl::ch10
