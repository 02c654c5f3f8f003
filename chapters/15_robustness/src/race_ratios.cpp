// The race's per-process ratios for chapter 15 (race_ratios.hpp).
#include "strahl/ch15/race_ratios.hpp"
#include "strahl/program.hpp"
#include "strahl/race_csv.hpp"
#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace strahl::ch15 {

namespace {
// What each row is compared with.
const std::pair<const char*, const char*> pairs[] = {
    {"ch15-watertight-fast", "ch15-mt-fast"},     {"ch15-watertight-bvh16", "ch13-bvh16"},
    {"ch15-mt-fast", "embree-medium"},            {"ch15-watertight-fast", "embree-medium"},
    {"ch13-bvh16", "embree-medium"},              {"ch15-watertight-bvh16", "embree-medium"}};
}  // namespace

std::string race_ratios(const std::filesystem::path& race_dir) {
    std::vector<std::filesystem::path> files;
    const std::filesystem::path processes = race_dir / "processes";
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(processes, ec))
        if (std::filesystem::exists(e.path() / "race.csv")) files.push_back(e.path() / "race.csv");
    if (ec || files.empty())
        throw std::runtime_error(processes.string() + ": no race.csv of a race --processes N run there");
    std::sort(files.begin(), files.end());
    // (scene, rays, structure, versus) -> the ratio in each process.
    std::map<std::tuple<std::string, std::string, std::string, std::string>, std::vector<double>> ratios;
    for (const auto& file : files) {
        std::map<std::tuple<std::string, std::string, std::string>, double> speed;  // closest; any for shadow rays
        for (const csv_row& r : read_csv(file, race_csv_header, race_csv_machine_header, "a race.csv written by the race (chapter 16)")) {
            const bool shadow = r.cells[5] == "shadow";
            speed[{r.cells[0], r.cells[5], r.cells[2]}] = csv_number(file, r, shadow ? 17 : 10);
        }
        for (const auto& [key, s] : speed)
            for (const auto& [row, versus] : pairs) {
                if (std::get<2>(key) != row) continue;
                const auto base = speed.find({std::get<0>(key), std::get<1>(key), versus});
                if (base != speed.end() && base->second > 0.0)
                    ratios[{std::get<0>(key), std::get<1>(key), row, versus}].push_back(s / base->second);
            }
    }
    std::ostringstream csv;
    csv << "scene,rays,structure,versus,processes,median,min,max\n";
    std::printf("speed ratios measured in the same process, median (range) of %zu processes:\n", files.size());
    for (auto& [key, v] : ratios) {
        std::sort(v.begin(), v.end());
        const std::size_t n = v.size();
        const double median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
        const auto& [scene, rays, row, versus] = key;
        csv << scene << ',' << rays << ',' << row << ',' << versus << ',' << n << ',' << median << ',' << v.front()
            << ',' << v.back() << '\n';
        std::printf("  %-12s %-8s %-22s / %-14s %5.2f (%.2f-%.2f)\n", scene.c_str(), rays.c_str(), row.c_str(),
                    versus.c_str(), median, v.front(), v.back());
    }
    if (ratios.empty()) throw std::runtime_error(race_dir.string() + ": the race has none of chapter 15's rows");
    return csv.str();
}

}  // namespace strahl::ch15
