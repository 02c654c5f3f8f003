// ch15: robustness. Five triangle tests (Moeller-Trumbore plain, with the paper's epsilon, from edges; the
// watertight test in float with its double fallback, and in double) in one tree walked with three box tests
// (plain, conservative, chapter 05's fast walk). Closed spheres from 1e-6 to 1e7 at up to 1e7 from the
// origin, with rays from inside aimed exactly at every vertex and edge: which combinations let rays escape
// through cracks (escapes.csv). Secondary rays spawned from hit points with no offset, a fixed epsilon,
// pbrt-v4's error bound and Waechter and Binder's integer offset: self-hits and leaks (spawn.csv). The teapot
// seen from 1e3 to 1e7: each test's tree against its brute force, bit for bit, with the rays' origins kept
// and moved to the scene (far.csv; --far-only writes just that). The teapot scaled by powers of two from 1e-30
// to 1e16: the hits of each test by brute force and of Embree, where products underflow or overflow
// (scale.csv, scale.svg; --scale-only writes just those, --replot redraws the plot from a scale.csv). Then the
// chapter's table: escapes and self-hits per million rays against Mrays/s on the bunny and Sponza
// (table.csv, escape_vs_speed.svg). Embree with and without its robust flag on the same aimed rays.
#include "strahl/diagram.hpp"
#include "strahl/camera.hpp"
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch15/accel.hpp"
#include "strahl/ch15/embree_robust.hpp"
#include "strahl/ch15/experiments.hpp"
#include "strahl/ch15/far.hpp"
#include "strahl/ch15/race_ratios.hpp"
#include "strahl/ch15/totals.hpp"
#include "strahl/ch15/scale.hpp"
#include "strahl/machine.hpp"
#include "strahl/parallel.hpp"
#include "strahl/plot.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

namespace strahl::ch15 {
// The chapter's figures (src/diagrams.cpp): the crack, the shear to ray space, the spawn offsets.
std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force);
}  // namespace strahl::ch15

