// ch05: the surface area heuristic. Builds chapter 04's median BVH, the full-sweep SAH BVH and binned SAH
// BVHs with 4 to 256 bins over the teapot in a stadium, the bunny and Sponza (when the shared meshes are
// there), traces the same primary and diffuse rays through each, and prints and plots the trade: build
// time against SAH cost against Mrays/s. Every tree's hits are checked against the median tree's.
#include "strahl/diagram.hpp"
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch05/accel.hpp"
#include "strahl/image.hpp"
#include "strahl/machine.hpp"
#include "strahl/parallel.hpp"
#include "strahl/plot.hpp"
#include "strahl/primary_trace.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace strahl::ch05 {
// The chapter's figure (src/diagrams.cpp): an SVG file priced by the chapter's own functions.
std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force);
}  // namespace strahl::ch05

namespace {

using namespace strahl;
using namespace strahl::ch05;
namespace fs = std::filesystem;

struct options {
    int width = 192, height = 144, repeats = 3;
    std::vector<int> bins;
    sah_costs costs;
    fs::path folder{"out/05_sah"};
    bool user_named = false, force = false;
};

struct variant {
    std::string label;  // "median", "sweep", "binned16", ...
    int bins = 0;       // 0 for the median and the sweep
    double build_ms = 0, sah = 0, primary_mrays = 0, diffuse_mrays = 0, boxes_per_ray = 0, tris_per_ray = 0;
    std::size_t nodes = 0, differing = 0;
    int depth = 0;
};

// Where the box tests go: box tests per primary ray, pixel by pixel, through the median tree (left half) and
// the binned SAH tree with 16 bins (right half), both walked by chapter 04's traversal and drawn on one
// colour scale, so the halves differ only by the tree.
void write_box_test_map(const scene& s, const std::string& name, const options& o, const fs::path& path) {
    const camera cam(s.camera, o.width, o.height);
    std::vector<float> both(std::size_t(2 * o.width) * std::size_t(o.height));
    sah_build_params p;
    p.costs = o.costs;
    p.bins = 16;
    const std::unique_ptr<ch04::bvh_accel_base> trees[] = {ch04::make_bvh_accel(false), make_accel(false, p)};
    for (int half = 0; half < 2; ++half) {
        trees[half]->build(s);
        const primary_trace r = trace_primary(*trees[half], cam, name + " " + trees[half]->name());
        for (int y = 0; y < o.height; ++y)
            for (int x = 0; x < o.width; ++x)
                both[std::size_t(y) * 2 * o.width + half * o.width + x] = r.box_tests[std::size_t(y) * o.width + x];
    }
    const char* label = o.width >= 128 ? "box tests per ray: median | SAH" : "median | SAH";  // fits the width
    write_image(path, heat_map(both, 2 * o.width, o.height, label));
    std::printf("  wrote %s\n", path.string().c_str());
}

std::vector<variant> run_scene(const scene& s, const std::string& name, const options& o) {
    const fs::path map_path = o.folder / (name + "_box_tests.png");
    prepare_output(map_path, o.user_named, o.force);
    std::printf("%s: %zu triangles; %d x %d primary rays and as many diffuse; build and trace on one thread, "
                "median of %d\n",
                s.name.c_str(), s.mesh.triangle_count(), o.width, o.height, o.repeats);
    // The rays: primary from the camera, diffuse from their hits (chapter 01's ray sets), with the
    // median BVH as the exact reference the other trees must agree with.
    const auto reference = ch04::make_bvh_accel(false);
    reference->build(s);
    const ch01::checked_rays rays = ch01::make_checked_rays(s, o.width, o.height, *reference);

    std::vector<variant> rows;
    const auto measure = [&](variant v, const std::function<std::unique_ptr<ch04::bvh_accel_base>()>& make) {
        std::unique_ptr<ch04::bvh_accel_base> a;
        v.build_ms = median_ms(o.repeats, [&] { a = make(), a->build(s); });
        const ch04::bvh& t = a->tree();
        v.sah = ch04::sah_tree_cost(t, o.costs.traversal, o.costs.intersection);
        v.nodes = t.nodes.size();
        v.depth = t.stats.depth;
        const ch01::checked_speed speed = ch01::time_checked(*a, rays, o.repeats);
        v.differing = speed.differing;
        v.primary_mrays = speed.primary_mrays;
        v.diffuse_mrays = speed.diffuse_mrays;
        std::vector<hit> dhits(rays.diffuse.size());
        const auto counts = a->intersect_counted(rays.diffuse, dhits);
        v.boxes_per_ray = counts ? counts->per_ray(counts->box_tests) : 0.0;
        v.tris_per_ray = counts ? counts->per_ray(counts->prim_tests) : 0.0;
        std::printf("  %-10s %10.2f %8.2f %8zu %5d %9.2f %9.2f %9.1f %9.1f %6zu\n", v.label.c_str(), v.build_ms, v.sah,
                    v.nodes, v.depth, v.primary_mrays, v.diffuse_mrays, v.boxes_per_ray, v.tris_per_ray, v.differing);
        std::fflush(stdout);
        rows.push_back(v);
    };
    std::printf("  %-10s %10s %8s %8s %5s %9s %9s %9s %9s %6s\n", "tree", "build ms", "SAH", "nodes", "depth",
                "primary", "diffuse", "boxes/ray", "tris/ray", "differ");
    std::printf("  %-10s %10s %8s %8s %5s %9s %9s %9s %9s %6s\n", "", "", "", "", "", "Mrays/s", "Mrays/s",
                "(diffuse)", "(diffuse)", "");
    measure({"median"}, [] { return ch04::make_bvh_accel(false); });
    sah_build_params p;
    p.costs = o.costs;
    p.method = sah_method::sweep;
    measure({"sweep"}, [p] { return make_accel(false, p); });
    p.method = sah_method::binned;
    for (const int k : o.bins) {
        p.bins = k;
        variant v{"binned" + std::to_string(k)};
        v.bins = k;
        measure(v, [p] { return make_accel(false, p); });
    }
    // The engineered row, as the race's ch05-binned16-fast: the same 16-bin tree from the fast builder,
    // walked by the fast traversal.
    p.bins = 16;
    measure({"fast16"}, [p] { return make_accel(false, p, walk_kind::fast); });
    write_box_test_map(s, name, o, map_path);
    return rows;
}

using scene_rows = std::vector<std::pair<std::string, std::vector<variant>>>;
const char* const csv_header = "scene,tree,bins,build_ms,sah_cost,nodes,depth,primary_mrays_s,diffuse_mrays_s,"
                               "boxes_per_ray,tris_per_ray,differing";

void write_table(const scene_rows& all, const fs::path& csv) {
    std::ostringstream text;
    text << csv_header << '\n';
    for (const auto& [name, rows] : all)
        for (const variant& v : rows)
            text << name << ',' << v.label << ',' << v.bins << ',' << v.build_ms << ',' << v.sah << ',' << v.nodes
                 << ',' << v.depth << ',' << v.primary_mrays << ',' << v.diffuse_mrays << ',' << v.boxes_per_ray
                 << ',' << v.tris_per_ray << ',' << v.differing << '\n';
    std::ofstream f(csv);
    f << with_machine(text.str(), this_machine(parallel_threads()));
    f.close();
    if (!f) throw std::runtime_error("cannot write " + csv.string());
}

// --replot: the rows of a bins.csv this program wrote, scene by scene in the file's order.
scene_rows read_table(const fs::path& csv) {
    scene_rows all;
    for (const csv_row& r : read_csv(csv, csv_header, machine_header, "a bins.csv written by ch05")) {
        const auto num = [&](std::size_t k) { return csv_number(csv, r, k); };
        variant v{r.cells[1], int(num(2))};
        v.build_ms = num(3), v.sah = num(4), v.nodes = std::size_t(num(5)), v.depth = int(num(6));
        v.primary_mrays = num(7), v.diffuse_mrays = num(8), v.boxes_per_ray = num(9), v.tris_per_ray = num(10);
        v.differing = std::size_t(num(11));
        if (all.empty() || all.back().first != r.cells[0]) all.emplace_back(r.cells[0], std::vector<variant>{});
        all.back().second.push_back(v);
    }
    return all;
}

void write_plots(const scene_rows& all, const fs::path& trade, const fs::path& cost) {
    // The trade per scene, one line in order of quality: the median tree, the binned trees by bin count, the
    // full sweep; the fast builder's 16-bin tree as a point of the same colour beside it.
    plot tp{"Build time against trace speed (diffuse rays, one thread)", "build time [ms]",
            "diffuse rays [Mrays/s]", true, false, {}};
    // SAH cost relative to the full sweep's, so that every scene reads on one scale.
    plot cp{"SAH cost of the binned trees relative to the full sweep's (dashed)", "bins per axis",
            "SAH cost / full sweep's SAH cost", true, false, {}};
    cp.y_from_zero = false;
    for (const auto& [name, rows] : all) {
        const int colour = int(tp.series.size());
        plot_series line{name, {}, {}, true, {}, colour}, fast{name + " (fast)", {}, {}, false, {}, colour};
        fast.in_legend = false;
        plot_series relative{name, {}, {}, true, {}, colour};
        const auto add = [](plot_series& ser, const variant& v) {
            ser.x.push_back(v.build_ms);
            ser.y.push_back(v.diffuse_mrays);
            ser.point_labels.push_back(v.bins ? std::to_string(v.bins) : v.label);
        };
        const variant* sweep = nullptr;
        for (const variant& v : rows)
            if (v.label == "sweep") sweep = &v;
        for (const variant& v : rows)
            if (v.label == "median") add(line, v);
        for (const variant& v : rows)
            if (v.bins) add(line, v);
        if (sweep) add(line, *sweep);
        for (const variant& v : rows)
            if (v.label != "median" && v.label != "sweep" && !v.bins) add(fast, v);
        tp.series.push_back(line);
        tp.series.push_back(fast);
        if (!sweep) continue;
        for (const variant& v : rows)
            if (v.bins) relative.x.push_back(v.bins), relative.y.push_back(v.sah / sweep->sah);
        cp.series.push_back(relative);
    }
    if (!cp.series.empty()) {
        // A dashed grey line at 1 across the bin counts plotted.
        plot_series one{"full sweep", {}, {1.0, 1.0}, true, {}, 8};
        one.dashed = true;
        const auto [fewest, most] = std::minmax_element(cp.series.front().x.begin(), cp.series.front().x.end());
        one.x = {*fewest, *most};
        cp.series.push_back(one);
    }
    write_svg(trade, to_svg(tp));
    write_svg(cost, to_svg(cp));
}

int run(int argc, const char* const* argv) {
    cli args("ch05", "Chapter 05, the surface area heuristic (" + std::string(track_name()) + "): median, full-sweep and binned "
             "SAH BVHs on the same rays; build time, SAH cost and Mrays/s per number of bins, as a table, a CSV "
             "file and two plots; box tests per pixel as a heat map, median against SAH.");
    args.scene_option({"stadium", "bunny", "sponza", "teapot"}, {"stadium", "bunny", "sponza"})
        .option("bins", "LIST", "4,8,16,32,64,128,256", "comma-separated bin counts, each in [2, 256]")
        .option("costs", "CT,CI", "1,1", "the SAH's traversal and intersection costs")
        .option("width", "N", "", "primary rays per row, 1..4096 (default 192, 96 with --quick)")
        .option("height", "N", "", "rows, 1..4096 (default 3/4 of the width)")
        .option("repeats", "K", "3", "timed runs per measurement after a warm-up; the median is reported")
        .output_options("write the CSV file, the plots and the heat maps into DIR/ (default out/05_sah/)")
        .option("replot", "CSV", "", "only redraw the two plots from a bins.csv written earlier (no building, no tracing)")
        .flag("quick", "the teapot in a stadium only, 96 x 72 rays, bins 4, 16, 64")
        .option("diagrams", "DIR", "", "only draw the chapter's figure into DIR/ (sweep_and_bins.svg; --force to "
                                       "replace it)");
    if (!args.parse(argc, argv)) return 0;
    if (draw_diagrams_if_asked(args, write_diagrams)) return 0;
    const bool quick = args.has("quick");
    options o;
    if (args.has("out")) o.folder = args.get("out"), o.user_named = true;
    o.force = args.has("force");
    const fs::path csv = o.folder / "bins.csv", trade = o.folder / "build_vs_trace.svg",
                   cost = o.folder / "bins_vs_sah.svg";
    if (args.has("replot")) {
        // The table read first: a file that is no bins.csv leaves no folder behind.
        const scene_rows rows = read_table(args.get("replot"));
        for (const fs::path& p : {trade, cost}) prepare_output(p, o.user_named, o.force);
        write_plots(rows, trade, cost);
        std::printf("wrote %s, %s from %s\n", trade.string().c_str(), cost.string().c_str(), args.get("replot").c_str());
        return 0;
    }
    // Every option is checked before anything is created, and every file this run writes before the work
    // starts, not after it. Per pixel: primary and diffuse rays with their hits, twice over (median and SAH
    // trees), the heat maps and their PNG rows: 200 bytes is ample.
    const image_size size = read_image_size(args, quick ? 96 : 192, 4096, 200);
    o.width = size.width, o.height = size.height;
    o.repeats = args.get_int("repeats");
    if (o.repeats < 1 || o.repeats > 100) throw usage_error("--repeats must lie in [1, 100]");
    o.bins = parse_int_list(quick && !args.has("bins") ? "4,16,64" : args.get("bins"), "bins", 2, 256);
    float ct = 0, ci = 0;
    char extra = 0;
    if (std::sscanf(args.get("costs").c_str(), "%f,%f%c", &ct, &ci, &extra) != 2 || !(ct > 0) || !(ci > 0) ||
        !std::isfinite(ct) || !std::isfinite(ci))
        throw usage_error("--costs wants two positive numbers CT,CI, not '" + args.get("costs") + "'");
    o.costs = {ct, ci};

    std::vector<std::string> names = args.scene_names();
    if (quick) names = {"stadium"};
    for (const fs::path& p : {csv, trade, cost}) prepare_output(p, o.user_named, o.force);
    const thread_limit one(1);  // the chapter's figures are single-threaded, as in the race's table
    scene_rows all;
    for (const std::string& name : names)
        if (const auto s = course_scene(name)) all.emplace_back(name, run_scene(*s, name, o));
    write_table(all, csv);
    write_plots(all, trade, cost);
    std::printf("wrote %s, %s, %s\n", csv.string().c_str(), trade.string().c_str(), cost.string().c_str());
    std::printf("against Embree on the same rays: build/release/bin/race --accels ch04-median,ch05-sweep,"
                "ch05-binned16,embree-medium\n");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch05_exercise" : "ch05", run, argc, argv);
}
