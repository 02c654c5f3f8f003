// Unit tests of common/'s SVG plots: label placement, the plot's options, small multiples and bar charts.
#include <catch2/catch.hpp>
#include "strahl/plot.hpp"
#include <cmath>
#include <regex>
#include <string>
#include <vector>

using namespace strahl;
using Catch::Matchers::Contains;

namespace {

double overlap_area(const label_box& a, const label_box& b) {
    const double w = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x);
    const double h = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
    return w > 0 && h > 0 ? w * h : 0.0;
}

bool inside(const label_box& b, const label_box& frame) {
    return b.x >= frame.x && b.y >= frame.y && b.x + b.w <= frame.x + frame.w && b.y + b.h <= frame.y + frame.h;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("plot labels: a crowded cluster gets labels that overlap neither each other nor any point", "[common][plot]") {
    // Nine points within 12 pixels of each other, in a frame with room around them: the old placement
    // (every label up and right of its point) overlapped all of them.
    const label_box frame{0, 0, 600, 400};
    std::vector<std::array<double, 2>> points;
    std::vector<std::string> texts;
    for (int i = 0; i < 9; ++i) {
        points.push_back({300.0 + 4.0 * (i % 3), 200.0 + 4.0 * (i / 3)});
        texts.push_back("binned" + std::to_string(4 << i));
    }
    const std::vector<label_place> placed = place_labels(points, texts, frame);
    REQUIRE(placed.size() == texts.size());
    for (std::size_t i = 0; i < placed.size(); ++i) {
        INFO("label " << texts[i]);
        CHECK(placed[i].clear);
        CHECK(inside(placed[i].box, frame));
        CHECK(placed[i].box.w >= 6.0 * double(texts[i].size()) * 0.99);  // sized from the text
        for (std::size_t j = 0; j < i; ++j) CHECK(overlap_area(placed[i].box, placed[j].box) == 0.0);
        for (const auto& [px, py] : points) CHECK(overlap_area(placed[i].box, {px - 3.5, py - 3.5, 7, 7}) == 0.0);
    }
    // Nine labels cannot all touch the cluster: some are set further out, with a leader line.
    std::size_t leaders = 0;
    for (const label_place& p : placed) leaders += p.leader;
    CHECK(leaders > 0);
}

TEST_CASE("plot labels: a lone point keeps its label beside it, at the frame's edge the label turns inwards", "[common][plot]") {
    const label_box frame{0, 0, 300, 200};
    const auto alone = place_labels({{100, 100}}, {"median"}, frame);
    REQUIRE(alone.size() == 1);
    CHECK_FALSE(alone[0].leader);
    CHECK(alone[0].box.x > 100.0);  // the first choice: to the right
    CHECK(std::abs(alone[0].box.y + alone[0].box.h / 2 - 100.0) < 1e-9);
    const auto edge = place_labels({{298, 100}}, {"sweep"}, frame);
    REQUIRE(edge.size() == 1);
    CHECK(inside(edge[0].box, frame));
    CHECK(edge[0].box.x + edge[0].box.w < 298.0);  // to the left of its point
    // No room anywhere: still a place (the least bad), marked as not clear, never a crash.
    const auto cramped = place_labels({{5, 5}}, {"a label far too long for its frame"}, {0, 0, 10, 10});
    REQUIRE(cramped.size() == 1);
    CHECK_FALSE(cramped[0].clear);
}

TEST_CASE("plot: colours, dashes, legend entries and a y axis fitted to the data", "[common][plot]") {
    plot p{"t", "x", "y", false, false, {}};
    plot_series a{"first", {1, 2, 3}, {10, 11, 12}, true, {"p", "q", "r"}, 4};
    plot_series b{"hidden", {1.5}, {10.5}, false, {"s"}, 4};
    b.in_legend = false;
    plot_series c{"reference", {1, 3}, {11, 11}, true, {}, 8};
    c.dashed = true;
    p.series = {a, b, c};
    const std::string svg = to_svg(p);
    CHECK(count(svg, "fill=\"#9467bd\"") == 5);   // palette 4: a's three points, b's one, a's legend swatch
    CHECK(count(svg, "stroke=\"#9467bd\"") == 1);  // a's line; b has none
    CHECK(count(svg, "stroke-dasharray") == 1);    // c's line
    CHECK_THAT(svg, Contains(">first</text>"));
    CHECK_THAT(svg, Contains(">reference</text>"));
    CHECK_THAT(svg, !Contains(">hidden</text>"));
    CHECK_THAT(svg, Contains(">s</text>"));        // b's point label is drawn all the same
    // From zero by default: a tick at 0; fitted: the lowest tick is near the data.
    CHECK_THAT(svg, Contains("text-anchor=\"end\">0</text>"));
    p.y_from_zero = false;
    CHECK_THAT(to_svg(p), !Contains("text-anchor=\"end\">0</text>"));
    // Non-finite values are left out, never written as coordinates.
    p.series[0].y[1] = std::nan("");
    const std::string with_nan = to_svg(p);
    CHECK_THAT(with_nan, !Contains("nan"));
    CHECK(count(with_nan, "<circle") == 5);
}

TEST_CASE("plot: small multiples place each panel in its cell", "[common][plot]") {
    std::vector<plot> panels(3, plot{"panel", "x", "y", false, false, {{"s", {1, 2}, {1, 2}, true, {}}}});
    const std::string svg = to_svg(panels, 2, 300, 200);
    CHECK_THAT(svg, Contains("width=\"600\" height=\"400\""));  // 2 columns, 2 rows
    CHECK(count(svg, "<svg") == 4);
    CHECK_THAT(svg, Contains("<svg x=\"0\" y=\"0\""));
    CHECK_THAT(svg, Contains("<svg x=\"300\" y=\"0\""));
    CHECK_THAT(svg, Contains("<svg x=\"0\" y=\"200\""));
    CHECK(count(svg, "</svg>") == 4);
    CHECK(count(to_svg(std::vector<plot>{}, 3), "<svg") == 1);  // no panels: an empty picture, no crash
}

TEST_CASE("bar chart: many categories slant their names steeply and the picture grows to fit them", "[common][plot]") {
    bar_chart few{"t", "y", {"a", "b", "c"}, {"s"}, {{1, 2, 3}}, false};
    const std::string small = to_svg(few, 720, 440);
    CHECK_THAT(small, Contains("rotate(20)"));
    CHECK_THAT(small, Contains("height=\"440\""));
    bar_chart many{"t", "y", {}, {"s"}, {{}}, true};
    for (int i = 0; i < 19; ++i) {
        many.categories.push_back("embree-medium-packet8-" + std::to_string(i));
        many.values[0].push_back(1.0 + i);
    }
    const std::string big = to_svg(many, 720, 440);
    CHECK_THAT(big, Contains("rotate(50)"));
    const std::regex height("<svg[^>]* height=\"([0-9]+)\"");
    std::smatch m;
    REQUIRE(std::regex_search(big, m, height));
    CHECK(std::stoi(m[1]) > 440);
}
