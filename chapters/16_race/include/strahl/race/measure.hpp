// Measuring one structure on one ray set, the same way for every structure: build time (median of timed
// builds after a warm-up), memory, SAH cost,
// Mrays/s of closest-hit and any-hit queries (median of timed runs after a warm-up), tests per ray from a
// counting run, and how many rays' results differ from the reference (brute force).
#pragma once
#include "strahl/accel.hpp"
#include "strahl/race/ray_sets.hpp"
#include <optional>
#include <string>
#include <vector>

namespace strahl::race {

// The exact answers for one ray set, from brute force.
struct reference {
    std::vector<hit> closest;
    std::vector<std::uint8_t> any;
};

struct timing_rules {
    int repeats = 5;           // timed runs after one warm-up run
    double budget_s = 4.0;     // stop repeating once this much time went into one query (at least 1 run)
    int threads = 1;
    std::size_t count_rays = 8192;  // the counting run uses every k-th ray, at most this many
    int cpu = -1;  // with one thread: builds and queries timed on this CPU alone (pinned_thread); -1: anywhere
};

// The counting run's sample: every k-th block of `block` consecutive rays (the last may be short), whole,
// at most about `limit` rays (at least one block). block = the structure's batch_alignment(): a packet tracer
// counts on whole tile rows, the packets the timed runs trace, not on packets of rays far apart.
std::vector<ray> counting_sample(std::span<const ray> rays, std::size_t limit, std::size_t block);

struct query_result {
    double mrays = 0.0;       // median, million rays per second
    int runs = 0;             // timed runs behind the median
    std::size_t rays = 0;     // rays per run
    std::size_t differing = 0;  // rays whose result differs from the reference (see agrees())
    std::optional<double> box_per_ray, prim_per_ray, nodes_per_ray;
};

// Build time in ms: a.build(s) once as a warm-up, then timed as the queries are (up to rules.repeats
// builds within the budget), the median. Only the first build of a process pays for fresh memory pages
// (on a virtual machine a page fault costs microseconds); the median is the steady cost of a rebuild.
double measure_build(accel& a, const scene& s, const timing_rules& rules);

// Times a.intersect (closest) or a.occluded (any) on rays and compares with the reference.
query_result measure_closest(const accel& a, std::span<const ray> rays, const std::vector<hit>& ref,
                             const timing_rules& rules);
query_result measure_any(const accel& a, std::span<const ray> rays, const std::vector<std::uint8_t>& ref,
                         const timing_rules& rules);

// Whether a closest hit agrees with the reference. For the course's structures (exact): both misses, or
// the same primitive with bit-identical t, u and v. For Embree, whose triangle test rounds differently:
// both misses, or the same primitive.
bool agrees(const hit& a, const hit& reference, bool exact);

}  // namespace strahl::race