namespace {

using namespace strahl;
using namespace strahl::ch15;
namespace fs = std::filesystem;

struct sphere_size {
    int stacks, slices;
    bool brute;  // also brute force with every test (linear in the triangles: the small spheres only)
};

std::vector<sphere_size> spheres(bool quick) {
    if (quick) return {{12, 24, true}, {24, 48, false}};
    return {{12, 24, true}, {24, 48, true}, {64, 128, false}, {256, 512, false}};
}

std::vector<placement> usable_placements(bool say) {
    std::vector<placement> out;
    for (const placement& p : all_placements()) {
        if (p.representable()) out.push_back(p);
        else if (say)
            std::printf("  radius %g at %g from the origin: skipped, float cannot hold it (radius < distance x 2^-12)\n",
                        double(p.scale), double(p.place));
    }
    return out;
}

// Per (test, box): the counts the table is made of, summed over spheres, placements and scenes.
struct tally {
    std::size_t escape_rays = 0, escapes = 0, spawn_rays = 0, self_hits = 0, differing = 0;
    std::vector<double> primary, diffuse;  // Mrays/s per scene
};
using key = std::pair<std::string, std::string>;  // (test, box)

double per_million(std::size_t n, std::size_t of) { return of ? 1e6 * double(n) / double(of) : 0.0; }

// 1. Rays from inside closed spheres, aimed at their vertices and edges: escapes.csv's rows.
std::string run_escapes(bool quick, std::map<key, tally>& t) {
    std::printf("1. escapes: rays from inside closed spheres, aimed at every vertex, at every edge's midpoint "
                "(from each of its two triangles) and at as many random points\n");
    const std::vector<placement> places = usable_placements(true);
    const bool embree = embree_available();
    if (!embree) std::printf("  Embree: not available in this build (no embree rows)\n");
    std::uint64_t total = 0;
    for (const sphere_size& s : spheres(quick))
        total += aimed_ray_count(s.stacks, s.slices) * places.size() * (15 + (s.brute ? 5 : 0) + (embree ? 2 : 0));
    std::ostringstream csv;
    csv << escapes_csv_header << '\n';
    progress_bar bar("escapes", total, "rays");
    for (const sphere_size& sz : spheres(quick))
        for (const placement& p : places) {
            scene s;
            s.name = "sphere";
            s.mesh = placed_sphere(sz.stacks, sz.slices, p);
            const aimed_rays rays = make_aimed_rays(s.mesh, p, 1);
            const auto record = [&](const std::string& test, const std::string& box, const std::vector<std::uint8_t>& f) {
                const std::array<std::size_t, 3> e = escapes(rays, f);
                for (const aim_kind k : all_aims)
                    csv << sz.stacks << ',' << sz.slices << ',' << s.mesh.triangle_count() << ',' << p.scale << ','
                        << p.place << ',' << test << ',' << box << ',' << name(k) << ',' << rays.count(k) << ','
                        << e[int(k)] << '\n';
                tally& x = t[{test, box}];
                x.escape_rays += rays.rays.size(), x.escapes += e[0] + e[1] + e[2];
            };
            for (const test_kind k : all_tests) {
                for (const box_kind b : all_boxes) {
                    const auto a = make_tree(k, b);
                    a->build(s);
                    record(name(k), name(b), found(*a, rays.rays, &bar));
                }
                if (!sz.brute) continue;
                const auto a = make_brute(k);
                a->build(s);
                record(name(k), "brute", found(*a, rays.rays, &bar));
            }
            if (embree)
                for (const bool robust : {false, true}) {
                    record(robust ? "embree-robust" : "embree", "embree", embree_found(s.mesh, rays.rays, robust));
                    bar.add(rays.rays.size());
                }
        }
    bar.finish();
    for (const sphere_size& sz : spheres(quick))
        std::printf("  sphere %d x %d (%zu triangles): %zu rays per structure and placement, %zu placements%s\n",
                    sz.slices, sz.stacks, std::size_t(2) * sz.slices * (sz.stacks - 1),
                    aimed_ray_count(sz.stacks, sz.slices), places.size(), sz.brute ? ", with brute force" : "");
    std::printf("  escapes per million rays, all spheres and placements:\n  %-18s %-13s %12s %10s %14s\n", "test",
                "box", "rays", "escapes", "per million");
    std::vector<key> order;
    for (const test_kind k : all_tests)
        for (const char* b : {name(box_kind::plain), name(box_kind::conservative), name(box_kind::fast), "brute"})
            order.push_back({name(k), b});
    order.push_back({"embree", "embree"}), order.push_back({"embree-robust", "embree"});
    for (const key& k : order)
        if (const auto x = t.find(k); x != t.end())
            std::printf("  %-18s %-13s %12zu %10zu %14.3f\n", k.first.c_str(), k.second.c_str(), x->second.escape_rays,
                        x->second.escapes, per_million(x->second.escapes, x->second.escape_rays));
    return csv.str();
}

// 2. The spawn offsets on the watertight tree: spawn.csv's rows.
std::string run_spawn(std::size_t points) {
    std::printf("\n2. spawn: %zu hit points per placement on a 128 x 64 sphere (watertight test, fast walk), one "
                "outward and one inward ray from each, tmin = 0\n", points);
    const std::vector<placement> places = usable_placements(false);
    std::ostringstream csv;
    csv << spawn_csv_header << '\n';
    std::map<offset_kind, spawn_counts> sums;
    progress_bar bar("spawn", points * places.size() * std::size(all_offsets), "hit points");
    for (const placement& p : places) {
        scene s;
        s.name = "sphere";
        s.mesh = placed_sphere(64, 128, p);
        const auto a = make_tree(test_kind::watertight, box_kind::fast);
        a->build(s);
        for (const offset_kind k : all_offsets) {
            const spawn_counts c = spawn_test(*a, s.mesh, p, k, points, true, 2, &bar);
            csv << p.scale << ',' << p.place << ',' << name(k) << ',' << c.rays() << ',' << c.outward_self_hits << ','
                << c.inward_self_hits << ',' << c.self_hits() << ',' << c.leaks << ','
                << per_million(c.self_hits(), c.rays()) << ',' << per_million(c.leaks, c.rays()) << '\n';
            sums[k] += c;
        }
    }
    bar.finish();
    std::printf("  %-8s %12s %12s %10s %16s %14s   %s\n", "offset", "rays", "self-hits", "leaks", "self-hits/M rays",
                "leaks/M rays", "(all placements)");
    for (const auto& [k, c] : sums)
        std::printf("  %-8s %12zu %12zu %10zu %16.1f %14.1f   %s\n", name(k), c.rays(), c.self_hits(), c.leaks,
                    per_million(c.self_hits(), c.rays()), per_million(c.leaks, c.rays()), describe(k));
    std::printf("  per placement: spawn.csv\n");
    return csv.str();
}

// 3a. Self-hits without an offset, per test and box: outward rays from each structure's own hit points.
void run_self_hits(std::size_t points, std::map<key, tally>& t) {
    std::printf("\n3. self-hits with no offset (tmin = 0): %zu outward rays per placement and structure\n", points);
    const std::vector<placement> places = usable_placements(false);
    progress_bar bar("self-hits", points * places.size() * 15, "hit points");
    for (const placement& p : places) {
        scene s;
        s.name = "sphere";
        s.mesh = placed_sphere(64, 128, p);
        for (const test_kind k : all_tests)
            for (const box_kind b : all_boxes) {
                const auto a = make_tree(k, b);
                a->build(s);
                const spawn_counts c = spawn_test(*a, s.mesh, p, offset_kind::none, points, false, 3, &bar);
                tally& x = t[{name(k), name(b)}];
                x.spawn_rays += c.rays(), x.self_hits += c.self_hits();
            }
    }
    bar.finish();
}

// 3b. Closest-hit speed on one thread, primary and diffuse rays; each structure's hits compared with the
// fast walk's with the same test (which equals brute force with that test).
void run_speed(const scene& s, int width, int height, int repeats, std::map<key, tally>& t) {
    std::printf("  %s: %zu triangles; %d x %d primary rays and as many diffuse; one thread, median of %d\n",
                s.name.c_str(), s.mesh.triangle_count(), width, height, repeats);
    const auto first = make_tree(test_kind::mt, box_kind::fast);
    first->build(s);
    const ch01::checked_rays rays = ch01::make_checked_rays(s, width, height, *first);
    progress_bar bar("speed " + s.name, 15, "structures");
    for (const test_kind k : all_tests) {
        const auto fast = make_tree(k, box_kind::fast);
        fast->build(s);
        ch01::checked_rays same = rays;  // the same rays, with this test's answers as the reference
        fast->intersect(same.primary, same.primary_hits);
        fast->intersect(same.diffuse, same.diffuse_hits);
        for (const box_kind b : all_boxes) {
            std::unique_ptr<accel> other;
            if (b != box_kind::fast) other = make_tree(k, b), other->build(s);
            const ch01::checked_speed v = ch01::time_checked(other ? *other : *fast, same, repeats);
            tally& x = t[{name(k), name(b)}];
            x.primary.push_back(v.primary_mrays), x.diffuse.push_back(v.diffuse_mrays), x.differing += v.differing;
            bar.add();
        }
    }
    bar.finish();
}

double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / double(v.size());
}

