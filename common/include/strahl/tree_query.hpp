// What every tree (chapter 03's k-d tree, chapter 04's BVH, and the ones after them) does around its own
// traversal, written once:
//   - rays it cannot place (a NaN or Inf component, a zero or vanishing direction) get brute force's
//     answer: every primitive in id order, no t-range arithmetic, no endless loop;
//   - "loose" primitives (non-finite boxes, left out of the tree) are tested by every ray;
//   - the leaf test: every primitive of a leaf through the set's intersect()/occludes() (the tie-correct
//     closest-hit step of chapter 01's primitive sets), counted.
// The structure hands over its traversal as walk(r, leaf), which calls leaf(ids, count) for each leaf it
// reaches, reads r.tmax (shrunk by each hit) to prune, and stops when leaf returns true.
#pragma once
#include "strahl/aabb.hpp"
#include "strahl/ray.hpp"
#include <cmath>
#include <cstdint>
#include <span>

namespace strahl {

// Whether t-range arithmetic on r is meaningful: finite origin and direction, a direction that does not
// vanish, an origin not absurdly far out.
inline bool placeable(const ray& r) {
    const float d2 = glm::dot(r.dir, r.dir);
    return std::isfinite(r.org.x) && std::isfinite(r.org.y) && std::isfinite(r.org.z) && std::isfinite(d2) &&
           d2 > 1e-30f && glm::dot(r.org, r.org) < 1e36f;
}

// The ray's slack, in t units: how far the triangle test's computed t may stray from the exact t of a box
// around the triangle. Relative 2^-16 of the farthest t inside the box plus 1e-5 of its diagonal. Trees
// widen their box and plane tests by it, so no primitive whose computed hit could win is lost.
inline float ray_slack(const ray& r, const aabb& box) {
    const float len = glm::length(r.dir);
    const float diag = glm::length(box.extent());
    const float reach = glm::length(r.org - box.centroid()) + diag;
    return (reach * 0x1p-16f + 1e-5f * diag) / len;
}

// The ray's slack in space: how far beside a box (or a split plane) a ray may pass and still get a hit from
// the triangle test's rounding. Moeller-Trumbore's u and v carry an absolute error of a few 2^-24
// |org - v0|, so a ray passing that close beside a triangle can be accepted; brute force reports the hit,
// and a tree must not cull the box. 2^-20 of the largest coordinate of the tree's box plus the origin's,
// on every axis: at least 16 times that error. Trees grow their boxes (and split planes) by it wherever a
// direction component is zero or tiny; chapter 05's fast slab test grows them by its own, like, bound.
inline float space_slack(const ray& r, const aabb& box) {
    const vec3 p = glm::max(glm::abs(box.min), glm::abs(box.max)), o = glm::abs(r.org);
    return 0x1p-20f * (std::max(std::max(p.x, p.y), p.z) + std::max(std::max(o.x, o.y), o.z));
}
inline aabb grown(const aabb& box, float by) { return {box.min - vec3(by), box.max + vec3(by)}; }

// The rules above around a structure's own descent: descend(r, best) for closest hit, descend(r) -> found
// for any hit, called only for a placeable ray with a non-empty interval, after the loose primitives.
// tree_closest and tree_any below descend through leaves of primitive ids; a structure whose leaves hold
// something else (chapter 13's triangle blocks) calls these directly.
template <class Set, class Stats, class Descend>
hit tree_closest_with(const Set& set, std::span<const std::uint32_t> loose, const ray& query, Stats& stats,
                      Descend&& descend) {
    stats.ray();
    hit best;
    if (!(query.tmin < query.tmax)) return best;  // an empty (or NaN) interval: a miss
    ray r = query;
    for (const std::uint32_t id : loose) stats.prim_test(), set.intersect(id, r, best);
    if (!placeable(r)) {
        for (std::uint32_t id = 0; id < set.size(); ++id) stats.prim_test(), set.intersect(id, r, best);
        return best;
    }
    descend(r, best);
    return best;
}

template <class Set, class Stats, class Descend>
bool tree_any_with(const Set& set, std::span<const std::uint32_t> loose, const ray& query, Stats& stats,
                   Descend&& descend) {
    stats.ray();
    if (!(query.tmin < query.tmax)) return false;
    for (const std::uint32_t id : loose)
        if (stats.prim_test(), set.occludes(id, query)) return true;
    if (!placeable(query)) {
        for (std::uint32_t id = 0; id < set.size(); ++id)
            if (stats.prim_test(), set.occludes(id, query)) return true;
        return false;
    }
    ray r = query;
    return descend(r);
}

template <class Set, class Stats, class Walk>
hit tree_closest(const Set& set, std::span<const std::uint32_t> loose, const ray& query, Stats& stats, Walk&& walk) {
    return tree_closest_with(set, loose, query, stats, [&](ray& r, hit& best) {
        walk(r, [&](const std::uint32_t* ids, std::uint32_t count) {
            for (std::uint32_t k = 0; k < count; ++k) stats.prim_test(), set.intersect(ids[k], r, best);
            return false;  // a closest-hit query visits every leaf the (shrinking) r.tmax still reaches
        });
    });
}

template <class Set, class Stats, class Walk>
bool tree_any(const Set& set, std::span<const std::uint32_t> loose, const ray& query, Stats& stats, Walk&& walk) {
    return tree_any_with(set, loose, query, stats, [&](ray& r) {
        bool found = false;
        walk(r, [&](const std::uint32_t* ids, std::uint32_t count) {
            for (std::uint32_t k = 0; k < count && !found; ++k) stats.prim_test(), found = set.occludes(ids[k], query);
            return found;  // any hit ends the walk
        });
        return found;
    });
}

}  // namespace strahl
