#include "strahl/plot.hpp"
#include "strahl/program.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace strahl {

namespace {

const char* const palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                               "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"};

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '&') out += "&amp;";
        else out += c;
    }
    return out;
}

std::string number(double v) {
    char buf[32];
    const double a = std::abs(v);
    if (a != 0.0 && (a >= 1e6 || a < 1e-3)) std::snprintf(buf, sizeof buf, "%.0e", v);
    else std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// One axis: maps data values to pixels, linear or logarithmic, with "nice" tick values.
struct axis {
    double lo = 0.0, hi = 1.0;
    bool log = false;

    // A log axis spans whole decades; a linear one starts at 0 (from_zero) or a little below the data, and
    // ends a little above it, so that no point sits on the frame.
    void fit(const std::vector<double>& values, bool from_zero = true) {
        double a = std::numeric_limits<double>::infinity(), b = -a;
        for (double v : values)
            if (std::isfinite(v) && (!log || v > 0.0)) { a = std::min(a, v); b = std::max(b, v); }
        if (!std::isfinite(a)) { a = log ? 1.0 : 0.0; b = log ? 10.0 : 1.0; }
        if (log) { lo = std::pow(10.0, std::floor(std::log10(a))); hi = std::pow(10.0, std::ceil(std::log10(b))); }
        else {
            const double margin = b > a ? 0.05 * (b - a) : std::max(0.05 * std::abs(a), 0.5);
            lo = from_zero ? std::min(0.0, a) : a - margin;
            hi = b + margin;
        }
        if (hi <= lo) hi = log ? lo * 10.0 : lo + 1.0;
    }
    double unit(double v) const {  // 0..1 along the axis
        return log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) : (v - lo) / (hi - lo);
    }
    bool drawable(double v) const { return std::isfinite(v) && (!log || v > 0.0); }
    std::vector<double> ticks() const {
        std::vector<double> t;
        if (log) {
            for (double v = lo; v <= hi * 1.0001; v *= 10.0) t.push_back(v);
            return t;
        }
        const double raw = (hi - lo) / 5.0, mag = std::pow(10.0, std::floor(std::log10(raw)));
        const double step = raw / mag < 2.0 ? 2.0 * mag : raw / mag < 5.0 ? 5.0 * mag : 10.0 * mag;
        for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) t.push_back(v);
        return t;
    }
    // Whether tick t gets a number: every tick, except on a log axis of more than 12 decades, where only the
    // decades whose exponent is a multiple of 2, 5 or 10 (the first that leaves at most 12) do; every decade
    // keeps its grid line.
    bool labelled(double t) const {
        if (!log) return true;
        const long decades = std::lround(std::log10(hi) - std::log10(lo));
        if (decades <= 12) return true;
        const long step = decades <= 24 ? 2 : decades <= 60 ? 5 : 10;
        return std::lround(std::log10(t)) % step == 0;
    }
};

struct frame_geometry {
    double left = 80, right, top = 40, bottom;
};

void header(std::ostringstream& out, int w, int h, const std::string& title) {
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
        << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << w / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << escape(title) << "</text>\n";
}

void y_axis(std::ostringstream& out, const axis& ay, const frame_geometry& g, const std::string& label) {
    for (double t : ay.ticks()) {
        const double y = g.bottom - ay.unit(t) * (g.bottom - g.top);
        out << "<line x1=\"" << g.left << "\" x2=\"" << g.right << "\" y1=\"" << y << "\" y2=\"" << y
            << "\" stroke=\"#e0e0e0\"/>";
        if (ay.labelled(t))
            out << "<text x=\"" << g.left - 6 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">" << number(t) << "</text>";
        out << "\n";
    }
    out << "<text transform=\"translate(18," << (g.top + g.bottom) / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
        << escape(label) << "</text>\n";
}