std::string plain_name(const std::string& scene_name) {
    std::string n = fs::path(scene_name).stem().string();
    for (char& c : n)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return n;
}

std::string table(const std::map<key, tally>& t, const std::vector<std::string>& scenes) {
    std::ostringstream csv;
    csv << "test,box,escape_rays,escapes,escapes_per_million,spawn_rays,self_hits,self_hits_per_million";
    for (const std::string& s : scenes) csv << ',' << s << "_primary_mrays_s," << s << "_diffuse_mrays_s";
    csv << ",differ_from_fast\n";
    std::printf("\nThe table: escapes and self-hits per million rays, closest-hit Mrays/s (one thread); 'differ': "
                "hits unlike the fast walk's with the same test\n  %-18s %-13s %12s %12s", "test", "box",
                "escapes/M", "self-hits/M");
    for (const std::string& s : scenes) std::printf(" %12s %12s", (s + " prim").c_str(), (s + " diff").c_str());
    std::printf(" %8s\n", "differ");
    for (const test_kind k : all_tests)
        for (const box_kind b : all_boxes) {
            const tally& x = t.at({name(k), name(b)});
            const double e = per_million(x.escapes, x.escape_rays), h = per_million(x.self_hits, x.spawn_rays);
            csv << name(k) << ',' << name(b) << ',' << x.escape_rays << ',' << x.escapes << ',' << e << ','
                << x.spawn_rays << ',' << x.self_hits << ',' << h;
            std::printf("  %-18s %-13s %12.3f %12.1f", name(k), name(b), e, h);
            for (std::size_t i = 0; i < scenes.size(); ++i) {
                csv << ',' << x.primary[i] << ',' << x.diffuse[i];
                std::printf(" %12.2f %12.2f", x.primary[i], x.diffuse[i]);
            }
            csv << ',' << x.differing << '\n';
            std::printf(" %8zu\n", x.differing);
        }
    std::printf("  (escapes/M: per million of the %zu rays of escapes.csv per structure; self-hits/M: per million "
                "outward rays; Mrays/s in the scene columns)\n", t.at({"mt", "fast"}).escape_rays);
    return csv.str();
}

