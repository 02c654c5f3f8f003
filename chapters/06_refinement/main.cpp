// ch06: refining a built BVH. Builds chapter 04's median tree and chapter 05's binned SAH tree (16 bins)
// over the teapot in a stadium, the bunny and Sponza (when the shared meshes are there), refines each by tree
// rotations (Kensler 2008) and by reinsertion (Bittner, Hapala and Havran 2013) under growing iteration
// budgets, and prints and plots the trade: SAH cost against refinement time; then traces the same primary
// and diffuse rays through each start tree and each fully refined tree (Mrays/s before and after). Every
// tree's hits are checked against the median tree's.
#include "strahl/diagram.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch06/accel.hpp"
#include "strahl/machine.hpp"
#include "strahl/parallel.hpp"
#include "strahl/plot.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace strahl::ch06 {
// The chapter's figure (src/diagrams.cpp): an SVG file computed by the chapter's own rotation code.
std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force);
}  // namespace strahl::ch06

namespace {

using namespace strahl;
using namespace strahl::ch06;
namespace fs = std::filesystem;

struct options {
    int width = 192, height = 144, repeats = 3;
    std::vector<int> rotation_budgets{1, 2, 4, 8, 64}, reinsertion_budgets{1, 4, 16, 64, 256};
    fs::path folder{"out/06_refinement"};
    bool user_named = false, force = false;
};

// One refinement: a start tree, a method (or none: the start tree itself), an iteration budget.
struct row {
    std::string scene, start, method;
    int budget = 0, iterations = 0, depth = 0;
    std::size_t moves = 0, nodes = 0, differing = 0;
    double ms = 0, sah_before = 0, sah_after = 0, primary_mrays = 0, diffuse_mrays = 0;  // Mrays/s: 0 = not traced
};

std::vector<row> run_scene(const scene& s, const options& o) {
    std::printf("%s: %zu triangles; %d x %d primary rays and as many diffuse; refine and trace on one thread, "
                "median of %d\n",
                s.name.c_str(), s.mesh.triangle_count(), o.width, o.height, o.repeats);
    // The rays: primary from the camera, diffuse from their hits (chapter 01's ray sets), with chapter 04's
    // median BVH as the exact reference every refined tree must agree with.
    const auto reference = ch04::make_bvh_accel(false);
    reference->build(s);
    const ch01::checked_rays rays = ch01::make_checked_rays(s, o.width, o.height, *reference);
    // What the builders see: one box and one centroid per triangle.
    const ch01::triangle_set tris(s.mesh);
    std::vector<aabb> boxes(tris.size());
    std::vector<vec3> centroids(tris.size());
    for (std::uint32_t i = 0; i < tris.size(); ++i) boxes[i] = tris.bounds(i), centroids[i] = boxes[i].centroid();

    // Traces both ray sets through a given tree (chapter 04's traversal), the medians of the timings.
    const auto trace = [&](row& r, const ch04::bvh& tree) {
        const auto a = ch04::make_bvh_accel(false, "given", [&tree](auto, auto) { return tree; });
        a->build(s);
        const ch01::checked_speed speed = ch01::time_checked(*a, rays, o.repeats);
        r.differing = speed.differing;
        r.primary_mrays = speed.primary_mrays;
        r.diffuse_mrays = speed.diffuse_mrays;
    };
    const auto print = [](const row& r) {
        std::printf("  %-9s %-11s %6d %6d %8zu %9.2f %8.2f %8.2f %5d", r.start.c_str(), r.method.c_str(), r.budget,
                    r.iterations, r.moves, r.ms, r.sah_before, r.sah_after, r.depth);
        if (r.primary_mrays > 0)
            std::printf(" %9.2f %9.2f %6zu", r.primary_mrays, r.diffuse_mrays, r.differing);
        std::printf("\n");
        std::fflush(stdout);
    };
    std::printf("  %-9s %-11s %6s %6s %8s %9s %8s %8s %5s %9s %9s %6s\n", "start", "method", "budget", "iters",
                "moves", "refine ms", "SAH", "SAH", "depth", "primary", "diffuse", "differ");
    std::printf("  %-9s %-11s %6s %6s %8s %9s %8s %8s %5s %9s %9s %6s\n", "", "", "", "", "", "", "before", "after",
                "", "Mrays/s", "Mrays/s", "");

    std::vector<row> rows;
    for (const start_tree st : {start_tree::median, start_tree::binned16}) {
        const ch04::bvh start = st == start_tree::median ? ch04::build_bvh(boxes, centroids)
                                                         : ch05::build_sah_bvh(boxes, centroids);
        row base{s.name, to_string(st), "none"};
        base.sah_before = base.sah_after = ch05::tree_cost(start);
        base.nodes = start.nodes.size();
        base.depth = start.stats.depth;
        trace(base, start);
        print(base);
        rows.push_back(base);
        for (const refine_method m : {refine_method::rotations, refine_method::reinsertion}) {
            const std::vector<int>& budgets = m == refine_method::rotations ? o.rotation_budgets : o.reinsertion_budgets;
            for (std::size_t b = 0; b < budgets.size(); ++b) {
                refine_params p;
                p.method = m;
                p.max_iterations = budgets[b];
                row r{s.name, to_string(st), to_string(m), budgets[b]};
                ch04::bvh refined;
                refine_stats stats;
                r.ms = median_ms(o.repeats, [&] { refined = start, stats = refine(refined, p); });
                r.iterations = stats.iterations;
                r.moves = stats.moves;
                r.sah_before = stats.before;
                r.sah_after = stats.after;
                r.nodes = refined.nodes.size();
                r.depth = refined.stats.depth;
                if (b + 1 == budgets.size()) trace(r, refined);  // the largest budget: traced
                print(r);
                rows.push_back(r);
            }
        }
    }
    return rows;
}

const char* const csv_header = "scene,start,method,budget,iterations,moves,refine_ms,sah_before,sah_after,nodes,depth,"
                               "primary_mrays_s,diffuse_mrays_s,differing";

void write_table(const std::vector<row>& rows, const fs::path& csv) {
    std::ostringstream text;
    text << csv_header << '\n';
    for (const row& r : rows)
        text << r.scene << ',' << r.start << ',' << r.method << ',' << r.budget << ',' << r.iterations << ','
             << r.moves << ',' << r.ms << ',' << r.sah_before << ',' << r.sah_after << ',' << r.nodes << ','
             << r.depth << ',' << r.primary_mrays << ',' << r.diffuse_mrays << ',' << r.differing << '\n';
    std::ofstream f(csv);
    f << with_machine(text.str(), this_machine(parallel_threads()));
    f.close();
    if (!f) throw std::runtime_error("cannot write " + csv.string());
}

// --replot: the rows of a refinement.csv this program wrote, in the file's order.
std::vector<row> read_table(const fs::path& csv) {
    std::vector<row> rows;
    for (const csv_row& c : read_csv(csv, csv_header, machine_header, "a refinement.csv written by ch06")) {
        const auto num = [&](std::size_t k) { return csv_number(csv, c, k); };
        // The scene names a plot file: letters, digits, '_' and '-' only (no '/', no "..").
        if (c.cells[0].empty() || c.cells[0].find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                               "0123456789_-") != std::string::npos)
            throw std::runtime_error(csv.string() + ", line " + std::to_string(c.line) + ": scene '" + c.cells[0] +
                                     "' is no plain name (letters, digits, '_', '-')");
        row r{c.cells[0], c.cells[1], c.cells[2], int(num(3)), int(num(4)), int(num(10))};
        r.moves = std::size_t(num(5)), r.nodes = std::size_t(num(9)), r.differing = std::size_t(num(13));
        r.ms = num(6), r.sah_before = num(7), r.sah_after = num(8), r.primary_mrays = num(11), r.diffuse_mrays = num(12);
        if (!(r.sah_before > 0)) throw std::runtime_error(csv.string() + ", line " + std::to_string(c.line) +
                                                          ": an SAH cost of 0 before refinement");
        rows.push_back(r);
    }
    return rows;
}