// The room right of the frame for the legend: 180 pixels, more where a label is longer than about 22
// characters (at 7 pixels a character, after the 25 of the swatch).
double legend_room(const std::vector<std::string>& labels) {
    std::size_t longest = 0;
    for (const std::string& l : labels) longest = std::max(longest, l.size());
    return std::max(180.0, 35.0 + 7.0 * double(longest));
}

// The legend right of the frame: a colour swatch and a label per entry (palette indices).
void legend(std::ostringstream& out, const std::vector<std::pair<std::string, int>>& entries,
            const frame_geometry& g) {
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const double y = g.top + 8 + 16.0 * double(i);
        out << "<rect x=\"" << g.right + 10 << "\" y=\"" << y - 9 << "\" width=\"10\" height=\"10\" fill=\""
            << palette[entries[i].second % 10] << "\"/><text x=\"" << g.right + 25 << "\" y=\"" << y << "\">"
            << escape(entries[i].first) << "</text>\n";
    }
}

double overlap(const label_box& a, const label_box& b) {
    const double w = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x);
    const double h = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
    return w > 0.0 && h > 0.0 ? w * h : 0.0;
}

}  // namespace

std::vector<label_place> place_labels(const std::vector<std::array<double, 2>>& points,
                                      const std::vector<std::string>& texts, const label_box& frame,
                                      double font_size) {
    // The obstacles: every point's marker (a disc of radius 3.5, as a box), then each label once placed.
    std::vector<label_box> taken;
    for (const auto& [px, py] : points) taken.push_back({px - 4.0, py - 4.0, 8.0, 8.0});
    const auto cost = [&](const label_box& b) {
        double c = 0.0;
        for (const label_box& t : taken) c += overlap(b, t);
        // Outside the frame counts as overlap, ten times over.
        return c + 10.0 * (b.w * b.h - overlap(b, frame));
    };
    std::vector<label_place> placed;
    for (std::size_t i = 0; i < texts.size() && i < points.size(); ++i) {
        const auto [px, py] = points[i];
        const double w = 0.6 * font_size * double(texts[i].size()), h = font_size;
        label_place best;
        double best_cost = std::numeric_limits<double>::infinity();
        // Rings of eight places, each ring 12 pixels further out; the first ring touches the marker.
        for (int ring = 0; ring < 6 && best_cost > 0.0; ++ring) {
            const double d = 5.0 + 12.0 * ring, e = 0.7 * d;
            const label_box around[8] = {
                {px + d, py - h / 2, w, h},      {px - d - w, py - h / 2, w, h},  // right, left
                {px + e, py - e - h, w, h},      {px + e, py + e, w, h},          // upper and lower right
                {px - w / 2, py - d - h, w, h},  {px - w / 2, py + d, w, h},      // above, below
                {px - e - w, py - e - h, w, h},  {px - e - w, py + e, w, h}};     // upper and lower left
            for (const label_box& b : around) {
                const double c = cost(b);
                if (c < best_cost) best_cost = c, best = {b, ring > 0, c == 0.0};
                if (c == 0.0) break;
            }
        }
        taken.push_back(best.box);
        placed.push_back(best);
    }
    return placed;
}

