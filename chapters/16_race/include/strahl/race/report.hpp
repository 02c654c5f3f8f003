// The race's results: one row per scene, structure and ray set, printed as a table and written as CSV,
// Markdown and SVG plots.
#pragma once
#include "strahl/machine.hpp"
#include "strahl/race_csv.hpp"
#include "strahl/race/measure.hpp"
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace strahl::race {

struct race_row {
    std::string scene;
    std::size_t triangles = 0;
    std::string accel, chapter;
    bool exact = true;  // must equal brute force (the course's structures); false for Embree
    std::string ray_set;
    double build_ms = 0.0;
    std::size_t memory_bytes = 0;
    std::optional<double> sah;
    query_result closest, any;
    std::optional<double> closest_vs_embree, any_vs_embree;  // speed ratio to embree-medium, same run
    std::string cpu;  // the machine's CPU where the row was read from a file that names it, else empty
};

// race.csv's machine columns (strahl/race_csv.hpp: race_csv_machine_header): strahl/machine.hpp's.
using strahl::machine_columns;
using strahl::this_machine;

// Fills the ratio columns from the embree-medium rows of the same scene and ray set.
void add_embree_ratios(std::vector<race_row>& rows);

void print_table(std::ostream& out, const std::vector<race_row>& rows);
// race.csv's first line: strahl::race_csv_header (strahl/race_csv.hpp), which the chapters read back.
using strahl::race_csv_header;
// Every row with the machine's columns; a row that names its own CPU (read from a process's file) keeps it.
std::string to_csv(const std::vector<race_row>& rows, const machine_columns& machine);
// processes > 1: the rows are medians across that many processes (race --processes), and the text says so.
std::string to_markdown(const std::vector<race_row>& rows, const std::string& machine, int processes = 1);

// speed_vs_build.svg (closest-hit Mrays/s against build ms, per scene, primary rays) and staircase.svg
// (primary-ray Mrays/s per structure in chapter order, one bar group per structure, a bar per scene).
void write_plots(const std::filesystem::path& folder, const std::vector<race_row>& rows);

// Rows of course structures whose results differ from brute force (must be none).
std::size_t wrong_rows(const std::vector<race_row>& rows);

}  // namespace strahl::race
