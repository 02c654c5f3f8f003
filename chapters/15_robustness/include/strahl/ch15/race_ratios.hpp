// The race's figures for this chapter, as ratios measured in the same process: each watertight row against
// the same structure with Moeller-Trumbore (ch15-watertight-fast / ch15-mt-fast, ch15-watertight-bvh16 /
// ch13-bvh16), and each course row against embree-medium. Per process, then the median and range across
// the processes of one `race --processes N` run (its DIR/processes/*/race.csv).
#pragma once
#include <filesystem>
#include <string>

namespace strahl::ch15 {

// The CSV text (scene,rays,structure,versus,processes,median,min,max) and a printed table; throws
// std::runtime_error naming the file where a race.csv is missing or not the race's.
std::string race_ratios(const std::filesystem::path& race_dir);

}  // namespace strahl::ch15
