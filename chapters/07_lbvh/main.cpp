// ch07: linear BVHs. Builds the LBVH (30- and 63-bit Morton codes, the lecture's hierarchy and Karras's)
// over the teapot in a stadium, a random triangle soup, the bunny and Sponza (when the shared meshes are
// there), and measures: the build's phases at 1 and N threads; the trees' SAH cost and trace speed against
// chapter 05's binned SAH tree on the same rays (every tree's hits checked against it); and the radix sort
// against std::sort and tbb::parallel_sort on the same keys.
#include "strahl/diagram.hpp"
#include "strahl/ch01/primitive_sets.hpp"
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch05/accel.hpp"
#include "strahl/ch07/accel.hpp"
#include "strahl/ch07/builder_scenes.hpp"
#include "strahl/ch07/morton.hpp"
#include "strahl/ch07/radix_sort.hpp"
#include "strahl/machine.hpp"
#include "strahl/parallel.hpp"
#include "strahl/plot.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/scene.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <map>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <tbb/parallel_sort.h>
#include <thread>

namespace strahl::ch07 {
// The chapter's figure (src/diagrams.cpp): the Z-order curve and the radix tree, by the chapter's own code.
std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force);
}  // namespace strahl::ch07

namespace {

using namespace strahl;
using namespace strahl::ch07;
namespace fs = std::filesystem;

struct options {
    int width = 192, height = 144, repeats = 3, threads = 2;
    fs::path folder{"out/07_lbvh"};
};

using inputs = builder_inputs;

// The thread counts the builds and sorts are timed at: 1 and o.threads.
std::vector<int> thread_counts(const options& o) { return o.threads == 1 ? std::vector<int>{1} : std::vector<int>{1, o.threads}; }

// Build phases: per builder and thread count, the median of each phase over o.repeats builds.
void time_phases(const std::string& name, const inputs& in, const options& o, std::ostringstream& csv,
                 std::vector<double>& build_ms_one_thread) {
    std::printf("  %-9s %7s %8s %8s %9s %8s %8s %8s   (ms, median of %d)\n", "builder", "threads", "codes", "sort",
                "hierarchy", "boxes", "collapse", "total", o.repeats);
    for (const lbvh_params& p : lbvh_variants())
        for (const int threads : thread_counts(o)) {
            const thread_limit limit(threads);
            std::vector<double> ph[6];
            build_lbvh(in.boxes, in.centroids, p);  // warm-up
            for (int r = 0; r < o.repeats; ++r) {
                lbvh_report rep;
                const ch04::bvh t = build_lbvh(in.boxes, in.centroids, p, &rep);
                const double v[6] = {rep.codes_ms, rep.sort_ms, rep.hierarchy_ms, rep.boxes_ms, rep.collapse_ms, t.stats.build_ms};
                for (int k = 0; k < 6; ++k) ph[k].push_back(v[k]);
            }
            double m[6];
            for (int k = 0; k < 6; ++k) m[k] = median(ph[k]);
            if (threads == 1) build_ms_one_thread.push_back(m[5]);
            std::printf("  %-9s %7d %8.2f %8.2f %9.2f %8.2f %8.2f %8.2f\n", to_string(p).c_str(), threads, m[0], m[1],
                        m[2], m[3], m[4], m[5]);
            csv << name << ',' << in.boxes.size() << ',' << to_string(p) << ',' << threads;
            for (const double x : m) csv << ',' << x;
            csv << '\n';
        }
}

// Scaling: each builder's median build time at 1 and o.threads threads, and the speed-up: chapter 05's
// binned SAH build (top down: the root alone on one thread, then subtrees as tasks) against the LBVH
// (every phase a parallel pass).
void time_scaling(const std::string& name, const inputs& in, const options& o, std::ostringstream& csv) {
    std::printf("  %-14s %7s %9s %8s   (ms, median of %d)\n", "builder", "threads", "build", "speed-up", o.repeats);
    ch05::sah_build_params binned;
    binned.bins = 16;
    lbvh_params lecture, karras;
    karras.hierarchy = hierarchy_method::karras;
    const std::pair<std::string, std::function<void()>> builders[] = {
        {"ch05-binned16", [&] { ch05::build_sah_bvh_fast(in.boxes, in.centroids, binned); }},
        {to_string(lecture), [&] { build_lbvh(in.boxes, in.centroids, lecture); }},
        {to_string(karras), [&] { build_lbvh(in.boxes, in.centroids, karras); }},
    };
    for (const auto& [builder, build] : builders) {
        double one = 0;
        for (const int threads : thread_counts(o)) {
            const thread_limit limit(threads);
            const double ms = median_ms(o.repeats, build);
            if (threads == 1) one = ms;
            std::printf("  %-14s %7d %9.2f %8.2f\n", builder.c_str(), threads, ms, one / ms);
            csv << name << ',' << in.boxes.size() << ',' << builder << ',' << threads << ',' << ms << ',' << one / ms << '\n';
        }
    }
}

// Quality: SAH cost and trace speed (one thread) of every LBVH and of chapter 05's binned SAH tree.
void compare_quality(const std::string& name, const scene& s, const inputs& in, const options& o,
                     const std::vector<double>& build_ms, std::ostringstream& csv) {
    ch05::sah_build_params binned;
    binned.bins = 16;
    const auto reference = ch05::make_accel(false, binned, ch05::walk_kind::fast);
    reference->build(s);
    const ch01::checked_rays rays = ch01::make_checked_rays(s, o.width, o.height, *reference);
    std::printf("  %-14s %5s %10s %9s %8s %6s %9s %9s %9s %6s\n", "tree", "bits", "dup codes", "build ms", "SAH",
                "depth", "nodes", "primary", "diffuse", "differ");
    const auto row = [&](const ch04::bvh_accel_base& a, const std::string& tree, int bits, std::size_t dups, double ms) {
        const ch04::bvh& t = a.tree();
        const double sah = ch05::tree_cost(t);
        const ch01::checked_speed speed = ch01::time_checked(a, rays, o.repeats);
        std::printf("  %-14s %5d %10zu %9.2f %8.2f %6d %9zu %9.2f %9.2f %6zu\n", tree.c_str(), bits, dups, ms, sah,
                    t.stats.depth, t.nodes.size(), speed.primary_mrays, speed.diffuse_mrays, speed.differing);
        std::fflush(stdout);
        csv << name << ',' << in.boxes.size() << ',' << tree << ',' << bits << ',' << dups << ',' << ms << ',' << sah << ','
            << t.stats.depth << ',' << t.nodes.size() << ',' << speed.primary_mrays << ',' << speed.diffuse_mrays << ','
            << speed.differing << '\n';
    };
    const thread_limit one(1);
    const double ch05_ms = median_ms(o.repeats, [&] { ch05::build_sah_bvh_fast(in.boxes, in.centroids, binned); });
    row(*reference, "ch05-binned16", 0, 0, ch05_ms);
    const std::vector<lbvh_params> list = lbvh_variants();
    for (std::size_t k = 0; k < list.size(); ++k) {
        lbvh_report rep;
        build_lbvh(in.boxes, in.centroids, list[k], &rep);
        const auto a = make_accel(list[k]);
        a->build(s);
        row(*a, to_string(list[k]), 3 * list[k].bits_per_axis, rep.duplicate_codes, build_ms[k]);
    }
}

// The sorts on the scene's own (key, id) pairs: the median time of o.repeats sorts of fresh copies.
void compare_sorts(const std::string& name, const inputs& in, const options& o, std::ostringstream& csv) {
    std::printf("  %-22s %7s %9s %9s   (ms, median of %d)\n", "sort", "threads", "30 bits", "63 bits", o.repeats);
    struct pair_key {
        std::uint64_t key;
        std::uint32_t id;
        bool operator<(const pair_key& b) const { return key < b.key || (key == b.key && id < b.id); }
    };
    const morton_codes codes[2] = {compute_morton_codes(in.boxes, in.centroids, 10),
                                   compute_morton_codes(in.boxes, in.centroids, 21)};
    const auto run = [&](const std::string& method, int threads, auto&& sort_keys, auto&& sort_pairs) {
        const thread_limit limit(threads);
        double ms[2];
        for (int b = 0; b < 2; ++b) {
            const morton_codes& c = codes[b];
            std::vector<std::uint64_t> want = c.keys;
            std::sort(want.begin(), want.end());
            std::vector<double> times;
            for (int r = 0; r <= o.repeats; ++r) {  // the first run untimed (warm-up)
                std::vector<std::uint64_t> keys = c.keys;
                std::vector<std::uint32_t> ids = c.ids;
                std::vector<pair_key> pairs(keys.size());
                for (std::size_t i = 0; i < keys.size(); ++i) pairs[i] = {keys[i], ids[i]};
                const timer t;
                if (sort_pairs) {
                    sort_pairs(pairs);
                    for (std::size_t i = 0; i < keys.size(); ++i) keys[i] = pairs[i].key;
                } else {
                    sort_keys(keys, ids, b == 0 ? 30 : 63);
                }
                if (r > 0) times.push_back(t.milliseconds());
                if (keys != want) throw std::logic_error(method + " did not sort the keys");
            }
            ms[b] = median(times);
        }
        std::printf("  %-22s %7d %9.2f %9.2f\n", method.c_str(), threads, ms[0], ms[1]);
        csv << name << ',' << in.boxes.size() << ',' << method << ',' << threads << ',' << ms[0] << ',' << ms[1] << '\n';
    };
    using pairs_fn = std::function<void(std::vector<pair_key>&)>;
    const auto radix = [](int digit, bool parallel) {
        return [digit, parallel](std::vector<std::uint64_t>& k, std::vector<std::uint32_t>& i, int bits) {
            radix_sort_params p;
            p.key_bits = bits, p.digit_bits = digit;
            parallel ? radix_sort_parallel(k, i, p) : radix_sort_serial(k, i, p);
        };
    };
    run("radix serial 8-bit", 1, radix(8, false), pairs_fn());
    run("radix serial 11-bit", 1, radix(11, false), pairs_fn());
    for (const int threads : thread_counts(o)) run("radix parallel 8-bit", threads, radix(8, true), pairs_fn());
    const auto none = [](std::vector<std::uint64_t>&, std::vector<std::uint32_t>&, int) {};
    run("std::sort", 1, none, pairs_fn([](std::vector<pair_key>& v) { std::sort(v.begin(), v.end()); }));
    for (const int threads : thread_counts(o))
        run("tbb::parallel_sort", threads, none, pairs_fn([](std::vector<pair_key>& v) { tbb::parallel_sort(v.begin(), v.end()); }));
}

// The CSV headers, shared by the writer and by --replot's reader.
const char* const phases_header = "scene,triangles,builder,threads,codes_ms,sort_ms,hierarchy_ms,boxes_ms,collapse_ms,total_ms";
const char* const quality_header = "scene,triangles,tree,bits,duplicate_codes,build_ms,sah_cost,depth,nodes,primary_mrays_s,"
                                   "diffuse_mrays_s,differing";
const char* const sort_header = "scene,keys,method,threads,ms_30bit,ms_63bit";
const char* const scaling_header = "scene,triangles,builder,threads,build_ms,speedup";

// The figures, drawn from the three CSV files (this run's, or --replot's):
//   phases.svg: each phase's share of the 30-bit LBVH's build, per scene and thread count;
//   build_vs_trace.svg: per scene, build time (log) against primary-ray speed for every tree, one point each;
//   sort.svg: nanoseconds per 30-bit key for each sort, per scene.
void write_plots(const fs::path& phases_csv, const fs::path& quality_csv, const fs::path& sort_csv, const fs::path& out) {
    const char* const phase_names[5] = {"codes", "sort", "hierarchy", "boxes", "collapse"};
    bar_chart phases{"Where the 30-bit LBVH's build time goes", "share of the build [%]", {}, {}, {}, false};
    for (const char* n : phase_names) phases.series_labels.push_back(n);
    phases.values.resize(5);
    for (const csv_row& r : read_csv(phases_csv, phases_header, machine_header, "a build_phases.csv written by ch07")) {
        if (r.cells[2] != "lbvh30") continue;
        const double total = csv_number(phases_csv, r, 9);
        double sum = 0;
        for (int k = 0; k < 5; ++k) sum += csv_number(phases_csv, r, 4 + k);
        char label[96];
        std::snprintf(label, sizeof label, "%s, %s thr. (%.1f ms)", r.cells[0].c_str(), r.cells[3].c_str(), total);
        phases.categories.push_back(label);
        for (int k = 0; k < 5; ++k) phases.values[k].push_back(sum > 0 ? 100.0 * csv_number(phases_csv, r, 4 + k) / sum : 0.0);
    }
    write_svg(out / "phases.svg", to_svg(phases, 900, 440));

    std::vector<plot> panels;
    std::map<std::string, std::size_t> panel_of;
    std::vector<std::string> trees;
    for (const csv_row& r : read_csv(quality_csv, quality_header, machine_header, "a quality.csv written by ch07")) {
        if (!panel_of.count(r.cells[0])) {
            panel_of[r.cells[0]] = panels.size();
            panels.push_back(plot{r.cells[0] + " (" + r.cells[1] + " triangles)", "build time, one thread [ms]",
                                  "primary rays [Mrays/s]", true, false, {}, false});
        }
        plot& p = panels[panel_of[r.cells[0]]];
        const auto at = std::find(trees.begin(), trees.end(), r.cells[2]);
        const int colour = int(at - trees.begin());
        if (at == trees.end()) trees.push_back(r.cells[2]);
        plot_series point{r.cells[2], {csv_number(quality_csv, r, 5)}, {csv_number(quality_csv, r, 9)}, false, {}, colour};
        point.in_legend = panel_of[r.cells[0]] == 0;  // one legend, in the first panel (same colours in all)
        p.series.push_back(point);
    }
    write_svg(out / "build_vs_trace.svg", to_svg(panels, 2, 560, 380));

    bar_chart sorts{"Sorting the 30-bit Morton codes (with their ids)", "time per key [ns]", {}, {}, {}, false};
    std::map<std::string, std::size_t> series_of, category_of;
    for (const csv_row& r : read_csv(sort_csv, sort_header, machine_header, "a sort.csv written by ch07")) {
        const std::string method = r.cells[2] + (r.cells[3] == "1" ? "" : ", " + r.cells[3] + " threads");
        const std::string scene = r.cells[0] + " (" + r.cells[1] + ")";
        if (!series_of.count(method)) series_of[method] = sorts.series_labels.size(), sorts.series_labels.push_back(method);
        if (!category_of.count(scene)) category_of[scene] = sorts.categories.size(), sorts.categories.push_back(scene);
    }
    sorts.values.assign(sorts.series_labels.size(), std::vector<double>(sorts.categories.size(), 0.0));
    for (const csv_row& r : read_csv(sort_csv, sort_header, machine_header, "a sort.csv written by ch07")) {
        const std::string method = r.cells[2] + (r.cells[3] == "1" ? "" : ", " + r.cells[3] + " threads");
        const double keys = std::max(1.0, csv_number(sort_csv, r, 1));
        sorts.values[series_of[method]][category_of[r.cells[0] + " (" + r.cells[1] + ")"]] =
            1e6 * csv_number(sort_csv, r, 4) / keys;
    }
    write_svg(out / "sort.svg", to_svg(sorts, 900, 440));
}

// A table with the machine's columns (the timings ran on up to `threads` threads).
void write_file(const fs::path& path, const std::string& header, const std::ostringstream& rows, int threads) {
    write_text(path, with_machine(header + '\n' + rows.str(), this_machine(threads)));
}

int run(int argc, const char* const* argv) {
    cli args("ch07", "Chapter 07, linear BVHs (" + std::string(track_name()) + "): Morton codes, radix sort, the "
             "hierarchy read off the codes' bits (the lecture's form and Karras's), boxes bottom up, SAH collapse. "
             "Build phases at 1 and N threads, SAH cost and Mrays/s against chapter 05's binned SAH tree, and the "
             "radix sort against std::sort and tbb::parallel_sort, and both builders' speed-up on N threads, as tables "
             "and CSV files.");
    args.option("scene", "NAME", "all", "stadium, soup, bunny, sponza, teapot or all (all: stadium, soup, bunny, sponza)")
        .threads_option("2", "the second thread count builds and sorts are timed at, 0..1024 (0: one per core)")
        .option("width", "N", "", "primary rays per row, 1..4096 (default 192, 48 with --quick)")
        .option("height", "N", "", "rows, 1..4096 (default 3/4 of the width)")
        .option("repeats", "K", "", "timed runs per measurement after a warm-up; the median is reported (default 5, "
                "1 with --quick)")
        .output_options("write the CSV files and the plots into DIR/ (default out/07_lbvh/)")
        .option("replot", "DIR", "", "only redraw the plots (phases.svg, build_vs_trace.svg, sort.svg) from the three CSV "
                "files in DIR written earlier (no building, no tracing)")
        .flag("quick", "the teapot and a soup of 20,000 triangles, 48 x 36 rays, one repeat")
        .option("diagrams", "DIR", "", "only draw the chapter's figure into DIR/ (zorder.svg; --force to replace it)");
    if (!args.parse(argc, argv)) return 0;
    if (draw_diagrams_if_asked(args, ch07::write_diagrams)) return 0;
    const bool quick = args.has("quick");
    options o;
    bool user_named = false;
    if (args.has("out")) o.folder = args.get("out"), user_named = true;
    const image_size size = read_image_size(args, quick ? 48 : 192, 4096, 200);
    o.width = size.width, o.height = size.height;
    o.repeats = args.has("repeats") ? args.get_int("repeats") : quick ? 1 : 5;
    if (o.repeats < 1 || o.repeats > 100) throw usage_error("--repeats must lie in [1, 100]");
    o.threads = read_threads(args, 0);
    if (o.threads == 0) o.threads = int(std::max(1u, std::thread::hardware_concurrency()));
    const std::string which = ch07::builder_scene_choice(args.get("scene"), quick);
    const fs::path phases_csv = o.folder / "build_phases.csv", quality_csv = o.folder / "quality.csv",
                   sort_csv = o.folder / "sort.csv", scaling_csv = o.folder / "scaling.csv";
    const fs::path svgs[3] = {o.folder / "phases.svg", o.folder / "build_vs_trace.svg", o.folder / "sort.svg"};
    if (args.has("replot")) {
        // The tables read first: a folder without them leaves no output folder behind.
        const fs::path from = args.get("replot");
        for (const char* f : {"build_phases.csv", "quality.csv", "sort.csv"})
            if (!fs::is_regular_file(from / f)) throw usage_error("--replot: no " + (from / f).string());
        read_csv(from / "build_phases.csv", phases_header, machine_header, "a build_phases.csv written by ch07");
        read_csv(from / "quality.csv", quality_header, machine_header, "a quality.csv written by ch07");
        read_csv(from / "sort.csv", sort_header, machine_header, "a sort.csv written by ch07");
        for (const fs::path& p : svgs) prepare_output(p, user_named, args.has("force"));
        write_plots(from / "build_phases.csv", from / "quality.csv", from / "sort.csv", o.folder);
        std::printf("wrote %s, %s, %s from %s\n", svgs[0].string().c_str(), svgs[1].string().c_str(),
                    svgs[2].string().c_str(), from.string().c_str());
        return 0;
    }
    for (const fs::path& p : {phases_csv, quality_csv, sort_csv, scaling_csv}) prepare_output(p, user_named, args.has("force"));
    for (const fs::path& p : svgs) prepare_output(p, user_named, args.has("force"));

    const std::vector<scene> scenes = ch07::builder_scenes(which);
    std::ostringstream phases, quality, sorts, scaling;
    for (const scene& s : scenes) {
        const inputs in(s.mesh);
        std::printf("%s: %zu triangles; builds and sorts at 1 and %d threads, tracing on one thread (%d x %d primary "
                    "rays and as many diffuse)\n", s.name.c_str(), in.boxes.size(), o.threads, o.width, o.height);
        std::vector<double> build_ms;
        time_phases(s.name, in, o, phases, build_ms);
        time_scaling(s.name, in, o, scaling);
        compare_quality(s.name, s, in, o, build_ms, quality);
        compare_sorts(s.name, in, o, sorts);
    }
    write_file(phases_csv, phases_header, phases, o.threads);
    write_file(quality_csv, quality_header, quality, o.threads);
    write_file(sort_csv, sort_header, sorts, o.threads);
    write_file(scaling_csv, scaling_header, scaling, o.threads);
    write_plots(phases_csv, quality_csv, sort_csv, o.folder);
    std::printf("wrote %s, %s, %s, %s and the plots %s, %s, %s\n", phases_csv.string().c_str(),
                quality_csv.string().c_str(), sort_csv.string().c_str(), scaling_csv.filename().string().c_str(), svgs[0].filename().string().c_str(), svgs[1].filename().string().c_str(),
                svgs[2].filename().string().c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch07_exercise" : "ch07", run, argc, argv);
}
