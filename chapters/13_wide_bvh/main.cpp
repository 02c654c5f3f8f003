// ch13: the wide BVH. Chapter 05's binned SAH tree, walked as a binary tree by chapter 05's fast traversal,
// against the same tree collapsed into 4-, 8- and 16-wide nodes (greedy and SAH-optimal collapse, leaves in
// blocks of 4 or 8 triangles), on the teapot in a stadium, the bunny and Sponza (when the shared meshes are
// there): primary, diffuse and shadow rays on one thread, Mrays/s, nodes, boxes and triangle lanes per ray,
// memory. Every tree's answers are checked against the binary tree's. A table, a CSV file and a plot.
#include "strahl/diagram.hpp"
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch05/accel.hpp"
#include "strahl/ch13/accel.hpp"
#include "strahl/machine.hpp"
#include "strahl/parallel.hpp"
#include "strahl/plot.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/timer.hpp"
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>

namespace strahl::ch13 {
// The chapter's figure (src/diagrams.cpp): a binary tree and its 4-wide collapse, by the chapter's own code.
std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force);
}  // namespace strahl::ch13

namespace {

using namespace strahl;
namespace fs = std::filesystem;

struct row {
    std::string scene, tree;
    double build_ms = 0, memory_mib = 0, primary = 0, diffuse = 0, shadow = 0;
    double nodes_per_ray = 0, boxes_per_ray = 0, lanes_per_ray = 0;  // diffuse rays, counted
    std::size_t differing = 0;
};

struct variant {
    std::string label;
    std::function<std::unique_ptr<accel>()> make;
};

std::vector<variant> variants(bool quick) {
    const auto binned = [](std::span<const aabb> b, std::span<const vec3> c) { return ch05::build_sah_bvh_fast(b, c); };
    const auto wide = [binned](const std::string& label, int n, int m, ch13::collapse_method method) {
        ch13::wide_config c;
        c.width = n, c.block = m, c.collapse.method = method;
        return variant{label, [=] { return std::unique_ptr<accel>(ch13::make_accel(label, binned, c)); }};
    };
    using ch13::collapse_method;
    std::vector<variant> v = {
        {"bvh2", [] { return std::unique_ptr<accel>(ch05::make_accel(false, {}, ch05::walk_kind::fast)); }},
        wide("bvh4", 4, 4, collapse_method::greedy),
        wide("bvh8", 8, 4, collapse_method::greedy),
        wide("bvh8-optimal", 8, 4, collapse_method::optimal),
    };
    if (quick) return v;
    v.push_back(wide("bvh4-optimal", 4, 4, collapse_method::optimal));
    v.push_back(wide("bvh8-block8", 8, 8, collapse_method::optimal));
    v.push_back(wide("bvh16", 16, 4, collapse_method::optimal));
    return v;
}

std::vector<row> run_scene(const scene& s, const std::string& name, int width, int height, int repeats, bool quick) {
    std::printf("%s: %zu triangles; %d x %d primary rays, as many diffuse and shadow rays; one thread, median of %d\n",
                name.c_str(), s.mesh.triangle_count(), width, height, repeats);
    const auto reference = ch05::make_accel(false, {}, ch05::walk_kind::fast);
    reference->build(s);
    const ch01::checked_rays rays = ch01::make_checked_rays(s, width, height, *reference);
    const std::vector<ray> shadow = ch01::secondary_rays(ch01::ray_kind::shadow, s, rays.primary, rays.primary_hits);
    std::vector<std::uint8_t> shadow_ref(shadow.size());
    reference->occluded(shadow, shadow_ref);
    std::printf("  %-13s %9s %8s %9s %9s %9s %10s %10s %10s %6s\n", "tree", "build ms", "MiB", "primary", "diffuse",
                "shadow", "nodes/ray", "boxes/ray", "lanes/ray", "differ");
    std::vector<row> rows;
    for (const variant& v : variants(quick)) {
        row r{name, v.label};
        std::unique_ptr<accel> a;
        r.build_ms = median_ms(repeats, [&] { a = v.make(), a->build(s); });
        r.memory_mib = double(a->memory_bytes()) / (1024.0 * 1024.0);
        const ch01::checked_speed speed = ch01::time_checked(*a, rays, repeats);
        r.primary = speed.primary_mrays, r.diffuse = speed.diffuse_mrays, r.differing = speed.differing;
        std::vector<std::uint8_t> blocked(shadow.size());
        const double shadow_ms = median_ms(repeats, [&] { a->occluded(shadow, blocked); });
        r.shadow = shadow_ms > 0 ? double(shadow.size()) / shadow_ms * 1e-3 : 0.0;
        for (std::size_t i = 0; i < shadow.size(); ++i) r.differing += blocked[i] != shadow_ref[i];
        std::vector<hit> dhits(rays.diffuse.size());
        if (const auto c = a->intersect_counted(rays.diffuse, dhits)) {
            r.nodes_per_ray = c->per_ray(c->nodes_visited);
            r.boxes_per_ray = c->per_ray(c->box_tests);
            r.lanes_per_ray = c->per_ray(c->prim_tests);
        }
        std::printf("  %-13s %9.2f %8.2f %9.2f %9.2f %9.2f %10.1f %10.1f %10.1f %6zu\n", r.tree.c_str(), r.build_ms,
                    r.memory_mib, r.primary, r.diffuse, r.shadow, r.nodes_per_ray, r.boxes_per_ray, r.lanes_per_ray,
                    r.differing);
        std::fflush(stdout);
        rows.push_back(r);
    }
    return rows;
}

const char* const csv_header = "scene,tree,build_ms,memory_mib,primary_mrays_s,diffuse_mrays_s,shadow_mrays_s,"
                               "nodes_per_ray,boxes_per_ray,lanes_per_ray,differing";

void write_table(const std::vector<row>& rows, const fs::path& csv) {
    std::ostringstream text;
    text << csv_header << '\n';
    for (const row& r : rows)
        text << r.scene << ',' << r.tree << ',' << r.build_ms << ',' << r.memory_mib << ',' << r.primary << ','
             << r.diffuse << ',' << r.shadow << ',' << r.nodes_per_ray << ',' << r.boxes_per_ray << ','
             << r.lanes_per_ray << ',' << r.differing << '\n';
    std::ofstream f(csv);
    f << with_machine(text.str(), this_machine(parallel_threads()));
    f.close();
    if (!f) throw std::runtime_error("cannot write " + csv.string());
}

// Each wide tree's speed-up over the binary tree on the same rays: one group of bars per tree, one bar per
// scene and ray set.
void write_plot(const std::vector<row>& rows, const fs::path& svg) {
    bar_chart c{"Speed-up over the binary tree (chapter 05's fast traversal), one thread", "x BVH2", {}, {}, {}, false};
    std::vector<std::string> scenes;
    for (const row& r : rows) {
        if (std::find(c.categories.begin(), c.categories.end(), r.tree) == c.categories.end() && r.tree != "bvh2")
            c.categories.push_back(r.tree);
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    }
    for (const std::string& s : scenes)
        for (const char* kind : {"primary", "diffuse", "shadow"}) {
            const row* base = nullptr;
            for (const row& r : rows)
                if (r.scene == s && r.tree == "bvh2") base = &r;
            if (!base) continue;
            std::vector<double> values;
            for (const std::string& t : c.categories) {
                double v = 0;
                for (const row& r : rows)
                    if (r.scene == s && r.tree == t) {
                        const std::string k = kind;
                        v = k == "primary" ? r.primary / base->primary
                            : k == "diffuse" ? r.diffuse / base->diffuse : r.shadow / base->shadow;
                    }
                values.push_back(v);
            }
            c.series_labels.push_back(s + " " + kind);
            c.values.push_back(values);
        }
    write_svg(svg, to_svg(c, 820, 460));
}

int run(int argc, const char* const* argv) {
    cli args("ch13", "Chapter 13, the wide BVH (" + std::string(track_name()) + "): chapter 05's binned SAH tree as a binary tree and "
             "collapsed into 4-, 8- and 16-wide nodes; primary, diffuse and shadow rays on one thread; Mrays/s, "
             "nodes, boxes and triangle lanes per ray, memory; a table, a CSV file and a plot.");
    args.scene_option({"stadium", "bunny", "sponza"}, {"stadium", "bunny", "sponza"}, "the meshes where present")
        .option("width", "N", "", "primary rays per row (default 192, 96 with --quick)")
        .option("height", "N", "", "rows (default 3/4 of the width)")
        .option("repeats", "K", "5", "timed runs per measurement after a warm-up; the median is reported")
        .output_options("write wide.csv and speedup.svg into DIR/ (default out/13_wide_bvh/)")
        .flag("quick", "the teapot in a stadium only, 96 x 72 rays, four trees")
        .option("diagrams", "DIR", "", "only draw the chapter's figure into DIR/ (collapse.svg; --force to replace it)");
    if (!args.parse(argc, argv)) return 0;
    if (draw_diagrams_if_asked(args, strahl::ch13::write_diagrams)) return 0;
    const bool quick = args.has("quick");
    fs::path folder = "out/13_wide_bvh";
    const bool user_named = args.has("out");
    if (user_named) folder = args.get("out");
    const fs::path csv = folder / "wide.csv", svg = folder / "speedup.svg";
    for (const fs::path& p : {csv, svg}) prepare_output(p, user_named, args.has("force"));
    const image_size size = read_image_size(args, quick ? 96 : 192, 4096);
    const int repeats = args.get_int("repeats");
    if (repeats < 1 || repeats > 100) throw usage_error("--repeats must lie in [1, 100]");
    std::vector<std::string> names = args.scene_names();
    if (quick) names = {"stadium"};
    const thread_limit one(1);
    std::printf("SIMD in this build (lanes: backend): %s\n", ch13::simd_widths().c_str());
    std::vector<row> rows;
    const auto add = [&](const std::vector<row>& r) { rows.insert(rows.end(), r.begin(), r.end()); };
    for (const std::string& name : names)
        if (const auto s = course_scene(name)) add(run_scene(*s, name, size.width, size.height, repeats, quick));
    write_table(rows, csv);
    write_plot(rows, svg);
    std::printf("wrote %s, %s\n", csv.string().c_str(), svg.string().c_str());
    std::size_t wrong = 0;
    for (const row& r : rows) wrong += r.differing;
    if (wrong) {
        std::printf("%zu answers differ from the binary tree's: a bug\n", wrong);
        return 1;
    }
    std::printf("against Embree on the same rays: build/release/bin/race --accels ch05-binned16-fast,ch13-bvh8,"
                "ch13-bvh8-optimal,embree-medium\n");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch13_exercise" : "ch13", run, argc, argv);
}