// Escapes per million against speed, one point per (test, box); zero escapes drawn on a dashed floor line.
void write_plot(const std::map<key, tally>& t, const fs::path& svg) {
    std::size_t rays = 0;
    double lo = inf, hi = 0;
    for (const test_kind k : all_tests)
        for (const box_kind b : all_boxes) {
            const tally& x = t.at({name(k), name(b)});
            rays = std::max(rays, x.escape_rays);
            lo = std::min(lo, mean(x.diffuse)), hi = std::max(hi, mean(x.diffuse));
        }
    const double floor = 0.5 * per_million(1, rays);  // half of one escape in all the rays
    plot p{"Escapes through closed spheres against speed (chapter 15)", "diffuse rays, Mrays/s (one thread, mean "
           "over the scenes)", "escapes per million rays", false, true, {}, false};
    int colour = 0;
    for (const test_kind k : all_tests) {
        plot_series s{name(k), {}, {}, false, {}, colour++};
        for (const box_kind b : all_boxes) {
            const tally& x = t.at({name(k), name(b)});
            s.x.push_back(mean(x.diffuse));
            s.y.push_back(x.escapes ? per_million(x.escapes, x.escape_rays) : floor);
            s.point_labels.push_back(std::string(name(b)) + (x.escapes ? "" : " (0)"));
        }
        p.series.push_back(s);
    }
    plot_series zero{"0 escapes in " + std::to_string(rays) + " rays", {lo, hi}, {floor, floor}, true, {}, 9};
    zero.dashed = true;
    p.series.push_back(zero);
    write_svg(svg, to_svg(p, 900, 520));
}

std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream in(s);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

// --scenes checked before anything is written: builtin names known, files there.
std::vector<std::string> scene_specs(const cli& args, bool quick) {
    if (args.has("scenes")) {
        const std::vector<std::string> specs = split(args.get("scenes"));
        if (specs.empty()) throw usage_error("--scenes names no scene");
        const std::vector<std::string> names = builtin_scene_names();
        for (const std::string& s : specs) {
            if (s.rfind("builtin:", 0) == 0) {
                if (std::find(names.begin(), names.end(), s.substr(8)) == names.end())
                    throw usage_error("--scenes: no built-in scene '" + s.substr(8) + "'");
            } else if (std::error_code ec; !fs::is_regular_file(s, ec)) {
                throw usage_error("--scenes: no file '" + s + "'");
            }
        }
        return specs;
    }
    if (quick) return {"builtin:teapot"};
    std::vector<std::string> specs;
    for (const char* mesh : {"bunny.ply", "sponza.obj"}) {
        const fs::path p = fs::path(STRAHL_SHARED_SCENES) / mesh;
        if (std::error_code ec; fs::exists(p, ec)) specs.push_back(p.string());
        else std::printf("%s: skipped, %s is not there (the course's shared meshes)\n", mesh, p.string().c_str());
    }
    if (specs.empty()) specs.push_back("builtin:teapot");
    return specs;
}

// The totals' files (totals.hpp), written into folder (its files prepared by the caller: prepare_output).
const char* const totals_files[] = {"spawn_totals.csv", "escapes_by_placement.csv", "escapes_by_sphere.csv",
                                    "escapes_by_aim.csv"};