std::string to_svg(const plot& p, int width, int height) {
    axis ax, ay;
    ax.log = p.log_x;
    ay.log = p.log_y;
    std::vector<double> xs, ys;
    for (const plot_series& s : p.series) {
        xs.insert(xs.end(), s.x.begin(), s.x.end());
        ys.insert(ys.end(), s.y.begin(), s.y.end());
    }
    ax.fit(xs);
    ay.fit(ys, p.y_from_zero);
    frame_geometry g;
    std::vector<std::string> labels;
    for (const plot_series& s : p.series)
        if (s.in_legend) labels.push_back(s.label);
    g.right = width - legend_room(labels);
    g.bottom = height - 50.0;
    std::ostringstream out;
    header(out, width, height, p.title);
    y_axis(out, ay, g, p.y_label + (p.log_y ? " (log)" : ""));
    for (double t : ax.ticks()) {
        const double x = g.left + ax.unit(t) * (g.right - g.left);
        out << "<line x1=\"" << x << "\" x2=\"" << x << "\" y1=\"" << g.top << "\" y2=\"" << g.bottom
            << "\" stroke=\"#e0e0e0\"/>";
        if (ax.labelled(t))
            out << "<text x=\"" << x << "\" y=\"" << g.bottom + 16 << "\" text-anchor=\"middle\">" << number(t) << "</text>";
        out << "\n";
    }
    out << "<text x=\"" << (g.left + g.right) / 2 << "\" y=\"" << height - 12 << "\" text-anchor=\"middle\">"
        << escape(p.x_label + (p.log_x ? " (log)" : "")) << "</text>\n";
    out << "<rect x=\"" << g.left << "\" y=\"" << g.top << "\" width=\"" << g.right - g.left << "\" height=\""
        << g.bottom - g.top << "\" fill=\"none\" stroke=\"black\"/>\n";
    // The series: lines first, then the points over them; the points' labels last, placed clear of both.
    std::vector<std::pair<std::string, int>> entries;
    std::vector<std::array<double, 2>> labelled, unlabelled;  // the points, with and without a label
    std::vector<std::string> texts;
    for (std::size_t si = 0; si < p.series.size(); ++si) {
        const plot_series& s = p.series[si];
        const int colour = s.color >= 0 ? s.color : int(si);
        if (s.in_legend) entries.emplace_back(s.label, colour);
        std::string path, dots;
        for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
            if (!ax.drawable(s.x[i]) || !ay.drawable(s.y[i])) continue;
            const double x = g.left + ax.unit(s.x[i]) * (g.right - g.left);
            const double y = g.bottom - ay.unit(s.y[i]) * (g.bottom - g.top);
            path += (path.empty() ? "M" : " L") + std::to_string(x) + " " + std::to_string(y);
            if (s.markers)
                dots += "<circle cx=\"" + std::to_string(x) + "\" cy=\"" + std::to_string(y) + "\" r=\"3.5\" fill=\"" +
                        palette[colour % 10] + "\"/>\n";
            if (i < s.point_labels.size() && !s.point_labels[i].empty())
                labelled.push_back({x, y}), texts.push_back(s.point_labels[i]);
            else
                unlabelled.push_back({x, y});
        }
        if (s.lines && !path.empty())
            out << "<path d=\"" << path << "\" fill=\"none\" stroke=\"" << palette[colour % 10]
                << "\" stroke-width=\"2\"" << (s.dashed ? " stroke-dasharray=\"6 4\"" : "") << "/>\n";
        out << dots;
    }
    const label_box frame{g.left, g.top, g.right - g.left, g.bottom - g.top};
    // The labelled points first (in the order of texts), then the others, as obstacles only.
    std::vector<std::array<double, 2>> anchors = labelled;
    anchors.insert(anchors.end(), unlabelled.begin(), unlabelled.end());
    const std::vector<label_place> places = place_labels(anchors, texts, frame);
    for (std::size_t i = 0; i < places.size(); ++i) {
        const label_box& b = places[i].box;
        if (places[i].leader) {
            // A thin line from the point to the nearest point of the label's box.
            const double lx = std::clamp(labelled[i][0], b.x, b.x + b.w), ly = std::clamp(labelled[i][1], b.y, b.y + b.h);
            out << "<line x1=\"" << labelled[i][0] << "\" y1=\"" << labelled[i][1] << "\" x2=\"" << lx << "\" y2=\""
                << ly << "\" stroke=\"#999999\" stroke-width=\"0.7\"/>\n";
        }
        out << "<text x=\"" << b.x << "\" y=\"" << b.y + 0.8 * b.h << "\" font-size=\"10\">" << escape(texts[i])
            << "</text>\n";
    }
    legend(out, entries, g);
    out << "</svg>\n";
    return out.str();
}