// The scenes of a table, in order of first appearance.
std::vector<std::string> scenes_of(const std::vector<row>& rows) {
    std::vector<std::string> names;
    for (const row& r : rows)
        if (std::find(names.begin(), names.end(), r.scene) == names.end()) names.push_back(r.scene);
    return names;
}

fs::path plot_path(const fs::path& folder, const std::string& scene) { return folder / ("sah_vs_time_" + scene + ".svg"); }

// One plot per scene: the SAH cost's reduction against refinement time (log scale), a series per start tree
// and method, a point per iteration budget.
void write_plots(const std::vector<row>& rows, const fs::path& folder) {
    for (const std::string& name : scenes_of(rows)) {
        plot p{"SAH cost reduction against refinement time (" + name + ", one thread; labels: budget)",
               "refinement time [ms]", "SAH cost reduction [% of the start tree's]", true, false, {}};
        for (const char* start : {"median", "binned16"})
            for (const char* method : {"rotated", "reinserted"}) {
                plot_series ser{std::string(start) + ", " + method, {}, {}, true, {}};
                for (const row& r : rows) {
                    if (r.scene != name || r.start != start || r.method != method) continue;
                    ser.x.push_back(r.ms);
                    ser.y.push_back(100.0 * (1.0 - r.sah_after / r.sah_before));
                    ser.point_labels.push_back(std::to_string(r.budget));
                }
                if (!ser.x.empty()) p.series.push_back(ser);
            }
        write_svg(plot_path(folder, name), to_svg(p));
    }
}

