// Unit tests of common/'s diagram canvas: the world-to-pixel map, the escaping of text, and well-formed SVG.
#include <catch2/catch.hpp>
#include "strahl/diagram.hpp"
#include "test_support.hpp"
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace strahl;
using Catch::Matchers::Contains;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// XML-ish well-formedness: every element opened is closed, in order, and no '<' or '&' stands bare in text.
bool balanced(const std::string& svg) {
    std::vector<std::string> open;
    for (std::size_t at = 0; (at = svg.find('<', at)) != std::string::npos;) {
        const std::size_t end = svg.find('>', at);
        if (end == std::string::npos) return false;
        const std::string tag = svg.substr(at + 1, end - at - 1);
        if (tag.find('<') != std::string::npos) return false;
        const std::string name = tag.substr(tag[0] == '/' ? 1 : 0, tag.find_first_of(" /", 1) - (tag[0] == '/' ? 1 : 0));
        if (tag[0] == '/') {
            if (open.empty() || open.back() != name) return false;
            open.pop_back();
        } else if (tag.back() != '/') {
            open.push_back(name);
        }
        at = end + 1;
    }
    for (std::size_t at = 0; (at = svg.find('&', at)) != std::string::npos; ++at)
        if (svg.compare(at, 4, "&lt;") && svg.compare(at, 4, "&gt;") && svg.compare(at, 5, "&amp;") &&
            svg.compare(at, 6, "&quot;"))
            return false;
    return open.empty();
}

}  // namespace

TEST_CASE("diagram: a view maps the world window into its pixel rectangle, y up, one scale, centred", "[common][diagram]") {
    diagram d(400, 300);
    // Before any view, world coordinates are pixels.
    CHECK(d.to_pixel(12, 34).x == Approx(12));
    CHECK(d.to_pixel(12, 34).y == Approx(34));
    // A 10 x 5 window into a 200 x 200 rectangle at (100, 50): 20 pixels per unit, 50 pixels spare above and below.
    d.view(0, 0, 10, 5, 100, 50, 200, 200);
    CHECK(d.scale() == Approx(20));
    CHECK(d.to_pixel(0, 0).x == Approx(100));
    CHECK(d.to_pixel(0, 0).y == Approx(200));   // the window's bottom edge: 50 + 50 + 5 * 20
    CHECK(d.to_pixel(10, 5).x == Approx(300));
    CHECK(d.to_pixel(10, 5).y == Approx(100));  // y up: the top edge
    CHECK(d.to_pixel(5, 2.5).y == Approx(150));  // the centre of the rectangle
    // A window offset from the origin, taller than wide: the width is centred instead.
    d.view(-2, 10, 0, 14, 0, 0, 100, 100);
    CHECK(d.scale() == Approx(25));
    CHECK(d.to_pixel(-2, 14).x == Approx(25));
    CHECK(d.to_pixel(-2, 14).y == Approx(0));
    CHECK(d.to_pixel(0, 10).x == Approx(75));
    CHECK(d.to_pixel(0, 10).y == Approx(100));
    d.pixels();
    CHECK(d.to_pixel(7, 8).y == Approx(8));
}

TEST_CASE("diagram: shapes land where the view puts them, rectangles from any two corners", "[common][diagram]") {
    diagram d(200, 100);
    d.view(0, 0, 2, 1, 0, 0, 200, 100);  // 100 pixels per unit
    d.rect(1.5, 1.0, 0.5, 0.25, {ink::black, ink::pale_blue, 2.0});
    d.line(0, 0, 2, 1, {ink::red, "none", 1.0, true});
    d.circle(1, 0.5, 4, {"none", ink::green});
    const std::string svg = d.svg();
    CHECK_THAT(svg, Contains("<rect x=\"50\" y=\"0\" width=\"100\" height=\"75\" fill=\"#d4e5f5\" stroke=\"#222222\" "
                             "stroke-width=\"2\"/>"));
    CHECK_THAT(svg, Contains("<line x1=\"0\" y1=\"100\" x2=\"200\" y2=\"0\""));
    CHECK_THAT(svg, Contains("stroke-dasharray"));
    CHECK_THAT(svg, Contains("<circle cx=\"100\" cy=\"50\" r=\"4\" fill=\"#2e8b2e\" stroke=\"none\"/>"));
    CHECK_THAT(svg, Contains("width=\"200\" height=\"100\""));
}

TEST_CASE("diagram: text is escaped, and the SVG is well formed", "[common][diagram]") {
    CHECK(svg_escape("a < b && c > \"d\"") == "a &lt; b &amp;&amp; c &gt; &quot;d&quot;");
    CHECK(svg_escape("plain") == "plain");
    diagram d(300, 200);
    d.text(10, 20, "t0 < t_split & t1 > 0", {14, "middle", ink::black, true, true});
    d.text(10, 40, "L <-> RL");
    d.polygon({{0, 0}, {10, 0}, {5, 8}}, {ink::orange, ink::pale_orange});
    d.arrow(0, 0, 100, 0, {ink::red, "none", 1.5}, 20.0);
    const std::string svg = d.svg();
    CHECK_THAT(svg, Contains(">t0 &lt; t_split &amp; t1 &gt; 0</text>"));
    CHECK_THAT(svg, Contains(">L &lt;-&gt; RL</text>"));
    CHECK_THAT(svg, Contains("text-anchor=\"middle\""));
    CHECK_THAT(svg, Contains("font-weight=\"bold\""));
    CHECK_THAT(svg, Contains("paint-order=\"stroke\""));
    CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
    CHECK(svg.find("</svg>") == svg.size() - 7);
    CHECK(count(svg, "<text") == 2);
    CHECK(count(svg, "<polygon") == 2);  // the triangle and the arrow's head
    CHECK(count(svg, "<path") == 1);     // the arrow's curved body
    CHECK(balanced(svg));
    CHECK_FALSE(balanced("<svg><text>a < b</text></svg>"));
    CHECK_FALSE(balanced("<svg><g></svg>"));
    // Written to a file as it is.
    const auto file = test::scratch_dir("diagram") / "d.svg";
    d.write(file);
    std::ifstream in(file);
    std::stringstream back;
    back << in.rdbuf();
    CHECK(back.str() == svg);
}
