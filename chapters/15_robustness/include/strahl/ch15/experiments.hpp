// Chapter 15's measurements, as its program (ch15) runs them: closed spheres at many scales and distances
// from the origin, rays from inside aimed exactly at their vertices and edges (where cracks open), and
// secondary rays spawned from hit points with each offset of spawn.hpp (where self-hits and leaks happen).
#pragma once
#include "strahl/accel.hpp"
#include "strahl/ch15/robust_bvh.hpp"
#include "strahl/progress.hpp"
#include "strahl/rng.hpp"
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace strahl::ch15 {

// A sphere's size and place: the unit sphere scaled to radius `scale`, its centre at distance `place` from
// the origin along placement_direction (a direction with no zero component: every coordinate is large).
struct placement {
    float scale = 1.0f, place = 0.0f;
    vec3 centre() const;
    vec3 inside() const;  // the rays' origin: just off the centre, centre + (0.013, -0.021, 0.007) scale
    // Whether float can hold the sphere there: its radius is at least 2^-12 of its distance from the origin
    // (else its vertices lie a few ulps apart and the sphere is no longer a sphere).
    bool representable() const { return scale >= place * 0x1p-12f; }
};
vec3 placement_direction();  // normalize(0.6, -0.3, 0.74)

// The scales 1e-6, 1e-3, 1, 1e3, 1e7 at the distances 0, 1e3, 1e5, 1e6, 1e7 (all 25; see representable()).
std::vector<placement> all_placements();

// tessellated_sphere(stacks, slices), scaled and moved to p.
triangle_mesh placed_sphere(int stacks, int slices, const placement& p);

// A random point of the ideal sphere the mesh approximates: p.centre() + p.scale * a uniform direction
// (two of g's floats).
vec3 random_point(pcg32& g, const placement& p);

// The escape test's rays for one sphere, from p.inside() (exercise 15.4): first one aimed at every vertex,
// then one at each face side's edge midpoint (3 per triangle: an edge is aimed at from both of its
// triangles), then as many at random_point()s (g = pcg32(seed, 15)). Directions are target - origin (not
// normalised, |dir| about the radius).
enum class aim_kind { vertex, edge, random };
inline constexpr aim_kind all_aims[] = {aim_kind::vertex, aim_kind::edge, aim_kind::random};
const char* name(aim_kind k);
struct aimed_rays {
    std::vector<ray> rays;
    std::array<std::size_t, 4> bounds{};  // rays of kind k: [bounds[k], bounds[k + 1])
    std::size_t count(aim_kind k) const { return bounds[int(k) + 1] - bounds[int(k)]; }
};
aimed_rays make_aimed_rays(const triangle_mesh& m, const placement& p, std::uint64_t seed);
std::size_t aimed_ray_count(int stacks, int slices);  // make_aimed_rays's count for that sphere

// Which rays hit something (1) or nothing (0) through a's closest-hit query, in chunks on TBB's threads;
// each chunk's rays are added to `bar` (may be null).
std::vector<std::uint8_t> found(const accel& a, std::span<const ray> rays, progress_bar* bar);
// The rays of each kind that found nothing.
std::array<std::size_t, 3> escapes(const aimed_rays& r, const std::vector<std::uint8_t>& found);

// The spawn test. From p.inside(), rays at random points of the ideal sphere hit the mesh through `a`;
// each hit point is interpolated from the barycentrics, p = (1-u-v) v0 + u v1 + v v2, with the triangle's
// geometric normal n (unit, outward). From it, with the origin moved by the offset:
//   outward: a cosine-distributed direction around n: the sphere is convex, so any hit is a self-hit;
//   inward:  a cosine-distributed direction around -n at least 0.2 rad below the tangent plane (so that
//            the far side is at least a third of the radius away): a hit on the same triangle, or within
//            1e-3 of the radius, is a self-hit; no hit at all is a leak (the origin went through the wall).
// Every ray has tmin = 0 and |dir| = the radius. Rays that find no first hit spawn nothing.
enum class offset_kind { none, fixed, bounded, integer };
inline constexpr offset_kind all_offsets[] = {offset_kind::none, offset_kind::fixed, offset_kind::bounded,
                                              offset_kind::integer};
const char* name(offset_kind k);
const char* describe(offset_kind k);
inline constexpr float fixed_epsilon = 1e-4f;  // offset_fixed's epsilon

struct spawn_counts {
    std::size_t hit_points = 0;  // first hits found (of the rays asked for)
    std::size_t outward = 0, outward_self_hits = 0;
    std::size_t inward = 0, inward_self_hits = 0, leaks = 0;
    std::size_t rays() const { return outward + inward; }
    std::size_t self_hits() const { return outward_self_hits + inward_self_hits; }
    spawn_counts& operator+=(const spawn_counts& o);
};
// `points` first rays (deterministic for a seed, whatever the thread count); inward rays only if asked.
spawn_counts spawn_test(const accel& a, const triangle_mesh& m, const placement& p, offset_kind k,
                        std::size_t points, bool inward, std::uint64_t seed, progress_bar* bar);

// The small and the large extreme: a scene and its rays scaled about the origin by s, a power of two.
// Multiplying by a power of two changes no rounding while the results are normal floats (2^-126 to 2^128),
// so every hit the tests lose on a scaled copy is lost to underflow or overflow, never to rounding: a
// vertex p becomes s p, a ray's origin s org, its direction is kept (unit length, as the camera makes it),
// and a hit's t becomes s t. scale_steps(lo, hi): the power of two nearest 10^d for each decade d in
// [lo, hi] (2^-100 for 1e-30, 2^40 for 1e12).
std::vector<float> scale_steps(int lo_decade, int hi_decade);
triangle_mesh scaled(const triangle_mesh& m, float s);
std::vector<ray> scaled(std::span<const ray> rays, float s);
// The scale experiment's view: the teapot's primary rays, width x height, from 12 units along
// normalize(0.3, 0.4, 1) from (0.2, 1.4, 0), the field of view framing 2.5 units above and below.
std::vector<ray> scale_view_rays(int width, int height);
// How many of the rays find a hit through a's closest-hit query, in chunks of 64 on TBB's threads.
std::size_t count_hits(const accel& a, std::span<const ray> rays);
// The largest side of a mesh's bounding box (0 for an empty mesh): the extent scene.hpp's min_extent bounds.
float largest_side(const triangle_mesh& m);

}  // namespace strahl::ch15
