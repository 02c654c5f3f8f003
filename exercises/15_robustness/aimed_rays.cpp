// Exercise 15.4 the escape experiment's rays (4 points). Read: experiments.hpp (aimed_rays, placement);
// README.md, "The experiment" and section 1; S. Woop, C. Benthin and I. Wald, "Watertight ray/triangle
// intersection", JCGT 2(1), 2013 (the cracks this experiment looks for).
#include "strahl/ch15/experiments.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch15 {

// Goal: the experiment's rays for the closed mesh m (a sphere placed by p), all from p.inside(), tmin 0 and
// tmax inf, each direction the target less the origin (not normalised): first one ray at every vertex (in
// m.positions' order), then one at the midpoint 0.5 (a + b) of each side (a, b) = (f[k], f[(k + 1) % 3]) of
// every triangle f (in m.indices' order, k = 0, 1, 2), then as many rays as those two kinds together at
// random_point(g, p), with g = pcg32(seed, 15). out.bounds[k] .. out.bounds[k + 1] are the rays of kind k
// (bounds[0] = 0).
// Hint: count per triangle side, not per edge: an edge shared by two triangles is aimed at twice, once from
// each (the same ray twice: float addition commutes), so that the vertex, edge and random rays come in the
// counts aimed_ray_count() gives.
// Why: why aim at vertices and edges at all, when random rays at the same sphere find no crack, and what do
// the random rays then show?
aimed_rays make_aimed_rays(const triangle_mesh& m, const placement& p, std::uint64_t seed) {
    STRAHL_TODO("15.4 the escape experiment's rays");
}

}  // namespace strahl::ch15
