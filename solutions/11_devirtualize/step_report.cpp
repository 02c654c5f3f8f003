// Exercise 11.4 what one step buys (4 points). Read: chapter 16's README (the race, its processes and
// --compare), and this chapter's staircase.
#include "strahl/ch11/step_report.hpp"
#include <algorithm>
#include <cmath>
#include <utility>

namespace strahl::ch11 {

// 11.4a: written before the race was run. Step 4 drops the index array and the 64-byte objects for 36-byte
// triangles in leaf order: the same tree and tests, so no test counter should move, but the memory should.
step_prediction my_prediction() { return {"ch11-type-sorted", "ch11-triangles", 1.15, "memory bytes"}; }

// 11.4c: pair the two rows per process and per (scene, rays); the counters from the first pair found.
std::vector<step_ratio> compare_steps(const std::vector<std::vector<race_csv_row>>& processes,
                                      const std::string& before, const std::string& after) {
    std::vector<step_ratio> out;
    std::vector<std::pair<const race_csv_row*, const race_csv_row*>> first;  // per entry of out
    for (const std::vector<race_csv_row>& rows : processes)
        for (const race_csv_row& b : rows) {
            if (b.structure != before) continue;
            const auto a = std::find_if(rows.begin(), rows.end(), [&](const race_csv_row& r) {
                return r.structure == after && r.scene == b.scene && r.rays == b.rays;
            });
            if (a == rows.end()) continue;
            auto at = std::find_if(out.begin(), out.end(), [&](const step_ratio& s) { return s.scene == b.scene && s.rays == b.rays; });
            if (at == out.end()) {
                step_ratio fresh;
                fresh.scene = b.scene, fresh.rays = b.rays;
                out.push_back(fresh);
                first.push_back({&b, &*a});
                at = out.end() - 1;
            }
            const bool shadow = b.rays == "shadow";
            at->ratios.push_back(shadow ? a->any_mrays_s / b.any_mrays_s : a->closest_mrays_s / b.closest_mrays_s);
        }
    for (std::size_t k = 0; k < out.size(); ++k) {
        step_ratio& s = out[k];
        std::vector<double> sorted = s.ratios;
        std::sort(sorted.begin(), sorted.end());
        const std::size_t n = sorted.size();
        s.median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
        s.lo = sorted.front(), s.hi = sorted.back();
        s.verdict = s.lo > 1.0 ? "faster" : s.hi < 1.0 ? "slower" : "level";
        // The counter that moved most, by the size of its log ratio; 1 % either way is no move.
        const race_csv_row &b = *first[k].first, &a = *first[k].second;
        const bool shadow = s.rays == "shadow";
        const double was[] = {shadow ? b.any_box_per_ray : b.closest_box_per_ray,
                              shadow ? b.any_prim_per_ray : b.closest_prim_per_ray,
                              shadow ? 0.0 : b.closest_nodes_per_ray, b.memory_bytes};
        const double now[] = {shadow ? a.any_box_per_ray : a.closest_box_per_ray,
                              shadow ? a.any_prim_per_ray : a.closest_prim_per_ray,
                              shadow ? 0.0 : a.closest_nodes_per_ray, a.memory_bytes};
        s.moved = "none", s.moved_ratio = 1.0;
        double largest = std::log(1.01);
        for (int c = 0; c < 4; ++c) {
            if (!(was[c] > 0.0 && now[c] > 0.0)) continue;
            const double change = std::fabs(std::log(now[c] / was[c]));
            if (change > largest) largest = change, s.moved = counter_names[c], s.moved_ratio = now[c] / was[c];
        }
    }
    return out;
}

}  // namespace strahl::ch11
