// Conceptual diagrams as SVG: a small 2D canvas on which the chapters draw their structures (grid cells,
// BVH boxes and node arrays, slabs, split planes, SAH bins, rotations) from the data their own code builds,
// so that a figure cannot drift from the code. SVG is text, as in plot.hpp: any browser opens it.
#pragma once
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace strahl {

// A light palette: pale fills under black text, and darker strokes of the same hues.
namespace ink {
inline constexpr const char* black = "#222222";
inline constexpr const char* grey = "#777777";
inline constexpr const char* pale_grey = "#eeeeee";
inline constexpr const char* blue = "#1f77b4";
inline constexpr const char* pale_blue = "#d4e5f5";
inline constexpr const char* red = "#c62828";
inline constexpr const char* pale_red = "#f8d5d5";
inline constexpr const char* green = "#2e8b2e";
inline constexpr const char* pale_green = "#d6efd0";
inline constexpr const char* orange = "#e67300";
inline constexpr const char* pale_orange = "#ffe2c2";
inline constexpr const char* purple = "#7b52ab";
inline constexpr const char* pale_purple = "#e5dbf2";
}  // namespace ink

struct pen {
    std::string stroke = ink::black;  // "none": no outline
    std::string fill = "none";
    double width = 1.5;               // pixels
    bool dashed = false;
    double fill_opacity = 1.0;
};

struct font {
    double size = 14.0;               // pixels
    std::string anchor = "start";     // start, middle or end of the text at x
    std::string color = ink::black;
    bool bold = false;
    bool halo = false;                // a white outline behind the letters, to read over lines
};

struct point2 {
    double x = 0.0, y = 0.0;
};

// A canvas of width x height pixels on white. Shapes take world coordinates; view() sets the map from the
// world (y up) to a rectangle of pixels, the same scale on both axes. Before any view(), and after pixels(),
// world coordinates are pixels (y down), for trees, arrays and captions.
class diagram {
public:
    diagram(int width, int height);

    // Maps the world window [x0, x1] x [y0, y1] into the pixel rectangle (left, top, w, h), as large as fits
    // with the aspect kept, centred.
    void view(double x0, double y0, double x1, double y1, double left, double top, double w, double h);
    void pixels();
    point2 to_pixel(double x, double y) const;
    double scale() const { return sx_; }  // pixels per world unit

    void rect(double x0, double y0, double x1, double y1, const pen& p);  // two opposite corners
    void line(double x0, double y0, double x1, double y1, const pen& p);
    // An arrow from (x0, y0) to (x1, y1), its head at the end; bend (pixels) curves it to the left of its way.
    void arrow(double x0, double y0, double x1, double y1, const pen& p, double bend = 0.0);
    void polygon(const std::vector<point2>& corners, const pen& p);
    void circle(double x, double y, double radius_px, const pen& p);
    void text(double x, double y, const std::string& s, const font& f = {});  // the baseline starts at (x, y)

    std::string svg() const;
    void write(const std::filesystem::path& file) const;  // write_svg (plot.hpp): throws if it cannot

private:
    void shape(const std::string& element, const std::string& geometry, const pen& p);
    int width_, height_;
    double ox_ = 0.0, oy_ = 0.0, sx_ = 1.0, sy_ = 1.0;  // pixel = (ox + sx x, oy + sy y)
    std::string body_;
};

// A chapter's --diagrams: each figure's file name and the function that draws it. write_figures refuses
// every file first (prepare_output: nothing replaced without force), then draws every figure, then writes
// them: an unfinished exercise stops the drawing and leaves no file behind. Returns the files written.
struct named_figure {
    std::string file;
    std::function<diagram()> draw;
};
std::vector<std::filesystem::path> write_figures(const std::filesystem::path& folder, bool force,
                                                 const std::vector<named_figure>& figures);

// A chapter program's --diagrams DIR: where the option was given, writes the chapter's figures with `write`
// (its write_diagrams; --force to replace them), prints each file written and returns true, and the program
// stops; else false.
class cli;
using figure_writer = std::vector<std::filesystem::path> (*)(const std::filesystem::path& folder, bool force);
bool draw_diagrams_if_asked(const cli& args, figure_writer write);

// The text with <, >, & and " written as entities, for SVG (and any XML) text and attributes.
std::string svg_escape(const std::string& text);

// A number as the figures print it, through a printf format ("%.3g": 3 significant digits).
inline std::string number_text(double v, const char* format = "%.3g") {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

}  // namespace strahl
