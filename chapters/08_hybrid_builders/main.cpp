// ch08: the hybrid builders. Builds HLBVH, PLOC (three search radii), TRBVH and ATRBVH over the teapot in a
// stadium, a random soup, the bunny and Sponza (when the shared meshes are there), beside chapter 05's
// binned SAH tree and chapter 07's LBVH, and measures each one's build time at 1 and N threads, SAH cost
// and trace speed on one thread (every tree's hits checked against chapter 05's). With --from-race it
// draws instead the build/trace trade of a race's every BVH builder and Embree, and its Pareto frontier.
#include "strahl/diagram.hpp"
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch05/accel.hpp"
#include "strahl/ch07/builder_scenes.hpp"
#include "strahl/ch07/lbvh.hpp"
#include "strahl/ch08/accel.hpp"
#include "strahl/ch08/pareto.hpp"
#include "strahl/machine.hpp"
#include "strahl/parallel.hpp"
#include "strahl/plot.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/scene.hpp"
#include "strahl/timer.hpp"
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

namespace strahl::ch08 {
// The chapter's figures (src/diagrams.cpp): a treelet before and after the subset DP, and one round of PLOC.
std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force);
}  // namespace strahl::ch08

namespace {

using namespace strahl;
namespace fs = std::filesystem;

struct options {
    int width = 192, height = 144, repeats = 5, threads = 2;
};

const char* const builders_header = "scene,triangles,builder,build_ms_1,build_ms_n,threads,speedup,sah_cost,depth,"
                                    "nodes,primary_mrays_s,diffuse_mrays_s,differing";

// Every builder on one scene: build times (median of o.repeats after a warm-up) on one thread and on
// o.threads, the flat tree's SAH cost, and the trace speed of chapter 05's fast walk on one thread.
void compare(const scene& s, const options& o, std::ostream& csv) {
    const ch07::builder_inputs in(s.mesh);
    ch05::sah_build_params binned;
    binned.bins = 16;
    const auto reference = ch05::make_accel(false, binned, ch05::walk_kind::fast);
    reference->build(s);
    const ch01::checked_rays rays = ch01::make_checked_rays(s, o.width, o.height, *reference);
    std::vector<ch08::variant> list = {
        {"ch05-binned16", "chapter 05's binned SAH", [binned](std::span<const aabb> b, std::span<const vec3> c) {
             return ch05::build_sah_bvh_fast(b, c, binned);
         }},
        {"ch07-lbvh30", "chapter 07's LBVH",
         [](std::span<const aabb> b, std::span<const vec3> c) { return ch07::build_lbvh(b, c); }}};
    for (const ch08::variant& v : ch08::variants()) list.push_back(v);
    std::printf("%s: %zu triangles; builds at 1 and %d threads, tracing on one thread (%d x %d primary rays and as "
                "many diffuse)\n", s.name.c_str(), in.boxes.size(), o.threads, o.width, o.height);
    std::printf("  %-14s %9s %9s %8s %8s %6s %9s %9s %9s %6s\n", "builder", "1 thr ms", "N thr ms", "speed-up", "SAH",
                "depth", "nodes", "primary", "diffuse", "differ");
    for (const ch08::variant& v : list) {
        double ms[2] = {0, 0};
        for (const int k : {0, 1}) {
            const thread_limit limit(k == 0 ? 1 : o.threads);
            ms[k] = median_ms(o.repeats, [&] { v.build(in.boxes, in.centroids); });
        }
        const auto a = ch05::make_bvh_accel(false, v.name, v.build, ch05::walk_kind::fast);
        {
            const thread_limit one(1);
            a->build(s);
        }
        const ch04::bvh& t = a->tree();
        const double sah = ch05::tree_cost(t);
        const ch01::checked_speed speed = ch01::time_checked(*a, rays, o.repeats);
        std::printf("  %-14s %9.2f %9.2f %8.2f %8.2f %6d %9zu %9.2f %9.2f %6zu\n", v.name.c_str(), ms[0], ms[1],
                    ms[0] / ms[1], sah, t.stats.depth, t.nodes.size(), speed.primary_mrays, speed.diffuse_mrays,
                    speed.differing);
        std::fflush(stdout);
        csv << s.name << ',' << in.boxes.size() << ',' << v.name << ',' << ms[0] << ',' << ms[1] << ',' << o.threads
            << ',' << ms[0] / ms[1] << ',' << sah << ',' << t.stats.depth << ',' << t.nodes.size() << ','
            << speed.primary_mrays << ',' << speed.diffuse_mrays << ',' << speed.differing << '\n';
    }
}

int run(int argc, const char* const* argv) {
    cli args("ch08", "Chapter 08, the hybrid builders (" + std::string(track_name()) + "): HLBVH, PLOC, TRBVH and ATRBVH "
             "beside chapter 05's binned SAH and chapter 07's LBVH: build time at 1 and N threads, SAH cost, Mrays/s on "
             "one thread, as a table and builders.csv. --from-race draws every BVH builder's and Embree's build/trace "
             "trade from a race, with its Pareto frontier.");
    args.option("scene", "NAME", "all", "stadium, soup, bunny, sponza, teapot or all (all: stadium, soup, bunny, sponza)")
        .threads_option("2", "the second thread count builds are timed at, 0..1024 (0: one per core)")
        .option("width", "N", "", "primary rays per row, 1..4096 (default 192, 48 with --quick)")
        .option("height", "N", "", "rows, 1..4096 (default 3/4 of the width)")
        .option("repeats", "K", "", "timed runs per measurement after a warm-up; the median is reported (default 5, "
                "1 with --quick)")
        .output_options("write builders.csv (or with --from-race pareto.csv and pareto.svg) into DIR/ "
                "(default out/08_hybrid_builders/)")
        .option("from-race", "CSV", "", "only draw pareto.svg and write pareto.csv from a race.csv (race --processes N "
                "with chapters 04-08's *-fast BVH rows and embree-low, -medium and -high)")
        .flag("quick", "the teapot and a soup of 20,000 triangles, 48 x 36 rays, one repeat")
        .option("diagrams", "DIR", "", "only draw the chapter's figures into DIR/ (treelet.svg, ploc.svg; --force to replace them)");
    if (!args.parse(argc, argv)) return 0;
    if (draw_diagrams_if_asked(args, strahl::ch08::write_diagrams)) return 0;
    fs::path folder = "out/08_hybrid_builders";
    const bool user_named = args.has("out"), force = args.has("force");
    if (user_named) folder = args.get("out");
    if (args.has("from-race")) {
        // The table read first: a file that is no race.csv leaves no folder behind.
        const std::vector<ch08::pareto_point> points = ch08::pareto_points(read_race_rows(args.get("from-race")));
        const std::string svg = ch08::pareto_svg(points);
        for (const char* f : {"pareto.csv", "pareto.svg"}) prepare_output(folder / f, user_named, force);
        write_text(folder / "pareto.csv", ch08::pareto_csv(points));
        write_svg(folder / "pareto.svg", svg);
        std::printf("wrote %s, %s from %zu points of %s\n", (folder / "pareto.csv").string().c_str(),
                    (folder / "pareto.svg").string().c_str(), points.size(), args.get("from-race").c_str());
        return 0;
    }
    const bool quick = args.has("quick");
    options o;
    const image_size size = read_image_size(args, quick ? 48 : 192, 4096, 200);
    o.width = size.width, o.height = size.height;
    o.repeats = args.has("repeats") ? args.get_int("repeats") : quick ? 1 : 5;
    if (o.repeats < 1 || o.repeats > 100) throw usage_error("--repeats must lie in [1, 100]");
    o.threads = read_threads(args, 0);
    if (o.threads == 0) o.threads = int(std::max(1u, std::thread::hardware_concurrency()));
    const std::string which = ch07::builder_scene_choice(args.get("scene"), quick);
    const fs::path csv_path = folder / "builders.csv";
    prepare_output(csv_path, user_named, force);

    const std::vector<scene> scenes = ch07::builder_scenes(which);
    std::ostringstream rows;
    for (const scene& s : scenes) compare(s, o, rows);
    write_text(csv_path, with_machine(std::string(builders_header) + "\n" + rows.str(), this_machine(o.threads)));
    std::printf("wrote %s\n", csv_path.string().c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch08_exercise" : "ch08", run, argc, argv);
}
