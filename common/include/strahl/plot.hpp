// Plots as SVG files: line and scatter plots (linear or logarithmic axes) and bar charts, enough for the
// course's figures (rays/s against triangles, build time against trace speed, the race's staircase).
// SVG is text: it opens in any browser and diffs in git.
#pragma once
#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace strahl {

struct plot_series {
    std::string label;
    std::vector<double> x, y;
    bool lines = true;                 // connect the points in order (false: points only)
    std::vector<std::string> point_labels;  // optional text beside each point (placed by place_labels)
    int color = -1;                    // palette index; -1: the series' own index
    bool dashed = false;               // draw the line dashed
    bool in_legend = true;             // false: a companion series (more points in another's colour), unlisted
    bool markers = true;               // a dot at each point (false: a line series drawn as the line alone)
};

struct plot {
    std::string title, x_label, y_label;
    bool log_x = false, log_y = false;
    std::vector<plot_series> series;
    bool y_from_zero = true;           // a linear y axis starts at 0; false: it fits the data's range
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
// Small multiples: the plots side by side, `columns` to a row, each panel_width x panel_height pixels.
std::string to_svg(const std::vector<plot>& panels, int columns, int panel_width = 600, int panel_height = 400);

// Label placement, greedy: each label in turn takes the first of a ring of places around its point (right,
// left, above, below, the diagonals; then rings further out, joined to the point by a leader line) where it
// overlaps no label placed before it, no point, and stays inside the frame; where no place is free, the one
// with the least overlap. `points` holds the labelled points, in the order of `texts`, then any further
// points to keep clear of. Boxes are in pixels, y down; a text's box is estimated from its length.
struct label_box {
    double x = 0, y = 0, w = 0, h = 0;  // top-left corner and size
};
struct label_place {
    label_box box;
    bool leader = false;  // placed away from its point: draw a line to it
    bool clear = true;    // overlaps nothing
};
std::vector<label_place> place_labels(const std::vector<std::array<double, 2>>& points,
                                      const std::vector<std::string>& texts, const label_box& frame,
                                      double font_size = 10.0);

// Writes the SVG to a file; throws std::runtime_error if it cannot.
void write_svg(const std::filesystem::path& file, const std::string& svg);

}  // namespace strahl
