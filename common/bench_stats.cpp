// Measures what stats.hpp claims: traversal-shaped code templated on counters<false> runs as fast as the
// same code with no counting at all, while counters<true> costs a little. A benchmark, not a test: it
// prints medians of 7 runs and the ratios, in one process, and asserts nothing.
#include "strahl/aabb.hpp"
#include "strahl/program.hpp"
#include "strahl/rng.hpp"
#include "strahl/stats.hpp"
#include "strahl/timer.hpp"
#include <cstdio>
#include <vector>

using namespace strahl;

namespace {

// A slab test of one ray against many boxes: the shape of a BVH's inner loop.
template <class Stats>
int count_hits(const std::vector<aabb>& boxes, vec3 org, vec3 inv_dir, Stats& stats) {
    int hits = 0;
    for (const aabb& b : boxes) {
        stats.box_test();
        const vec3 t0 = (b.min - org) * inv_dir, t1 = (b.max - org) * inv_dir;
        const vec3 lo = glm::min(t0, t1), hi = glm::max(t0, t1);
        const float enter = std::max(std::max(lo.x, lo.y), std::max(lo.z, 0.0f));
        const float leave = std::min(std::min(hi.x, hi.y), hi.z);
        if (enter <= leave) {  // data-dependent, like a traversal: the count cannot be hoisted out of the loop
            stats.prim_test();
            ++hits;
        }
    }
    return hits;
}

int count_hits_plain(const std::vector<aabb>& boxes, vec3 org, vec3 inv_dir) {
    int hits = 0;
    for (const aabb& b : boxes) {
        const vec3 t0 = (b.min - org) * inv_dir, t1 = (b.max - org) * inv_dir;
        const vec3 lo = glm::min(t0, t1), hi = glm::max(t0, t1);
        const float enter = std::max(std::max(lo.x, lo.y), std::max(lo.z, 0.0f));
        const float leave = std::min(std::min(hi.x, hi.y), hi.z);
        hits += enter <= leave;
    }
    return hits;
}

int run(int argc, const char* const* argv) {
    cli args("bench_stats", "Times a slab-test loop without counters, with counters<false> and with counters<true>.");
    args.option("boxes", "N", "100000", "boxes per ray").option("rays", "N", "200", "rays per run");
    if (!args.parse(argc, argv)) return 0;
    const int n = args.get_int("boxes"), rays = args.get_int("rays");
    if (n <= 0 || rays <= 0) throw usage_error("--boxes and --rays must be positive");
    pcg32 rng(7);
    std::vector<aabb> boxes(n);
    for (aabb& b : boxes) {
        const vec3 p(rng.next_float(), rng.next_float(), rng.next_float());
        b = aabb::from_points(p, p + 0.01f);
    }
    std::vector<vec3> dirs(rays);
    for (vec3& d : dirs) d = glm::normalize(vec3(rng.next_float() - 0.5f, rng.next_float() - 0.5f, 1.0f));

    long sink = 0;
    not_counting off;
    counting on;
    auto one_run = [&](int variant) {
        timer t;
        const vec3 org(0.5f, 0.5f, -1.0f);
        for (const vec3& d : dirs) {
            const vec3 inv = 1.0f / d;
            sink += variant == 0 ? count_hits_plain(boxes, org, inv)
                  : variant == 1 ? count_hits(boxes, org, inv, off)
                                 : count_hits(boxes, org, inv, on);
        }
        return t.milliseconds();
    };
    // Variants take turns, after one warm-up round, so drift in the machine's speed hits all three alike.
    std::vector<double> ms[3];
    for (int rep = 0; rep < 8; ++rep)
        for (int variant = 0; variant < 3; ++variant) {
            const double t = one_run(variant);
            if (rep > 0) ms[variant].push_back(t);
        }
    const double plain = median(ms[0]), with_off = median(ms[1]), with_on = median(ms[2]);
    const double tests = double(n) * rays;
    std::printf("%-22s %10s %14s %8s\n", "variant", "median ms", "Mtests/s", "ratio");
    std::printf("%-22s %10.2f %14.1f %8.3f\n", "no counters", plain, tests / plain / 1e3, 1.0);
    std::printf("%-22s %10.2f %14.1f %8.3f\n", "counters<false>", with_off, tests / with_off / 1e3, with_off / plain);
    std::printf("%-22s %10.2f %14.1f %8.3f\n", "counters<true>", with_on, tests / with_on / 1e3, with_on / plain);
    std::printf("(medians of 7 runs after a warm-up, %d rays x %d boxes; box tests counted: %llu; checksum %ld)\n", rays, n,
                (unsigned long long)on.values().box_tests, sink);
    return 0;
}

}  // namespace

int main(int argc, char** argv) { return guarded_main("bench_stats", run, argc, argv); }
