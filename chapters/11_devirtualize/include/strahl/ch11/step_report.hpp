// Exercise 11.4: what one step of the staircase buys, predicted, measured and explained. The steps share
// one tree, one walk and the same rays, so a step's speed-up is not a guess to argue about: the race
// measures it, process by process, and the race's exact counters say whether the work changed or only
// its cost. The student
//   (a) writes down a prediction first (my_prediction): two rows of the race, the speed-up expected on
//       diffuse rays, and the counter expected to explain it;
//   (b) runs the race with both rows over several processes (race --processes N --accels BEFORE,AFTER);
//   (c) computes from the race's own per-process tables what the step bought (compare_steps), which
//       `ch11 --step-report DIR` prints beside the prediction.
// The rule for ranking two speeds is the course's (chapter 16's race --compare): the ratio is paired, after
// over before in the same process, since processes differ from each other more than the steps do; faster
// where every process says faster, slower where every process says slower, else level.
#pragma once
#include "strahl/race_csv.hpp"
#include <string>
#include <vector>

namespace strahl::ch11 {

// The counters compare_steps looks at, by the names it reports.
inline constexpr const char* counter_names[] = {"box tests per ray", "triangle tests per ray", "nodes per ray",
                                                "memory bytes"};

// Exercise 11.4 (exercises/11_devirtualize/step_report.cpp), part a: the prediction, written before the
// race is run. before and after: two different rows "ch11-STEP" of the race; ratio: the speed of after
// over before expected on the diffuse rays (closest hit), a number in (0.1, 10); counter: the one of
// counter_names expected to move, or "none".
struct step_prediction {
    std::string before, after;
    double ratio = 0.0;
    std::string counter;
};
step_prediction my_prediction();

// What a step bought on one scene and ray set.
struct step_ratio {
    std::string scene, rays;
    std::vector<double> ratios;  // after / before in each process that has both rows, in the processes' order
    double median = 0.0, lo = 0.0, hi = 0.0;  // the median of ratios (mean of the middle two for an even
                                              // count), the smallest and the largest
    std::string verdict;  // "faster": every ratio above 1; "slower": every ratio below 1; else "level"
    std::string moved;    // the counter of counter_names that changed most (after / before, in either
                          // direction: the largest |log(after / before)|), "none" where every counter's
                          // after / before lies within [1 / 1.01, 1.01] (or a counter is 0 in either row)
    double moved_ratio = 1.0;  // that counter's after / before (1 for "none")
};

// Exercise 11.4, part c: processes[k] is process k's race.csv (read_race_rows). For every (scene, rays)
// where some process has both rows, in the order in which they first appear (process 0's rows first, then
// process 1's, ...): the speed of `after` over `before` per process, closest-hit Mrays/s, but any-hit Mrays/s on shadow
// rays (the race times no closest hit there); the counters from the first process that has both rows (they
// are exact, the same in every process), closest-hit counters, any-hit ones on shadow rays (box tests,
// triangle tests; nodes per ray reads 0 there), and memory_bytes. Rows of other structures are ignored.
std::vector<step_ratio> compare_steps(const std::vector<std::vector<race_csv_row>>& processes,
                                      const std::string& before, const std::string& after);

}  // namespace strahl::ch11
