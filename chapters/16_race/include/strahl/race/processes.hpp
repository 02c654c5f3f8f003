// The race over several fresh processes. One process is one sample of the machine: on the course's VMs a
// whole process can come out 20 to 30% slower than the next (its builds, Embree's included, and the course's
// traversals; chapter 05's README), and the median of a process's repeats cannot smooth that away.
// `race --processes N` runs the race N times, each time as a fresh process (every second one measuring the
// structures in reverse order, so that no row is always measured first or last), and reports each figure's
// median across the processes, with its spread.
#pragma once
#include "strahl/plot.hpp"
#include "strahl/race/report.hpp"
#include <filesystem>
#include <string>
#include <vector>

namespace strahl::race {

// Reads back a race.csv that to_csv wrote (the any-hit nodes per ray, not in the CSV, stay empty); throws
// std::runtime_error naming the file and line on anything else.
std::vector<race_row> read_race_csv(const std::filesystem::path& file);

// The smallest, median and largest of one figure across processes.
struct spread {
    double min = 0.0, median = 0.0, max = 0.0;
    int samples = 0;  // processes that measured it
};

// One row of the combined race: `row` holds, per figure, the median across processes (the ratios to Embree
// are the medians of each process's own ratio, not ratios of medians: a process that is slow for both
// structures leaves its ratio alone). Its differing counts are the largest of any process, its timed runs
// the sum; memory, SAH cost and tests per ray are the first process's (the same in every process: the
// builders are deterministic).
struct combined_row {
    race_row row;
    spread build_ms, closest, any, closest_vs_embree, any_vs_embree;
};

// Combines the rows of several processes: one row per scene, ray set and structure, in the first process's
// order (rows that later processes lack have fewer samples; rows only later processes have are appended).
// Throws std::runtime_error when one row's triangle or ray count differs between processes (not one race).
std::vector<combined_row> combine_processes(const std::vector<std::vector<race_row>>& processes);

// The combined rows with each figure's spread: "median (min to max)" per cell, as Markdown.
std::string spread_markdown(const std::vector<combined_row>& rows, int processes, const std::string& machine);

// spread.svg's panels: one per scene and ray set, the speed of every structure (closest hit; any hit where
// the set has no closest-hit query) against the process that measured it, on a log axis, so that a process
// that is slow as a whole shows as a dip in every line at once, and a ratio as a constant gap.
std::vector<plot> spread_plot(const std::vector<std::vector<race_row>>& processes);

// Two rows compared, the claim rule: which of A and B is faster on one scene, ray set and query. Each
// process gives one paired ratio, A's Mrays/s over B's in that process (the same rays, the same machine
// state; the order of the rows alternates from process to process), so that a process slow as a whole
// leaves the ratio alone. The verdict: "faster" where A beat B in every process, "slower" where B beat A in
// every process, "level" otherwise (the noise covers the gap). With two rows of equal speed, all of n
// processes agree by chance with probability 2^(1-n): 1 in 16 for 5 processes, so verdicts need at least
// min_processes; with fewer, "too few processes".
struct comparison {
    std::string scene, ray_set, query;  // query: "closest" or "any"
    std::string a, b;
    std::vector<double> ratios;  // A / B, one per process that measured both
    spread ratio;
    std::string verdict;
};
inline constexpr int min_processes = 5;
std::string verdict_of(const std::vector<double>& ratios);

// Every (scene, ray set, query) that both rows measured, in the first process's order. Throws
// std::invalid_argument naming a row that no process measured.
std::vector<comparison> compare_rows(const std::vector<std::vector<race_row>>& processes, const std::string& a,
                                     const std::string& b);

// compare.csv: scene, rays, query, a, b, processes, ratio_median, ratio_min, ratio_max, verdict, then each
// process's ratio; and the same as a Markdown table.
inline constexpr const char* compare_csv_header =
    "scene,rays,query,a,b,processes,ratio_median,ratio_min,ratio_max,verdict,ratios";
std::string comparisons_csv(const std::vector<comparison>& c);
std::string comparisons_markdown(const std::vector<comparison>& c, const std::string& machine);

// Reads back a compare.csv that comparisons_csv wrote; throws std::runtime_error naming the file and line
// on anything else.
std::vector<comparison> read_comparisons_csv(const std::filesystem::path& file);

// The same comparisons in two runs of a race (an earlier compare.csv against this run's): how many verdicts
// held. A verdict that held says the same in both; one that changed went between faster or slower and level;
// an opposite one went from faster to slower or back (the claim rule should make those rare: each needs
// every process of one run against every process of the other).
struct verdict_change {
    comparison earlier, now;
};
struct verdict_stability {
    int both = 0, held = 0, opposite = 0;
    std::vector<verdict_change> changed;  // opposite ones included
};
verdict_stability compare_verdicts(const std::vector<comparison>& earlier, const std::vector<comparison>& now);
std::string stability_markdown(const verdict_stability& s, const std::string& earlier_name);

// Runs this program (/proc/self/exe) with `args` (argv[1...]) as a child process whose standard output and
// error go to `log`; waits for it and returns its exit status (128 + the signal's number if a signal ended it).
int run_self(const std::vector<std::string>& args, const std::filesystem::path& log);

}  // namespace strahl::race
