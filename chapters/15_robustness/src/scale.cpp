// Chapter 15's scale experiment (scale.hpp).
#include "strahl/ch15/scale.hpp"
#include "strahl/ch15/embree_robust.hpp"
#include "strahl/ch15/experiments.hpp"
#include "strahl/ch15/robust_bvh.hpp"
#include "strahl/machine.hpp"
#include "strahl/plot.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/progress.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace strahl::ch15 {

namespace {

namespace fs = std::filesystem;

const std::string scale_header = "scale,extent,coordinate,test,rays,hits,expected";

// The smallest |det| = |e1 . (d x e2)| (two lengths) and |t's numerator| = |e2 . ((org - v0) x e1)| (three)
// of the closest hits, in double, where the rays hit at scale 1.
void print_smallest_products(const triangle_mesh& m, const std::vector<ray>& rays) {
    brute_tests<test_kind::mt> brute;
    scene s;
    s.mesh = m;
    brute.build(s);
    std::vector<hit> hits(rays.size());
    brute.intersect(rays, hits);
    double det_min = inf, num_min = inf;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        if (!hits[i].found()) continue;
        const std::array<vec3, 3> t = m.triangle(hits[i].prim);
        const glm::dvec3 v0(t[0]), e1 = glm::dvec3(t[1]) - v0, e2 = glm::dvec3(t[2]) - v0, d(rays[i].dir);
        const glm::dvec3 q = glm::cross(glm::dvec3(rays[i].org) - v0, e1);
        det_min = std::min(det_min, std::abs(glm::dot(e1, glm::cross(d, e2))));
        num_min = std::min(num_min, std::abs(glm::dot(e2, q)));
    }
    const double normal = 0x1p-126, least = 0x1p-149;
    std::printf("  at scale 1, the hits' smallest |det| (two lengths) %.3g, smallest |t's numerator| (three lengths) "
                "%.3g: scaled by s they become s^2 and s^3 times that.\n  t's numerator leaves float's normal range "
                "(2^-126, 1.2e-38; flush-to-zero makes it 0) below s = %.3g and rounds to 0 (below 2^-150) below "
                "s = %.3g;\n  det leaves it below s = %.3g (and 1/det overflows below about s = %.3g)\n",
                det_min, num_min, std::cbrt(normal / num_min), std::cbrt(0.5 * least / num_min),
                std::sqrt(normal / det_min), std::sqrt(0x1p-128 / det_min));
}

// Brute force with test K, no ray frame (the triangle test alone: nothing is far here, and a frame computed
// from a vanishing box would itself misbehave), its hits on rays.
template <test_kind K>
std::size_t brute_hits(const scene& s, const std::vector<ray>& rays) {
    brute_tests<K> a;
    a.build(s);
    a.set_frame(ray_frame());
    return count_hits(a, rays);
}
std::size_t brute_hits(test_kind k, const scene& s, const std::vector<ray>& rays) {
    switch (k) {
        case test_kind::mt: return brute_hits<test_kind::mt>(s, rays);
        case test_kind::mt_epsilon: return brute_hits<test_kind::mt_epsilon>(s, rays);
        case test_kind::mt_edges: return brute_hits<test_kind::mt_edges>(s, rays);
        case test_kind::watertight: return brute_hits<test_kind::watertight>(s, rays);
        case test_kind::watertight_double: return brute_hits<test_kind::watertight_double>(s, rays);
    }
    return 0;
}

}  // namespace

