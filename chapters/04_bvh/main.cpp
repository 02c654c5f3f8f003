// ch04: the BVH. Builds chapter 04's BVH (object median and spatial median) over the teapot, the teapot in
// a stadium and the shared bunny for both primitive sets, renders primary rays through it, and prints per
// build: nodes, leaves, depth, memory, build time, box and triangle tests per ray, Mrays/s, and writes that
// table as runs.csv. Draws the lecture's picture of the AABB problem: box tests per pixel as a heat map
// (rays grazing the surface pay most), with the boxes of chosen levels drawn over it.
#include "strahl/diagram.hpp"
#include "strahl/ch02/accel.hpp"
#include "strahl/ch03/accel.hpp"
#include "strahl/ch04/accel.hpp"
#include "strahl/display.hpp"
#include "strahl/image.hpp"
#include "strahl/machine.hpp"
#include "strahl/parallel.hpp"
#include "strahl/procedural.hpp"
#include "strahl/primary_trace.hpp"
#include "strahl/plot.hpp"
#include "strahl/program.hpp"
#include "strahl/timer.hpp"
#include <cstdio>
#include <fstream>

namespace strahl::ch04 {
// The chapter's figures (src/diagrams.cpp): SVG files drawn from the structures its code builds.
std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force);
}  // namespace strahl::ch04

