// Plots as SVG files: line and scatter plots (linear or logarithmic axes) and bar charts, enough for the
// course's figures (rays/s against triangles, build time against trace speed, the race's staircase).
// SVG is text: it opens in any browser and diffs in git.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace strahl {

struct plot_series {
    std::string label;
    std::vector<double> x, y;
    bool lines = true;                 // connect the points in order (false: points only)
    std::vector<std::string> point_labels;  // optional text beside each point
};

struct plot {
    std::string title, x_label, y_label;
    bool log_x = false, log_y = false;
    std::vector<plot_series> series;
};

// A bar chart: one group per category, one bar per series in each group.
struct bar_chart {
    std::string title, y_label;
    std::vector<std::string> categories;
    std::vector<std::string> series_labels;
    std::vector<std::vector<double>> values;  // values[series][category]
    bool log_y = false;
};

// The SVG text. Non-finite values and, on log axes, values <= 0 are left out (never drawn as garbage).
std::string to_svg(const plot& p, int width = 720, int height = 440);
std::string to_svg(const bar_chart& c, int width = 720, int height = 440);

// Writes the SVG to a file; throws std::runtime_error if it cannot.
void write_svg(const std::filesystem::path& file, const std::string& svg);

}  // namespace strahl
