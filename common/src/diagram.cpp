#include "strahl/diagram.hpp"
#include "strahl/plot.hpp"
#include "strahl/program.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>

namespace strahl {

namespace {

// A coordinate to two decimals (pixels: finer is invisible, and the files stay small and diffable).
std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", std::abs(v) < 0.005 ? 0.0 : v);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
}

std::string attr(const char* name, const std::string& value) { return std::string(" ") + name + "=\"" + value + "\""; }

}  // namespace

std::string svg_escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '&') out += "&amp;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

diagram::diagram(int width, int height) : width_(width), height_(height) {}

void diagram::view(double x0, double y0, double x1, double y1, double left, double top, double w, double h) {
    const double dx = std::max(x1 - x0, 1e-12), dy = std::max(y1 - y0, 1e-12);
    const double s = std::min(w / dx, h / dy);
    sx_ = s, sy_ = -s;
    ox_ = left + 0.5 * (w - s * dx) - s * x0;
    oy_ = top + 0.5 * (h - s * dy) + s * y1;  // y1 at the top
}

void diagram::pixels() { ox_ = oy_ = 0.0, sx_ = sy_ = 1.0; }

point2 diagram::to_pixel(double x, double y) const { return {ox_ + sx_ * x, oy_ + sy_ * y}; }

void diagram::shape(const std::string& element, const std::string& geometry, const pen& p) {
    body_ += "<" + element + geometry + attr("fill", svg_escape(p.fill)) + attr("stroke", svg_escape(p.stroke));
    if (p.stroke != "none") body_ += attr("stroke-width", num(p.width));
    if (p.fill != "none" && p.fill_opacity < 1.0) body_ += attr("fill-opacity", num(p.fill_opacity));
    if (p.dashed) body_ += attr("stroke-dasharray", num(3.0 * p.width) + " " + num(2.5 * p.width));
    body_ += "/>\n";
}

void diagram::rect(double x0, double y0, double x1, double y1, const pen& p) {
    const point2 a = to_pixel(x0, y0), b = to_pixel(x1, y1);
    shape("rect", attr("x", num(std::min(a.x, b.x))) + attr("y", num(std::min(a.y, b.y))) +
                      attr("width", num(std::abs(b.x - a.x))) + attr("height", num(std::abs(b.y - a.y))), p);
}

void diagram::line(double x0, double y0, double x1, double y1, const pen& p) {
    const point2 a = to_pixel(x0, y0), b = to_pixel(x1, y1);
    shape("line", attr("x1", num(a.x)) + attr("y1", num(a.y)) + attr("x2", num(b.x)) + attr("y2", num(b.y)), p);
}

void diagram::arrow(double x0, double y0, double x1, double y1, const pen& p, double bend) {
    const point2 a = to_pixel(x0, y0), b = to_pixel(x1, y1);
    const double dx = b.x - a.x, dy = b.y - a.y, len = std::max(std::hypot(dx, dy), 1e-9);
    // The control point of a quadratic curve, `bend` pixels off the middle of the way (to its left on screen).
    const point2 c{0.5 * (a.x + b.x) + bend * dy / len, 0.5 * (a.y + b.y) - bend * dx / len};
    // The head: a triangle along the curve's last tangent (c to b), its tip at b; the line stops at its base.
    const double tx = b.x - c.x, ty = b.y - c.y, tl = std::max(std::hypot(tx, ty), 1e-9);
    const double ux = tx / tl, uy = ty / tl, head = 4.0 + 2.5 * p.width, half = 0.45 * head;
    const point2 base{b.x - head * ux, b.y - head * uy};
    pen body = p;
    body.fill = "none";
    shape("path", attr("d", "M" + num(a.x) + " " + num(a.y) + " Q" + num(c.x) + " " + num(c.y) + " " + num(base.x) +
                                " " + num(base.y)), body);
    pen tip{"none", p.stroke, 0.0};
    shape("polygon", attr("points", num(b.x) + "," + num(b.y) + " " + num(base.x - half * uy) + "," +
                                        num(base.y + half * ux) + " " + num(base.x + half * uy) + "," +
                                        num(base.y - half * ux)), tip);
}

void diagram::polygon(const std::vector<point2>& corners, const pen& p) {
    std::string points;
    for (const point2& q : corners) {
        const point2 a = to_pixel(q.x, q.y);
        points += (points.empty() ? "" : " ") + num(a.x) + "," + num(a.y);
    }
    shape("polygon", attr("points", points), p);
}

void diagram::circle(double x, double y, double radius_px, const pen& p) {
    const point2 a = to_pixel(x, y);
    shape("circle", attr("cx", num(a.x)) + attr("cy", num(a.y)) + attr("r", num(radius_px)), p);
}

void diagram::text(double x, double y, const std::string& s, const font& f) {
    const point2 a = to_pixel(x, y);
    body_ += "<text" + attr("x", num(a.x)) + attr("y", num(a.y)) + attr("font-size", num(f.size)) +
             attr("fill", svg_escape(f.color));
    if (f.anchor != "start") body_ += attr("text-anchor", svg_escape(f.anchor));
    if (f.bold) body_ += attr("font-weight", "bold");
    if (f.halo) body_ += attr("stroke", "white") + attr("stroke-width", "4") + attr("paint-order", "stroke");
    body_ += ">" + svg_escape(s) + "</text>\n";
}

std::string diagram::svg() const {
    return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width_) + "\" height=\"" +
           std::to_string(height_) + "\" viewBox=\"0 0 " + std::to_string(width_) + " " + std::to_string(height_) +
           "\" font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" + body_ +
           "</svg>\n";
}

void diagram::write(const std::filesystem::path& file) const { write_svg(file, svg()); }

std::vector<std::filesystem::path> write_figures(const std::filesystem::path& folder, bool force,
                                                 const std::vector<named_figure>& figures) {
    std::vector<std::filesystem::path> files;
    for (const named_figure& f : figures) files.push_back(folder / f.file), prepare_output(files.back(), true, force);
    std::vector<diagram> drawn;
    for (const named_figure& f : figures) drawn.push_back(f.draw());
    for (std::size_t k = 0; k < files.size(); ++k) drawn[k].write(files[k]);
    return files;
}

bool draw_diagrams_if_asked(const cli& args, figure_writer write) {
    if (!args.has("diagrams")) return false;
    for (const std::filesystem::path& f : write(args.get("diagrams"), args.has("force")))
        std::printf("wrote %s\n", f.string().c_str());
    return true;
}

}  // namespace strahl
