#include "strahl/race/measure.hpp"
#include "strahl/parallel.hpp"
#include "strahl/timer.hpp"
#include <cstring>

namespace strahl::race {

namespace {

bool bits_equal(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Warm-up, then up to rules.repeats timed runs within the time budget; a warm-up that alone exceeds a
// quarter of the budget counts as the first timed run (slow structures on big scenes run once).
template <class Run>
std::vector<double> time_runs(const timing_rules& rules, Run&& run) {
    const pinned_thread pin(rules.threads == 1 ? rules.cpu : -1);
    std::vector<double> seconds;
    timer warm;
    run();
    const double first = warm.seconds();
    if (first > rules.budget_s / 4.0) return {first};
    double spent = first;
    for (int k = 0; k < rules.repeats && (k == 0 || spent < rules.budget_s); ++k) {
        timer t;
        run();
        seconds.push_back(t.seconds());
        spent += seconds.back();
    }
    return seconds;
}

void per_ray(query_result& q, const std::optional<counter_values>& c) {
    if (!c || c->rays == 0) return;
    q.box_per_ray = c->per_ray(c->box_tests);
    q.prim_per_ray = c->per_ray(c->prim_tests);
    q.nodes_per_ray = c->per_ray(c->nodes_visited);
}

}  // namespace

std::vector<ray> counting_sample(std::span<const ray> rays, std::size_t limit, std::size_t block) {
    block = std::max<std::size_t>(1, block);
    const std::size_t blocks = (rays.size() + block - 1) / block;
    const std::size_t wanted = std::max<std::size_t>(1, limit / block);
    const std::size_t stride = std::max<std::size_t>(1, (blocks + wanted - 1) / wanted);
    std::vector<ray> out;
    for (std::size_t b = 0; b < blocks; b += stride) {
        const std::size_t first = b * block, last = std::min(rays.size(), first + block);
        out.insert(out.end(), rays.begin() + std::ptrdiff_t(first), rays.begin() + std::ptrdiff_t(last));
    }
    return out;
}

bool agrees(const hit& a, const hit& b, bool exact) {
    if (!a.found() || !b.found()) return a.found() == b.found();
    if (!exact) return a.prim == b.prim;
    return a.prim == b.prim && bits_equal(a.t, b.t) && bits_equal(a.u, b.u) && bits_equal(a.v, b.v);
}

double measure_build(accel& a, const scene& s, const timing_rules& rules) {
    // The course's parallel builders (TBB) get the race's thread count, as Embree's device does: a build
    // time in the single-thread table is a single-thread time.
    const thread_limit limit(rules.threads);
    return 1e3 * median(time_runs(rules, [&] { a.build(s); }));
}

query_result measure_closest(const accel& a, std::span<const ray> rays, const std::vector<hit>& ref,
                             const timing_rules& rules) {
    query_result q;
    q.rays = rays.size();
    std::vector<hit> hits(rays.size());
    const std::vector<double> s = time_runs(rules, [&] { trace_closest(a, rays, hits, rules.threads); });
    q.runs = int(s.size());
    q.mrays = rays.empty() ? 0.0 : double(rays.size()) / median(s) / 1e6;
    for (std::size_t i = 0; i < rays.size(); ++i) q.differing += !agrees(hits[i], ref[i], a.exact());
    const std::vector<ray> few = counting_sample(rays, rules.count_rays, a.batch_alignment());
    std::vector<hit> few_hits(few.size());
    per_ray(q, a.intersect_counted(few, few_hits));
    return q;
}

query_result measure_any(const accel& a, std::span<const ray> rays, const std::vector<std::uint8_t>& ref,
                         const timing_rules& rules) {
    query_result q;
    q.rays = rays.size();
    std::vector<std::uint8_t> blocked(rays.size());
    const std::vector<double> s = time_runs(rules, [&] { trace_any(a, rays, blocked, rules.threads); });
    q.runs = int(s.size());
    q.mrays = rays.empty() ? 0.0 : double(rays.size()) / median(s) / 1e6;
    for (std::size_t i = 0; i < rays.size(); ++i) q.differing += blocked[i] != ref[i];
    const std::vector<ray> few = counting_sample(rays, rules.count_rays, a.batch_alignment());
    std::vector<std::uint8_t> few_blocked(few.size());
    per_ray(q, a.occluded_counted(few, few_blocked));
    return q;
}

}  // namespace strahl::race
