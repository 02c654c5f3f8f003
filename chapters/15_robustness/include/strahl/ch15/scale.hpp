// Chapter 15's scale experiment (main.cpp's section 2c): the teapot and its primary rays scaled about the
// origin by the power of two nearest each decade from 1e-30 to 1e16 (experiments.hpp: the scaling itself
// rounds nothing), each triangle test by brute force (no ray frame: the test alone) and Embree with and
// without its robust flag, against the hits each finds at scale 1 (scale.csv, scale.svg). The scene is
// scaled in code: the loader's range (scene.hpp's min_extent and max_coordinate) would refuse the ends, and
// the failure is what is measured.
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace strahl::ch15 {

// One row of scale.csv: one test at one scale.
struct scale_row {
    double scale = 0, extent = 0, coordinate = 0;
    std::string test;
    std::size_t rays = 0, hits = 0, expected = 0;
};

// Runs the experiment (quick: 16 x 12 rays, else 64 x 48), printing its table and, at scale 1, the smallest
// products of the hits' Moeller-Trumbore test, from which the scales where they leave float's normal range
// follow (t's numerator first: three lengths).
std::vector<scale_row> run_scale(bool quick);

// scale.csv, and its rows read back (--replot); a file that is not one throws, naming it.
std::string scale_csv(const std::vector<scale_row>& rows);
std::vector<scale_row> read_scale_csv(const std::filesystem::path& file);

// Hits found (as a fraction of those at scale 1) against the teapot's extent, a line per test; dashed, the
// course's range: min_extent, and the extent at which the teapot's largest coordinate reaches max_coordinate.
void write_scale_plot(const std::vector<scale_row>& rows, const std::filesystem::path& svg);

}  // namespace strahl::ch15
