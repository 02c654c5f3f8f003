#include "strahl/plot.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

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

    void fit(const std::vector<double>& values) {
        double a = std::numeric_limits<double>::infinity(), b = -a;
        for (double v : values)
            if (std::isfinite(v) && (!log || v > 0.0)) { a = std::min(a, v); b = std::max(b, v); }
        if (!std::isfinite(a)) { a = log ? 1.0 : 0.0; b = log ? 10.0 : 1.0; }
        if (log) { lo = std::pow(10.0, std::floor(std::log10(a))); hi = std::pow(10.0, std::ceil(std::log10(b))); }
        else { lo = std::min(0.0, a); hi = b; }
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
            << "\" stroke=\"#e0e0e0\"/><text x=\"" << g.left - 6 << "\" y=\"" << y + 4
            << "\" text-anchor=\"end\">" << number(t) << "</text>\n";
    }
    out << "<text transform=\"translate(18," << (g.top + g.bottom) / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
        << escape(label) << "</text>\n";
}

void legend(std::ostringstream& out, const std::vector<std::string>& labels, const frame_geometry& g) {
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const double y = g.top + 8 + 16.0 * double(i);
        out << "<rect x=\"" << g.right + 10 << "\" y=\"" << y - 9 << "\" width=\"10\" height=\"10\" fill=\""
            << palette[i % 10] << "\"/><text x=\"" << g.right + 25 << "\" y=\"" << y << "\">" << escape(labels[i])
            << "</text>\n";
    }
}

}  // namespace

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
    ay.fit(ys);
    frame_geometry g;
    g.right = width - 180.0;
    g.bottom = height - 50.0;
    std::ostringstream out;
    header(out, width, height, p.title);
    y_axis(out, ay, g, p.y_label + (p.log_y ? " (log)" : ""));
    for (double t : ax.ticks()) {
        const double x = g.left + ax.unit(t) * (g.right - g.left);
        out << "<line x1=\"" << x << "\" x2=\"" << x << "\" y1=\"" << g.top << "\" y2=\"" << g.bottom
            << "\" stroke=\"#e0e0e0\"/><text x=\"" << x << "\" y=\"" << g.bottom + 16 << "\" text-anchor=\"middle\">"
            << number(t) << "</text>\n";
    }
    out << "<text x=\"" << (g.left + g.right) / 2 << "\" y=\"" << height - 12 << "\" text-anchor=\"middle\">"
        << escape(p.x_label + (p.log_x ? " (log)" : "")) << "</text>\n";
    out << "<rect x=\"" << g.left << "\" y=\"" << g.top << "\" width=\"" << g.right - g.left << "\" height=\""
        << g.bottom - g.top << "\" fill=\"none\" stroke=\"black\"/>\n";
    std::vector<std::string> labels;
    for (std::size_t si = 0; si < p.series.size(); ++si) {
        const plot_series& s = p.series[si];
        labels.push_back(s.label);
        std::string path;
        for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
            if (!ax.drawable(s.x[i]) || !ay.drawable(s.y[i])) continue;
            const double x = g.left + ax.unit(s.x[i]) * (g.right - g.left);
            const double y = g.bottom - ay.unit(s.y[i]) * (g.bottom - g.top);
            path += (path.empty() ? "M" : " L") + std::to_string(x) + " " + std::to_string(y);
            out << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"3.5\" fill=\"" << palette[si % 10] << "\"/>\n";
            if (i < s.point_labels.size())
                out << "<text x=\"" << x + 6 << "\" y=\"" << y - 6 << "\" font-size=\"10\">" << escape(s.point_labels[i])
                    << "</text>\n";
        }
        if (s.lines && !path.empty())
            out << "<path d=\"" << path << "\" fill=\"none\" stroke=\"" << palette[si % 10] << "\" stroke-width=\"2\"/>\n";
    }
    legend(out, labels, g);
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
    g.right = width - 180.0;
    g.bottom = height - 70.0;
    std::ostringstream out;
    header(out, width, height, c.title);
    y_axis(out, ay, g, c.y_label + (c.log_y ? " (log)" : ""));
    const double group = (g.right - g.left) / double(std::max<std::size_t>(1, c.categories.size()));
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
            << ") rotate(20)\" font-size=\"11\">" << escape(c.categories[k]) << "</text>\n";
    }
    out << "<rect x=\"" << g.left << "\" y=\"" << g.top << "\" width=\"" << g.right - g.left << "\" height=\""
        << g.bottom - g.top << "\" fill=\"none\" stroke=\"black\"/>\n";
    legend(out, c.series_labels, g);
    out << "</svg>\n";
    return out.str();
}

void write_svg(const std::filesystem::path& file, const std::string& svg) {
    std::ofstream out(file, std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write '" + file.string() + "': " + std::strerror(errno));
    out << svg;
    out.close();
    if (!out) throw std::runtime_error("writing '" + file.string() + "' failed");
}

}  // namespace strahl