namespace {

using namespace strahl;
using namespace strahl::ch04;
namespace fs = std::filesystem;

struct options {
    int width, height, first_level, last_level;
    fs::path folder{"out/04_bvh"};
    bool user_named = false, force = false;
};

// Facing-ratio shading: |cos| between the ray and the triangle's normal; background dark blue.
image shade(const scene& s, const camera& cam, const std::vector<hit>& hits) {
    image img(cam.width(), cam.height(), color(0.05f, 0.07f, 0.12f));
    for (int y = 0; y < cam.height(); ++y)
        for (int x = 0; x < cam.width(); ++x) {
            const hit& h = hits[std::size_t(y) * cam.width() + x];
            if (!h.found()) continue;
            const auto t = s.mesh.triangle(h.prim);
            const vec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
            const vec3 d = cam.pixel_ray(x, y).dir;
            const float f = std::abs(glm::dot(n, d)) / std::max(1e-30f, glm::length(n) * glm::length(d));
            img.at(x, y) = color(0.15f + 0.8f * f);
        }
    return img;
}

// The heat map of box tests per pixel, with the boxes of the chosen levels drawn over its picture rows.
image box_test_picture(const bvh& t, const camera& cam, const primary_trace& r, const options& o) {
    static const color palette[] = {{1.0f, 1.0f, 1.0f}, {1.0f, 0.3f, 0.2f}, {1.0f, 0.7f, 0.1f},
                                    {0.3f, 1.0f, 0.4f}, {0.3f, 0.8f, 1.0f}, {0.8f, 0.5f, 1.0f}};
    image heat = heat_map(r.box_tests, cam.width(), cam.height(), "box tests per ray");
    image top(cam.width(), cam.height());
    std::copy_n(heat.pixels.begin(), top.pixels.size(), top.pixels.begin());
    std::vector<line_segment> lines;
    for (const level_box& lb : level_boxes(t, o.first_level, o.last_level)) {
        const auto edges = box_wireframe(lb.box, palette[(lb.level - o.first_level) % 6]);
        lines.insert(lines.end(), edges.begin(), edges.end());
    }
    draw_lines(top, cam, lines, 1.0f);
    std::copy(top.pixels.begin(), top.pixels.end(), heat.pixels.begin());
    return heat;
}

// runs.csv: a row per scene, split and primitive set, the table the program prints. Columns: scene,
// triangles, width and height (primary rays), split (median: object median; spatial), set (triangles or
// virtual), nodes, leaves, depth, memory_bytes (nodes and index array) and the same in KiB and MiB,
// build_ms, nodes, box and triangle tests per ray, mrays_per_s (one timed run on all threads), and
// speed_vs_triangles: this row's Mrays/s over the same split's triangles row (1 for that row).
const char* const runs_header =
    "scene,triangles,width,height,split,set,nodes,leaves,depth,memory_bytes,memory_kib,memory_mib,build_ms,"
    "nodes_per_ray,box_tests_per_ray,prim_tests_per_ray,mrays_per_s,speed_vs_triangles";

void run_scene(const scene& s, const options& o, std::ostream& csv) {
    const camera cam(s.camera, o.width, o.height);
    const fs::path render_path = o.folder / (s.name + ".png"), heat_path = o.folder / (s.name + "_box_tests.png");
    prepare_output(render_path, o.user_named, o.force);
    prepare_output(heat_path, o.user_named, o.force);
    std::printf("%s: %zu triangles, %d x %d primary rays\n", s.name.c_str(), s.mesh.triangle_count(), o.width,
                o.height);
    std::printf("  %-8s %-9s %8s %5s %9s %9s %10s %9s %9s %8s\n", "split", "set", "nodes", "depth", "memory",
                "build ms", "nodes/ray", "boxes/ray", "tris/ray", "Mrays/s");
    for (const split_method m : {split_method::object_median, split_method::spatial_median}) {
        double triangles_mrays = 0.0;
        for (const bool is_virtual : {false, true}) {
            bvh_build_params p;
            p.split = m;
            const auto a = make_bvh_accel(is_virtual, p);
            a->build(s);
            const bvh& t = a->tree();
            const primary_trace r = trace_primary(*a, cam, s.name + " " + a->name());
            const double rays = double(r.hits.size());
            std::printf("  %-8s %-9s %8zu %5d %8.1fK %9.1f %10.1f %9.1f %9.1f %8.2f\n", to_string(m),
                        is_virtual ? "virtual" : "triangles", t.nodes.size(), t.stats.depth,
                        double(t.memory_bytes()) / 1024.0, t.stats.build_ms, r.counts.per_ray(r.counts.nodes_visited),
                        r.counts.per_ray(r.counts.box_tests), r.counts.per_ray(r.counts.prim_tests),
                        rays / r.seconds * 1e-6);
            const double mrays = rays / r.seconds * 1e-6;
            if (!is_virtual) triangles_mrays = mrays;
            csv << s.name << ',' << s.mesh.triangle_count() << ',' << o.width << ',' << o.height << ','
                << to_string(m) << ',' << (is_virtual ? "virtual" : "triangles") << ',' << t.nodes.size() << ','
                << t.stats.leaves << ',' << t.stats.depth << ',' << t.memory_bytes() << ','
                << double(t.memory_bytes()) / 1024.0 << ',' << double(t.memory_bytes()) / (1024.0 * 1024.0) << ','
                << t.stats.build_ms << ',' << r.counts.per_ray(r.counts.nodes_visited) << ','
                << r.counts.per_ray(r.counts.box_tests) << ',' << r.counts.per_ray(r.counts.prim_tests) << ','
                << mrays << ',' << mrays / triangles_mrays << '\n';
            if (is_virtual || m != split_method::object_median) continue;
            write_image(render_path, shade(s, cam, r.hits));
            write_image(heat_path, box_test_picture(t, cam, r, o));
        }
    }
    std::printf("  memory: nodes (32 bytes) + index array (4 bytes per triangle); at most 2N - 1 nodes\n");
    std::printf("  wrote    %s, %s\n", render_path.string().c_str(), heat_path.string().c_str());
}

// "Hierarchical, hence logarithmic": the teapot tessellated ever finer, primary rays through the grid, the
// k-d tree and the BVH (one thread), against brute force, whose every ray tests all N triangles. Writes
// sweep.csv and sweep.svg: triangle tests per ray and nodes (cells) per ray against N, and Mrays/s.
void sweep(bool quick, const options& o) {
    const std::vector<int> resolutions = quick ? std::vector<int>{1, 2, 4} : std::vector<int>{1, 2, 4, 8, 16, 32};
    const int w = quick ? 48 : 160, h = w * 3 / 4;
    const fs::path csv_path = o.folder / "sweep.csv", svg_path = o.folder / "sweep.svg";
    prepare_output(csv_path, o.user_named, o.force);
    prepare_output(svg_path, o.user_named, o.force);
    const thread_limit one(1);
    std::printf("sweep: the teapot tessellated ever finer, %d x %d primary rays, one thread\n", w, h);
    std::printf("  %9s  %-10s %9s %10s %9s %9s\n", "triangles", "structure", "build ms", "nodes/ray", "tris/ray",
                "Mrays/s");
    std::ofstream csv(csv_path);
    csv << "triangles,structure,build_ms,nodes_per_ray,prim_tests_per_ray,mrays_per_s\n";
    const char* names[] = {"grid", "k-d tree", "BVH"};
    std::vector<plot_series> tests(3), nodes(3), speed(3);
    plot_series brute{"brute force (N)", {}, {}, true, {}, 7};
    for (int k = 0; k < 3; ++k) tests[k].label = nodes[k].label = speed[k].label = names[k];
    for (const int res : resolutions) {
        const scene s = teapot_scene(res);
        const camera cam(s.camera, w, h);
        const double n = double(s.mesh.triangle_count());
        brute.x.push_back(n), brute.y.push_back(n);
        csv << s.mesh.triangle_count() << ",brute force,0,0," << s.mesh.triangle_count() << ",\n";
        for (int k = 0; k < 3; ++k) {
            const auto a = k == 0 ? ch02::make_accel(false) : k == 1 ? ch03::make_accel(false) : make_accel(false);
            const timer built;
            a->build(s);
            const double build_ms = built.milliseconds();
            const primary_trace r = trace_primary(*a, cam, s.name + " " + names[k]);
            const double per_node = r.counts.per_ray(r.counts.nodes_visited), per_tri = r.counts.per_ray(r.counts.prim_tests);
            const double mrays = double(r.hits.size()) / r.seconds * 1e-6;
            std::printf("  %9zu  %-10s %9.1f %10.1f %9.1f %9.2f\n", s.mesh.triangle_count(), names[k], build_ms,
                        per_node, per_tri, mrays);
            csv << s.mesh.triangle_count() << ',' << names[k] << ',' << build_ms << ',' << per_node << ','
                << per_tri << ',' << mrays << '\n';
            tests[k].x.push_back(n), tests[k].y.push_back(per_tri);
            nodes[k].x.push_back(n), nodes[k].y.push_back(per_node);
            speed[k].x.push_back(n), speed[k].y.push_back(mrays);
        }
    }
    plot pt{"triangle tests per ray", "triangles N", "tests per ray", true, true, {}};
    pt.series = tests;
    pt.series.push_back(brute);
    plot pn{"nodes (cells) visited per ray: log N is a straight line here", "triangles N", "nodes per ray", true,
            false, nodes};
    plot ps{"Mrays/s, one thread", "triangles N", "Mrays/s", true, true, speed};
    write_svg(svg_path, to_svg(std::vector<plot>{pt, pn, ps}, 3, 420, 340));
    csv.close();
    stamp_machine(csv_path, parallel_threads());
    std::printf("  wrote    %s, %s\n", csv_path.string().c_str(), svg_path.string().c_str());
}

int run(int argc, const char* const* argv) {
    cli args("ch04", "Chapter 04, the BVH (" + std::string(track_name()) + "): object and spatial median BVHs over plain "
             "triangles and virtual objects, primary rays through them, tree statistics, and box tests per "
             "pixel as a heat map with the boxes of chosen levels drawn over it.");
    args.scene_option({"teapot", "stadium", "bunny"}, {"teapot", "stadium", "bunny"}, "only the first two with --quick")
        .option("width", "N", "", "image width, 1..16384 (default 640, 320 with --quick; 16384 x 16384 needs over "
                                  "20 GB of memory: refused where the machine has less)")
        .option("height", "N", "", "image height, 1..16384 (default 3/4 of the width)")
        .option("levels", "A-B", "2-3", "draw the boxes of the nodes at depths A to B (the root is depth 0)")
        .threads_option("0", "worker threads, 0..1024 (0: one per core)")
        .output_options("write the images and runs.csv into DIR/ (default out/04_bvh/)")
        .flag("quick", "smaller images and only the built-in scenes")
        .flag("sweep", "measure instead how the grid, the k-d tree and the BVH scale with the triangle count "
                       "(writes sweep.csv, sweep.svg)")
        .option("diagrams", "DIR", "", "only draw the chapter's figures into DIR/ (subdivision.svg, flattened.svg, "
                                       "slab_test.svg; --force to replace them)");
    if (!args.parse(argc, argv)) return 0;
    if (draw_diagrams_if_asked(args, write_diagrams)) return 0;
    const bool quick = args.has("quick");
    const int threads = read_threads(args, 0);
    const thread_limit limit(threads);
    options o;
    // Per pixel: a primary ray's hit and its counts (28 bytes), the rendered image, the heat map and its
    // picture (12 bytes each), the PNG rows, and room for the structures: 80 bytes is ample.
    const image_size size = read_image_size(args, quick ? 320 : 640, 16384, 80);
    o.width = size.width, o.height = size.height;
    const std::string levels = args.get("levels");
    char dash = 0, extra = 0;
    if (std::sscanf(levels.c_str(), "%d%c%d%c", &o.first_level, &dash, &o.last_level, &extra) != 3 || dash != '-' ||
        o.first_level < 0 || o.last_level < o.first_level || o.last_level > 20)
        throw usage_error("--levels must be A-B with 0 <= A <= B <= 20, not '" + levels + "'");
    if (args.has("out")) {
        o.folder = args.get("out");
        o.user_named = true;
    }
    o.force = args.has("force");

    if (args.has("sweep")) {
        sweep(quick, o);
        return 0;
    }
    std::vector<std::string> all = {"teapot", "stadium"};
    if (!quick) all.push_back("bunny");
    const std::vector<std::string> names = args.scene_names(all);
    const fs::path runs_path = o.folder / "runs.csv";
    prepare_output(runs_path, o.user_named, o.force);
    std::ofstream runs(runs_path);
    runs << runs_header << '\n';
    for (const std::string& name : names)
        if (const auto s = course_scene(name)) run_scene(*s, o, runs);
    runs.close();
    stamp_machine(runs_path, parallel_threads());
    std::printf("wrote %s\n", runs_path.string().c_str());
    std::printf("against the grid, the k-d tree and Embree, on the same rays:\n"
                "  build/release/bin/race --quick --accels brute,ch02-grid,ch03-kd,ch04-median,ch04-spatial,"
                "embree-medium\n");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch04_exercise" : "ch04", run, argc, argv);
}