void write_totals(const ch15::totals_csvs& t, const fs::path& folder) {
    const std::string* texts[] = {&t.spawn, &t.by_placement, &t.by_sphere, &t.by_aim};
    for (int i = 0; i < 4; ++i) write_text(folder / totals_files[i], *texts[i]);
    std::printf("wrote %s/{spawn_totals.csv, escapes_by_placement.csv, escapes_by_sphere.csv, escapes_by_aim.csv}\n",
                folder.string().c_str());
}

int run(int argc, const char* const* argv) {
    cli args("ch15", "Chapter 15, robustness (" + std::string(track_name()) + "): five triangle tests x three box tests on closed "
             "spheres from 1e-6 to 1e7, rays aimed at their vertices and edges (escapes), secondary rays spawned with "
             "four offsets (self-hits, leaks), and the accuracy/speed table on the bunny and Sponza.");
    args.option("scenes", "LIST", "", "comma-separated scenes for the speed columns: builtin:NAME or mesh files "
                                      "(default: ../shared/scenes/bunny.ply and sponza.obj; builtin:teapot with --quick)")
        .option("width", "N", "", "primary rays per row for the speed columns (default 192, 64 with --quick)")
        .option("height", "N", "", "rows (default 3/4 of the width)")
        .option("repeats", "K", "5", "timed runs per speed after a warm-up; the median is reported")
        .option("spawn-points", "N", "", "hit points per placement in the spawn test, 1000 to 10000000 (default "
                                         "200000, 1000 with --quick; a quarter of it per structure for the self-hits)")
        .threads_option("0", "threads counting escapes and self-hits, 0..1024 (0: one per core); speeds are "
                                     "always timed on one thread")
        .output_options("write escapes.csv, spawn.csv, far.csv, scale.csv, scale.svg, table.csv and escape_vs_speed.svg into DIR/ "
                                   "(default out/15_robustness/)")
        .option("from-race", "DIR", "", "only write race_ratios.csv: the same-process speed ratios of a race run "
                "with --processes N and chapter 15's rows (DIR/processes/*/race.csv), median and range")
        .option("totals", "DIR", "", "only write spawn_totals.csv, escapes_by_placement.csv, escapes_by_sphere.csv and "
                "escapes_by_aim.csv: the totals of DIR/spawn.csv and DIR/escapes.csv written earlier (no tracing)")
        .flag("quick", "the two smallest spheres, 1000 spawn points, the far-away teapot at 32 x 24 rays, the scaled teapot at 16 x 12, the teapot at 64 x 48 for the speed columns, one repeat")
        .flag("far-only", "only the teapot seen from far away: write far.csv and nothing else")
        .flag("scale-only", "only the teapot scaled from 1e-30 to 1e16: write scale.csv and scale.svg and nothing else")
        .option("replot", "CSV", "", "only redraw scale.svg from a scale.csv written earlier (no tracing)")
        .option("diagrams", "DIR", "", "only draw the chapter's figures into DIR/ (crack.svg, shear.svg, offsets.svg; "
                                       "--force to replace them)");
    if (!args.parse(argc, argv)) return 0;
    if (draw_diagrams_if_asked(args, write_diagrams)) return 0;
    const fs::path single_folder = args.has("out") ? fs::path(args.get("out")) : fs::path("out/15_robustness");
    if (args.has("from-race")) {
        const fs::path& folder = single_folder;
        prepare_output(folder / "race_ratios.csv", args.has("out"), args.has("force"));
        const std::string csv = race_ratios(args.get("from-race"));
        write_text(folder / "race_ratios.csv", csv);
        std::printf("wrote %s\n", (folder / "race_ratios.csv").string().c_str());
        return 0;
    }
    if (args.has("totals")) {
        const fs::path from = args.get("totals");
        const ch15::totals_csvs t = ch15::totals(from / "escapes.csv", from / "spawn.csv");  // read first: no folder on a bad file
        for (const char* f : totals_files) prepare_output(single_folder / f, args.has("out"), args.has("force"));
        write_totals(t, single_folder);
        return 0;
    }
    const bool quick = args.has("quick");
    if (args.has("replot")) {
        // The table read first: a file that is no scale.csv leaves no folder behind.
        const std::vector<scale_row> rows = read_scale_csv(args.get("replot"));
        prepare_output(single_folder / "scale.svg", args.has("out"), args.has("force"));
        write_scale_plot(rows, single_folder / "scale.svg");
        std::printf("wrote %s from %s\n", (single_folder / "scale.svg").string().c_str(), args.get("replot").c_str());
        return 0;
    }
    if (args.has("scale-only")) {
        const fs::path& folder = single_folder;
        for (const char* f : {"scale.csv", "scale.svg"}) prepare_output(folder / f, args.has("out"), args.has("force"));
        const thread_limit counting(read_threads(args, 0));
        const std::vector<scale_row> rows = run_scale(quick);
        write_text(folder / "scale.csv", with_machine(scale_csv(rows), this_machine(parallel_threads())));
        write_scale_plot(read_scale_csv(folder / "scale.csv"), folder / "scale.svg");  // as --replot draws it
        std::printf("wrote %s, %s\n", (folder / "scale.csv").string().c_str(), (folder / "scale.svg").string().c_str());
        return 0;
    }
    if (args.has("far-only")) {
        const fs::path& folder = single_folder;
        prepare_output(folder / "far.csv", args.has("out"), args.has("force"));
        const thread_limit counting(read_threads(args, 0));
        write_text(folder / "far.csv", run_far(quick));
        std::printf("wrote %s\n", (folder / "far.csv").string().c_str());
        return 0;
    }
    const image_size size = read_image_size(args, quick ? 64 : 192, 4096);
    const int repeats = quick ? 1 : args.get_int("repeats");
    if (repeats < 1 || repeats > 100) throw usage_error("--repeats must lie in [1, 100]");
    const int points = args.has("spawn-points") ? args.get_int("spawn-points") : quick ? 1000 : 200000;
    if (points < 1000 || points > 10000000) throw usage_error("--spawn-points must lie in [1000, 10000000]");
    const int threads = read_threads(args, 0);
    const std::vector<std::string> specs = scene_specs(args, quick);
    fs::path folder = "out/15_robustness";
    const bool user_named = args.has("out");
    if (user_named) folder = args.get("out");
    for (const char* f : {"escapes.csv", "spawn.csv", "far.csv", "scale.csv", "scale.svg", "table.csv", "escape_vs_speed.svg"})
        prepare_output(folder / f, user_named, args.has("force"));
    for (const char* f : totals_files) prepare_output(folder / f, user_named, args.has("force"));

    const timer clock;
    std::map<key, tally> t;
    std::string escapes_csv, spawn_csv, far_csv;
    std::vector<scale_row> scale_rows;
    machine_columns counted;  // Embree's escapes and hits depend on its kernels: the machine, the counting threads
    {
        const thread_limit counting(threads);
        counted = this_machine(parallel_threads());
        escapes_csv = run_escapes(quick, t);
        spawn_csv = run_spawn(std::size_t(points));
        far_csv = run_far(quick);
        scale_rows = run_scale(quick);
        run_self_hits(std::size_t(points) / 4, t);
    }
    std::printf("\n4. speed: closest hit, one thread\n");
    const thread_limit one(1);
    std::vector<std::string> scenes;
    for (const std::string& spec : specs) {
        const scene s = load_scene_spec(spec);
        scenes.push_back(plain_name(s.name));
        run_speed(s, size.width, size.height, repeats, t);
    }
    const std::string table_csv = with_machine(table(t, scenes), this_machine(1));  // speeds on one thread
    write_text(folder / "escapes.csv", with_machine(escapes_csv, counted));
    write_text(folder / "spawn.csv", spawn_csv);  // the course's tests alone: the same counts on any machine
    write_text(folder / "far.csv", far_csv);
    write_text(folder / "scale.csv", with_machine(scale_csv(scale_rows), counted));
    write_scale_plot(read_scale_csv(folder / "scale.csv"), folder / "scale.svg");  // as --replot draws it
    write_text(folder / "table.csv", table_csv);
    write_plot(t, folder / "escape_vs_speed.svg");
    write_totals(ch15::totals(folder / "escapes.csv", folder / "spawn.csv"), folder);
    std::printf("wrote %s/{escapes.csv, spawn.csv, far.csv, scale.csv, scale.svg, table.csv, escape_vs_speed.svg} in %.1f s\n", folder.string().c_str(),
                clock.seconds());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch15_exercise" : "ch15", run, argc, argv);
}
