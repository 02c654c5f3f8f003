// Exercise 11.4 what one step buys (4 points). Read: chapter 16's README (the race, its processes and
// --compare), and this chapter's staircase.
#include "strahl/ch11/step_report.hpp"
#include "strahl/todo.hpp"

namespace strahl::ch11 {

// Part a, before you run anything: pick a step of the staircase (two rows "ch11-..." of the race), and
// write down the speed-up you expect on diffuse rays and the counter you expect to explain it (one of
// counter_names, or "none"). Return it, e.g. {"ch11-variant", "ch11-type-sorted", 1.05, "none"}.
// Then run the race (README: "Exercise 11.4") and `ch11 --exercise --step-report DIR`.
// Why: every step walks the same tree with the same triangle test: which counters can move at all?
step_prediction my_prediction() {
    STRAHL_TODO("11.4 what one step buys: your prediction");
}

// Part c: from each process's race.csv, per (scene, rays), the speed of `after` over `before` in that
// process (any-hit speed on shadow rays), their median and range, the verdict, and the counter that moved
// most (step_report.hpp says exactly how).
// Hint: pair first, summarise after: a ratio is taken inside one process, never across two.
// Why: the medians of the two rows over the processes give a ratio too; when can it say "faster" where the
// processes themselves disagree?
std::vector<step_ratio> compare_steps(const std::vector<std::vector<race_csv_row>>& processes,
                                      const std::string& before, const std::string& after) {
    STRAHL_TODO("11.4 what one step buys: the paired ratios");
}

}  // namespace strahl::ch11
