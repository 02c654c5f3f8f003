// ch09: spatial splits. Builds the SBVH over Sponza, the teapot in a stadium, the bunny and the armadillo
// (where the shared meshes are) beside chapter 05's binned SAH tree, chapter 06's reinserted tree and
// chapter 03's k-d tree: SAH cost, references per triangle, memory, build time and the trace speed of
// chapter 05's fast walk on one thread (every structure's hits checked against the binned tree's); then
// the overlap threshold alpha swept from 1 (no spatial split) to 0, as alpha.csv and alpha.svg.
#include "strahl/diagram.hpp"
#include "strahl/machine.hpp"
#include "strahl/parallel.hpp"
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch03/accel.hpp"
#include "strahl/ch05/accel.hpp"
#include "strahl/ch06/accel.hpp"
#include "strahl/ch09/accel.hpp"
#include "strahl/plot.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/scene.hpp"
#include "strahl/timer.hpp"
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace strahl::ch09 {
// The chapter's figure (src/diagrams.cpp): an object split against a spatial split, by the chapter's own code.
std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force);
}  // namespace strahl::ch09

namespace {

using namespace strahl;
namespace fs = std::filesystem;

struct options {
    int width = 192, height = 144, repeats = 5;
    std::vector<double> alphas;
    ch09::sbvh_params sbvh;
    bool sweep_only = false;
};

const char* const compare_header = "scene,triangles,structure,sah_cost,refs_per_triangle,memory_mb,build_ms,"
                                   "primary_mrays_s,diffuse_mrays_s,differing";
const char* const alpha_header = "scene,triangles,alpha,sah_cost,refs_per_triangle,memory_mb,build_ms,spatial_splits,"
                                 "unsplit,primary_mrays_s,diffuse_mrays_s,differing";

// One structure on one scene: built once (timed), its figures, its speed on the checked rays.
struct measured {
    double sah = 0, refs = 1, memory_mb = 0, build_ms = 0;
    ch01::checked_speed speed;
};
measured measure(accel& a, const scene& s, const ch01::checked_rays& rays, const options& o) {
    measured m;
    const timer clock;
    a.build(s);
    m.build_ms = clock.milliseconds();
    m.sah = a.sah_cost().value_or(0.0);
    m.memory_mb = double(a.memory_bytes()) / (1024.0 * 1024.0);
    m.speed = ch01::time_checked(a, rays, o.repeats);
    return m;
}

const char* const variants_header = "scene,triangles,variant,alpha,sah_cost,refs_per_triangle,memory_mb,build_ms,"
                                    "spatial_splits,unsplit,primary_mrays_s,diffuse_mrays_s,differing";

// --variants: "default", or NAME=VALUE with NAME budget, bins (chopped bins), leaf (max_leaf) or unsplit (0, 1).
ch09::sbvh_params variant_params(const std::string& v, ch09::sbvh_params p) {
    if (v == "default") return p;
    const std::size_t eq = v.find('=');
    const std::string name = v.substr(0, eq == std::string::npos ? v.size() : eq);
    char* end = nullptr;
    const double x = eq == std::string::npos ? NAN : std::strtod(v.c_str() + eq + 1, &end);
    const bool number = eq != std::string::npos && end && *end == '\0' && eq + 1 < v.size();
    if (name == "budget" && number && x >= 1 && x <= 16) p.budget = float(x);
    else if (name == "bins" && number && x >= 2 && x <= 256 && x == std::floor(x)) p.spatial_bins = int(x);
    else if (name == "leaf" && number && x >= 1 && x <= 255 && x == std::floor(x)) p.max_leaf = int(x);
    else if (name == "unsplit" && number && (x == 0 || x == 1)) p.unsplit = x == 1;
    else throw usage_error("--variants: '" + v + "' is not default, budget=B (1..16), bins=K (2..256), leaf=N (1..255) "
                           "or unsplit=0|1");
    return p;
}

// Each variant of the SBVH at each alpha on one scene, timed as run_scene's sweep (one row each).
void run_variants(const scene& s, const options& o, const std::vector<std::string>& variants, std::ostream& csv) {
    ch05::sah_build_params binned;
    binned.bins = 16;
    const auto reference = ch05::make_accel(false, binned, ch05::walk_kind::fast);
    reference->build(s);
    const ch01::checked_rays rays = ch01::make_checked_rays(s, o.width, o.height, *reference);
    std::printf("%s: %zu triangles; SBVH variants, one thread, median of %d\n  %-14s %-8s %8s %9s %9s %9s %9s %6s\n",
                s.name.c_str(), s.mesh.triangle_count(), o.repeats, "variant", "alpha", "SAH", "refs/tri", "build ms",
                "primary", "diffuse", "differ");
    for (const std::string& v : variants)
        for (const double alpha : o.alphas) {
            ch09::sbvh_params p = variant_params(v, o.sbvh);
            p.alpha = float(alpha);
            const auto a = ch09::make_accel(p);
            measured m = measure(*a, s, rays, o);
            const ch09::sbvh_report& r = a->report();
            m.refs = double(r.references) / double(std::max<std::size_t>(1, r.triangles));
            std::printf("  %-14s %-8g %8.2f %9.3f %9.1f %9.3f %9.3f %6zu\n", v.c_str(), alpha, m.sah, m.refs, m.build_ms,
                        m.speed.primary_mrays, m.speed.diffuse_mrays, m.speed.differing);
            std::fflush(stdout);
            csv << s.name << ',' << s.mesh.triangle_count() << ',' << v << ',' << alpha << ',' << m.sah << ',' << m.refs
                << ',' << m.memory_mb << ',' << m.build_ms << ',' << r.spatial_splits << ',' << r.unsplit << ','
                << m.speed.primary_mrays << ',' << m.speed.diffuse_mrays << ',' << m.speed.differing << '\n';
        }
}

void run_scene(const scene& s, const options& o, std::ostream& compare, std::ostream& sweep) {
    const std::size_t n = s.mesh.triangle_count();
    ch05::sah_build_params binned;
    binned.bins = 16;
    const auto reference = ch05::make_accel(false, binned, ch05::walk_kind::fast);
    reference->build(s);
    const ch01::checked_rays rays = ch01::make_checked_rays(s, o.width, o.height, *reference);
    std::printf("%s: %zu triangles; %d x %d primary rays and as many diffuse, one thread, median of %d\n",
                s.name.c_str(), n, o.width, o.height, o.repeats);
    std::printf("  %-30s %8s %9s %9s %9s %9s %9s %6s\n", "structure", "SAH", "refs/tri", "MiB", "build ms", "primary",
                "diffuse", "differ");
    const auto row = [&](const std::string& name, const measured& m) {
        std::printf("  %-30s %8.2f %9.3f %9.2f %9.1f %9.3f %9.3f %6zu\n", name.c_str(), m.sah, m.refs, m.memory_mb,
                    m.build_ms, m.speed.primary_mrays, m.speed.diffuse_mrays, m.speed.differing);
        std::fflush(stdout);
        compare << s.name << ',' << n << ',' << name << ',' << m.sah << ',' << m.refs << ',' << m.memory_mb << ','
                << m.build_ms << ',' << m.speed.primary_mrays << ',' << m.speed.diffuse_mrays << ','
                << m.speed.differing << '\n';
    };
    // The SBVH against the trees before it.
    if (!o.sweep_only) {
        const auto a = ch09::make_accel(o.sbvh);
        measured m = measure(*a, s, rays, o);
        m.refs = double(a->report().references) / double(std::max<std::size_t>(1, a->report().triangles));
        row(a->name(), m);
        const auto binned_fast = ch05::make_accel(false, binned, ch05::walk_kind::fast);
        row(binned_fast->name(), measure(*binned_fast, s, rays, o));
        ch06::refine_params r;
        r.start = ch06::start_tree::binned16, r.method = ch06::refine_method::reinsertion;
        const auto reinserted = ch06::make_accel(false, r, ch05::walk_kind::fast);
        row(reinserted->name(), measure(*reinserted, s, rays, o));
        const auto kd = ch03::make_kd_accel(false);
        measured k = measure(*kd, s, rays, o);
        k.refs = kd->tree().stats.refs_per_prim();
        row(kd->name(), k);
    }
    // The overlap threshold, from no spatial split (alpha = 1) to every overlap (alpha = 0).
    std::printf("  alpha sweep:\n  %-10s %8s %9s %9s %9s %9s %9s %9s %6s\n", "alpha", "SAH", "refs/tri", "MiB",
                "build ms", "spatial", "primary", "diffuse", "differ");
    for (const double alpha : o.alphas) {
        ch09::sbvh_params p = o.sbvh;
        p.alpha = float(alpha);
        const auto a = ch09::make_accel(p);
        measured m = measure(*a, s, rays, o);
        const ch09::sbvh_report& r = a->report();
        m.refs = double(r.references) / double(std::max<std::size_t>(1, r.triangles));
        std::printf("  %-10g %8.2f %9.3f %9.2f %9.1f %9zu %9.3f %9.3f %6zu\n", alpha, m.sah, m.refs, m.memory_mb,
                    m.build_ms, r.spatial_splits, m.speed.primary_mrays, m.speed.diffuse_mrays, m.speed.differing);
        std::fflush(stdout);
        sweep << s.name << ',' << n << ',' << alpha << ',' << m.sah << ',' << m.refs << ',' << m.memory_mb << ','
              << m.build_ms << ',' << r.spatial_splits << ',' << r.unsplit << ',' << m.speed.primary_mrays << ','
              << m.speed.diffuse_mrays << ',' << m.speed.differing << '\n';
    }
}

// alpha.svg from alpha.csv's rows: SAH cost, memory and trace speed against alpha, one series per scene, each
// relative to its alpha = 1 tree (so that scenes share an axis). alpha = 0 has no place on a log axis: it is drawn
// at 1e-7, as the title says.
std::string alpha_svg(const std::vector<csv_row>& rows, const fs::path& file) {
    std::vector<std::string> order;
    std::map<std::string, std::vector<std::array<double, 5>>> by_scene;  // alpha, SAH, memory, primary, diffuse
    for (const csv_row& r : rows) {
        if (!by_scene.count(r.cells[0])) order.push_back(r.cells[0]);
        by_scene[r.cells[0]].push_back({csv_number(file, r, 2), csv_number(file, r, 3), csv_number(file, r, 5),
                                        csv_number(file, r, 9), csv_number(file, r, 10)});
    }
    plot sah, mem;
    sah.title = "SAH cost relative to alpha = 1 (alpha 0 at 1e-7)";
    mem.title = "memory relative to alpha = 1 (alpha 0 at 1e-7)";
    sah.x_label = mem.x_label = "overlap threshold alpha";
    sah.y_label = "SAH cost / SAH cost at alpha = 1";
    mem.y_label = "memory / memory at alpha = 1";
    plot speed;
    speed.title = "Mrays/s relative to alpha = 1: primary solid, diffuse dashed";
    speed.x_label = "overlap threshold alpha";
    speed.y_label = "Mrays/s / Mrays/s at alpha = 1 (one thread)";
    sah.log_x = mem.log_x = speed.log_x = true;
    sah.y_from_zero = mem.y_from_zero = speed.y_from_zero = false;
    for (const std::string& name : order) {
        const auto& pts = by_scene[name];
        std::array<double, 5> at1{};
        for (const auto& p : pts)
            if (p[0] == 1.0) at1 = p;
        const int color = int(sah.series.size());
        plot_series a, b, primary, diffuse;
        a.label = b.label = primary.label = name;
        diffuse.color = primary.color = color, diffuse.dashed = true, diffuse.in_legend = false;
        for (const auto& p : pts) {
            const double x = p[0] > 0 ? p[0] : 1e-7;
            const auto rel = [&](int k) { return at1[std::size_t(k)] > 0 ? p[std::size_t(k)] / at1[std::size_t(k)] : NAN; };
            a.x.push_back(x), a.y.push_back(rel(1));
            b.x.push_back(x), b.y.push_back(rel(2));
            primary.x.push_back(x), primary.y.push_back(rel(3));
            diffuse.x.push_back(x), diffuse.y.push_back(rel(4));
        }
        sah.series.push_back(a), mem.series.push_back(b), speed.series.push_back(primary), speed.series.push_back(diffuse);
    }
    return to_svg(std::vector<plot>{sah, mem, speed}, 3, 560, 420);
}

int run(int argc, const char* const* argv) {
    cli args("ch09", "Chapter 09, spatial splits (" + std::string(track_name()) + "): the SBVH beside chapter 05's "
             "binned SAH tree, chapter 06's reinserted tree and chapter 03's k-d tree (SAH cost, references per "
             "triangle, memory, build ms, Mrays/s on one thread, as compare.csv), and the overlap threshold alpha "
             "swept from 1 to 0 (alpha.csv, alpha.svg).");
    args.scene_option({"sponza", "stadium", "bunny", "armadillo"}, {"sponza", "stadium", "bunny", "armadillo"},
                      "the shared meshes where present")
        .option("width", "N", "", "primary rays per row, 1..4096 (default 192, 48 with --quick)")
        .option("height", "N", "", "rows, 1..4096 (default 3/4 of the width)")
        .option("repeats", "K", "", "timed runs per measurement after a warm-up; the median is reported (default 5, "
                "1 with --quick)")
        .option("alphas", "LIST", "1,1e-1,1e-2,1e-3,1e-4,1e-5,0", "the overlap thresholds swept, each in [0, 1]")
        .option("budget", "B", "1.5", "references per triangle at most, in [1, 16]")
        .option("spatial-bins", "K", "16", "chopped bins per axis of a spatial split, 2..256")
        .option("max-leaf", "N", "8", "references per leaf at most, 1..255")
        .flag("sweep-only", "only the alpha sweep (compare.csv then holds its header alone)")
        .option("variants", "LIST", "", "instead: the SBVH with each variant at each of --alphas, into variants.csv: "
                "default, budget=B, bins=K (chopped bins), leaf=N (max_leaf) or unsplit=0|1, comma-separated")
        .output_options("write compare.csv, alpha.csv and alpha.svg into DIR/ (default out/09_sbvh/)")
        .option("replot", "CSV", "", "only draw alpha.svg from an alpha.csv this program wrote")
        .flag("quick", "the teapot in a stadium only, 48 x 36 rays, one repeat, alphas 1, 1e-5 and 0")
        .option("diagrams", "DIR", "", "only draw the chapter's figure into DIR/ (splits.svg; --force to replace it)");
    if (!args.parse(argc, argv)) return 0;
    if (draw_diagrams_if_asked(args, strahl::ch09::write_diagrams)) return 0;
    fs::path folder = "out/09_sbvh";
    const bool user_named = args.has("out"), force = args.has("force");
    if (user_named) folder = args.get("out");
    if (args.has("replot")) {
        const fs::path csv = args.get("replot");
        const std::string svg = alpha_svg(read_csv(csv, alpha_header, machine_header, "an alpha.csv written by ch09"), csv);
        prepare_output(folder / "alpha.svg", user_named, force);
        write_svg(folder / "alpha.svg", svg);
        std::printf("wrote %s\n", (folder / "alpha.svg").string().c_str());
        return 0;
    }
    const bool quick = args.has("quick");
    options o;
    const image_size size = read_image_size(args, quick ? 48 : 192, 4096, 200);
    o.width = size.width, o.height = size.height;
    o.repeats = args.has("repeats") ? args.get_int("repeats") : quick ? 1 : 5;
    if (o.repeats < 1 || o.repeats > 100) throw usage_error("--repeats must lie in [1, 100]");
    o.sbvh.budget = float(args.get_double("budget"));
    if (!(o.sbvh.budget >= 1.0f && o.sbvh.budget <= 16.0f)) throw usage_error("--budget must lie in [1, 16]");
    o.sbvh.spatial_bins = args.get_int("spatial-bins");
    if (o.sbvh.spatial_bins < 2 || o.sbvh.spatial_bins > 256) throw usage_error("--spatial-bins must lie in [2, 256]");
    o.sbvh.max_leaf = args.get_int("max-leaf");
    if (o.sbvh.max_leaf < 1 || o.sbvh.max_leaf > 255) throw usage_error("--max-leaf must lie in [1, 255]");
    o.sweep_only = args.has("sweep-only");
    {
        std::string text = quick && !args.has("alphas") ? "1,1e-5,0" : args.get("alphas");
        std::stringstream list(text);
        for (std::string item; std::getline(list, item, ',');) {
            char* end = nullptr;
            const double a = std::strtod(item.c_str(), &end);
            if (item.empty() || *end != '\0' || !(a >= 0.0 && a <= 1.0))
                throw usage_error("--alphas: '" + item + "' is no number in [0, 1]");
            o.alphas.push_back(a);
        }
    }
    std::vector<std::string> names = args.scene_names();
    if (quick) names = {"stadium"};
    std::vector<std::string> variants;
    if (args.has("variants")) {
        std::stringstream list(args.get("variants"));
        for (std::string item; std::getline(list, item, ',');) variant_params(item, o.sbvh), variants.push_back(item);
        if (variants.empty()) throw usage_error("--variants: an empty list");
        prepare_output(folder / "variants.csv", user_named, force);
    } else {
        for (const char* f : {"compare.csv", "alpha.csv", "alpha.svg"}) prepare_output(folder / f, user_named, force);
    }

    std::vector<scene> scenes;
    for (const std::string& name : names)
        if (auto s = course_scene(name)) scenes.push_back(std::move(*s));
    std::ostringstream compare, sweep;
    if (!variants.empty()) {
        for (const scene& s : scenes) run_variants(s, o, variants, compare);
        write_text(folder / "variants.csv", with_machine(std::string(variants_header) + "\n" + compare.str(), this_machine(parallel_threads())));
        std::printf("wrote %s\n", (folder / "variants.csv").string().c_str());
        return 0;
    }
    for (const scene& s : scenes) run_scene(s, o, compare, sweep);
    const machine_columns here = this_machine(parallel_threads());
    write_text(folder / "compare.csv", with_machine(std::string(compare_header) + "\n" + compare.str(), here));
    const std::string alpha_csv = with_machine(std::string(alpha_header) + "\n" + sweep.str(), here);
    write_text(folder / "alpha.csv", alpha_csv);
    write_svg(folder / "alpha.svg", alpha_svg(read_csv(folder / "alpha.csv", alpha_header, machine_header, "an alpha.csv written by ch09"),
                                              folder / "alpha.csv"));
    for (const char* f : {"compare.csv", "alpha.csv", "alpha.svg"}) std::printf("wrote %s\n", (folder / f).string().c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch09_exercise" : "ch09", run, argc, argv);
}