std::vector<scale_row> run_scale(bool quick) {
    const int w = quick ? 16 : 64, h = quick ? 12 : 48;
    std::printf("\n2c. the small and the large extreme: the teapot (builtin_scene(\"teapot\")'s mesh) and %d x %d "
                "primary rays scaled by 2^k, k nearest each decade from 1e-30 to 1e16; brute force with each test "
                "(no ray frame) and Embree, hits against their own at scale 1\n", w, h);
    const triangle_mesh teapot = teapot_mesh(8);
    const std::vector<ray> rays = scale_view_rays(w, h);
    print_smallest_products(teapot, rays);
    const bool embree = embree_available();
    if (!embree) std::printf("  Embree: not available in this build (no embree rows)\n");
    const std::vector<float> steps = scale_steps(-30, 16);
    std::vector<std::string> tests;
    for (const test_kind k : all_tests) tests.push_back(name(k));
    if (embree) tests.push_back("embree"), tests.push_back("embree-robust");
    // Hits of test `which` on the teapot scaled by s.
    const auto hits_at = [&](std::size_t which, float s) -> std::size_t {
        const std::vector<ray> r = scaled(rays, s);
        scene sc;
        sc.name = "teapot";
        sc.mesh = scaled(teapot, s);
        if (which < std::size(all_tests)) return brute_hits(all_tests[which], sc, r);
        const std::vector<std::uint8_t> f = embree_found(sc.mesh, r, tests[which] == "embree-robust");
        return std::size_t(std::count(f.begin(), f.end(), std::uint8_t(1)));
    };
    const float extent = largest_side(teapot);
    float reach = 0.0f;
    for (const vec3& p : teapot.positions) reach = std::max({reach, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    std::vector<scale_row> rows;
    progress_bar bar("scale", tests.size() * (steps.size() + 1), "runs");
    for (std::size_t k = 0; k < tests.size(); ++k) {
        const std::size_t expected = hits_at(k, 1.0f);
        bar.add();
        for (const float s : steps) {
            rows.push_back({double(s), double(extent * s), double(reach * s), tests[k], rays.size(), hits_at(k, s), expected});
            bar.add();
        }
    }
    bar.finish();
    // The table: a row per scale, per test its hits of those at scale 1.
    std::printf("  %-10s %-10s", "scale", "extent");
    for (const std::string& t : tests) std::printf(" %17s", t.c_str());
    std::printf("\n");
    for (std::size_t i = 0; i < steps.size(); ++i) {
        std::printf("  %-10.3g %-10.3g", double(steps[i]), double(extent * steps[i]));
        for (std::size_t k = 0; k < tests.size(); ++k) {
            const scale_row& r = rows[k * steps.size() + i];
            std::printf(" %11zu/%5zu", r.hits, r.expected);
        }
        std::printf("\n");
    }
    return rows;
}

std::string scale_csv(const std::vector<scale_row>& rows) {
    std::ostringstream csv;
    csv << scale_header << '\n';
    for (const scale_row& r : rows)
        csv << r.scale << ',' << r.extent << ',' << r.coordinate << ',' << r.test << ',' << r.rays << ',' << r.hits
            << ',' << r.expected << '\n';
    return csv.str();
}

// --replot: the rows of a scale.csv this program wrote.
std::vector<scale_row> read_scale_csv(const fs::path& file) {
    std::vector<scale_row> rows;
    for (const csv_row& r : read_csv(file, scale_header, machine_header, "a scale.csv written by ch15")) {
        const auto num = [&](std::size_t k) { return csv_number(file, r, k); };
        rows.push_back({num(0), num(1), num(2), r.cells[3], std::size_t(num(4)), std::size_t(num(5)), std::size_t(num(6))});
    }
    return rows;
}

// Hits found (as a fraction of those at scale 1) against the teapot's extent, a line per test; dashed, the
// course's range: min_extent, and the extent at which the teapot's largest coordinate reaches max_coordinate.
void write_scale_plot(const std::vector<scale_row>& rows, const fs::path& svg) {
    plot p{"Hits against the scene's size: the teapot scaled by powers of two (chapter 15)",
           "the teapot's extent (largest side of its box), units", "hits found / hits at scale 1", true, false, {}};
    std::vector<std::string> order;
    double per_coordinate = 0;  // extent / largest coordinate (the same in every row)
    for (const scale_row& r : rows) {
        if (std::find(order.begin(), order.end(), r.test) == order.end()) order.push_back(r.test);
        if (r.coordinate > 0) per_coordinate = r.extent / r.coordinate;
    }
    // Tests that find as many hits at every scale share one line ("mt = mt-edges"); the watertight tests are
    // dashed, so that the Moeller-Trumbore line shows where it runs under them.
    for (std::size_t k = 0; k < order.size(); ++k) {
        plot_series s{order[k], {}, {}, true, {}, int(k)};
        for (const scale_row& r : rows)
            if (r.test == order[k]) s.x.push_back(r.extent), s.y.push_back(r.expected ? double(r.hits) / double(r.expected) : 0.0);
        s.dashed = order[k].rfind("watertight", 0) == 0;
        bool merged = false;
        for (plot_series& before : p.series)
            if (before.x == s.x && before.y == s.y) before.label += " = " + s.label, merged = true;
        if (!merged) p.series.push_back(s);
    }
    const auto rule = [&](const std::string& label, double x) {
        plot_series line{label, {x, x}, {0.0, 1.0}, true, {}, 9};
        line.dashed = true, line.markers = false;
        p.series.push_back(line);
    };
    const auto decade = [](float v) { return "1e" + std::to_string(std::lround(std::log10(double(v)))); };
    rule("extent " + decade(min_extent) + " (min_extent)", double(min_extent));
    if (per_coordinate > 0) rule("coordinates " + decade(max_coordinate) + " (max_coordinate)", double(max_coordinate) * per_coordinate);
    write_svg(svg, to_svg(p, 900, 520));
}

}  // namespace strahl::ch15