int run(int argc, const char* const* argv) {
    cli args("ch06", "Chapter 06, refining a BVH (" + std::string(track_name()) + "): tree rotations and reinsertion on chapter "
             "04's median tree and chapter 05's binned SAH tree; SAH cost against refinement time per "
             "iteration budget, and Mrays/s before and after, as a table, a CSV file and a plot per scene.");
    args.scene_option({"stadium", "bunny", "sponza", "teapot"}, {"stadium", "bunny", "sponza"})
        .option("rotations", "LIST", "1,2,4,8,64", "comma-separated budgets of rotation passes")
        .option("reinsertions", "LIST", "1,4,16,64,256", "comma-separated budgets of reinsertion batches")
        .option("width", "N", "", "primary rays per row, 1..4096 (default 192, 96 with --quick)")
        .option("height", "N", "", "rows, 1..4096 (default 3/4 of the width)")
        .option("repeats", "K", "3", "timed runs per measurement after a warm-up; the median is reported")
        .output_options("write the CSV file and the plots into DIR/ (default out/06_refinement/)")
        .option("replot", "CSV", "", "only redraw the plots from a refinement.csv written earlier (no refining, no tracing)")
        .flag("quick", "the teapot in a stadium only, 96 x 72 rays, budgets 1,64 and 1,16,64")
        .option("diagrams", "DIR", "", "only draw the chapter's figure into DIR/ (rotation.svg; --force to replace it)");
    if (!args.parse(argc, argv)) return 0;
    if (draw_diagrams_if_asked(args, write_diagrams)) return 0;
    const bool quick = args.has("quick");
    options o;
    if (args.has("out")) o.folder = args.get("out"), o.user_named = true;
    o.force = args.has("force");
    if (args.has("replot")) {
        const std::vector<row> rows = read_table(args.get("replot"));
        // Every file is checked before any is written.
        for (const std::string& name : scenes_of(rows)) prepare_output(plot_path(o.folder, name), o.user_named, o.force);
        write_plots(rows, o.folder);
        for (const std::string& name : scenes_of(rows)) std::printf("wrote %s\n", plot_path(o.folder, name).string().c_str());
        return 0;
    }
    const thread_limit one(1);  // the chapter's figures are single-threaded, as in the race's table
    // Per pixel: primary and diffuse rays with their hits for each tree measured, and the PNG rows: 200 bytes
    // is ample.
    const image_size size = read_image_size(args, quick ? 96 : 192, 4096, 200);
    o.width = size.width, o.height = size.height;
    o.repeats = args.get_int("repeats");
    if (o.repeats < 1 || o.repeats > 100) throw usage_error("--repeats must lie in [1, 100]");
    o.rotation_budgets = parse_int_list(quick && !args.has("rotations") ? "1,64" : args.get("rotations"), "rotations", 1, 10000);
    o.reinsertion_budgets =
        parse_int_list(quick && !args.has("reinsertions") ? "1,16,64" : args.get("reinsertions"), "reinsertions", 1, 10000);

    std::vector<std::string> names = args.scene_names();
    if (quick) names = {"stadium"};
    // Every file this run may write is checked before the work starts, not after it.
    const fs::path csv = o.folder / "refinement.csv";
    prepare_output(csv, o.user_named, o.force);
    for (const std::string& name : names)
        prepare_output(plot_path(o.folder, name), o.user_named, o.force);
    std::vector<row> rows;
    const auto add = [&](const std::string& name, scene s) {
        s.name = name;  // the rows' scene, and the plot's file name
        const std::vector<row> r = run_scene(s, o);
        rows.insert(rows.end(), r.begin(), r.end());
    };
    for (const std::string& name : names)
        if (const auto s = course_scene(name)) add(name, *s);
    write_table(rows, csv);
    write_plots(rows, o.folder);
    std::printf("wrote %s", csv.string().c_str());
    for (const std::string& name : scenes_of(rows)) std::printf(", %s", plot_path(o.folder, name).string().c_str());
    std::printf("\n");
    std::printf("an LBVH start tree comes with chapter 07; against Embree on the same rays: build/release/bin/race "
                "--accels ch05-binned16,ch06-binned16-rotated,ch06-binned16-reinserted,embree-medium\n");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch06_exercise" : "ch06", run, argc, argv);
}