std::string to_svg(const std::vector<plot>& panels, int columns, int panel_width, int panel_height) {
    columns = std::max(1, std::min(columns, int(std::max<std::size_t>(1, panels.size()))));
    const int rows = std::max(1, (int(panels.size()) + columns - 1) / columns);
    std::ostringstream out;
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << columns * panel_width << "\" height=\""
        << rows * panel_height << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    for (std::size_t k = 0; k < panels.size(); ++k) {
        // Each panel is a whole plot, nested as an <svg> element placed at its cell.
        std::string panel = to_svg(panels[k], panel_width, panel_height);
        const std::string at = "<svg x=\"" + std::to_string(int(k) % columns * panel_width) + "\" y=\"" +
                               std::to_string(int(k) / columns * panel_height) + "\" ";
        panel.replace(0, 5, at);
        out << panel;
    }
    out << "</svg>\n";
    return out.str();
}

std::string to_svg(const bar_chart& c, int width, int height) {
    axis ay;
    ay.log = c.log_y;
    std::vector<double> all;
    for (const auto& row : c.values) all.insert(all.end(), row.begin(), row.end());
    ay.fit(all);
    frame_geometry g;
    g.right = width - legend_room(c.series_labels);
    const double group = (g.right - g.left) / double(std::max<std::size_t>(1, c.categories.size()));
    // The category names, slanted: 20 degrees where the groups are wide enough that neighbouring names stay
    // 13 pixels apart, else 50; the picture grows downwards by what the longest name needs.
    std::size_t longest = 0;
    for (const std::string& name : c.categories) longest = std::max(longest, name.size());
    const double pi = 3.14159265358979, slant = group * std::sin(20.0 * pi / 180.0) >= 13.0 ? 20.0 : 50.0;
    const double below = 24.0 + 0.6 * 11.0 * double(longest) * std::sin(slant * pi / 180.0);
    height += int(std::max(0.0, below - 70.0));
    g.bottom = height - std::max(70.0, below);
    std::ostringstream out;
    header(out, width, height, c.title);
    y_axis(out, ay, g, c.y_label + (c.log_y ? " (log)" : ""));
    const double bar = group * 0.8 / double(std::max<std::size_t>(1, c.values.size()));
    for (std::size_t k = 0; k < c.categories.size(); ++k) {
        const double x0 = g.left + group * double(k) + group * 0.1;
        for (std::size_t si = 0; si < c.values.size(); ++si) {
            if (k >= c.values[si].size() || !ay.drawable(c.values[si][k])) continue;
            const double base = c.log_y ? 0.0 : ay.unit(0.0);
            const double top = ay.unit(c.values[si][k]);
            const double y = g.bottom - std::max(top, base) * (g.bottom - g.top);
            const double h = std::abs(top - base) * (g.bottom - g.top);
            out << "<rect x=\"" << x0 + bar * double(si) << "\" y=\"" << y << "\" width=\"" << bar * 0.95
                << "\" height=\"" << h << "\" fill=\"" << palette[si % 10] << "\"/>\n";
        }
        out << "<text transform=\"translate(" << x0 + group * 0.4 << "," << g.bottom + 14
            << ") rotate(" << slant << ")\" font-size=\"11\">" << escape(c.categories[k]) << "</text>\n";
    }
    out << "<rect x=\"" << g.left << "\" y=\"" << g.top << "\" width=\"" << g.right - g.left << "\" height=\""
        << g.bottom - g.top << "\" fill=\"none\" stroke=\"black\"/>\n";
    std::vector<std::pair<std::string, int>> entries;
    for (std::size_t i = 0; i < c.series_labels.size(); ++i) entries.emplace_back(c.series_labels[i], int(i));
    legend(out, entries, g);
    out << "</svg>\n";
    return out.str();
}

void write_svg(const std::filesystem::path& file, const std::string& svg) { write_text(file, svg); }

}  // namespace strahl
