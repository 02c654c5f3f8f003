// ch03: the k-d tree. Builds chapter 03's SAH k-d tree over the teapot, the teapot in a stadium and the
// shared bunny (Sponza with --sponza) for both primitive sets, renders primary rays through it (shaded by
// facing ratio), draws the first levels' split planes over the render, and prints per set: nodes, leaves,
// depth, references per triangle, memory, build time, SAH cost, nodes and triangles tested per ray, Mrays/s,
// and writes that table as runs.csv.
#include "strahl/diagram.hpp"
#include "strahl/ch03/accel.hpp"
#include "strahl/display.hpp"
#include "strahl/image.hpp"
#include "strahl/machine.hpp"
#include "strahl/parallel.hpp"
#include "strahl/procedural.hpp"
#include "strahl/primary_trace.hpp"
#include "strahl/program.hpp"
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace strahl::ch03 {
// The chapter's figure (src/diagrams.cpp): an SVG file drawn by the chapter's own traversal step.
std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force);
}  // namespace strahl::ch03

namespace {

using namespace strahl;
using namespace strahl::ch03;
namespace fs = std::filesystem;

struct options {
    int width, height, levels;
    fs::path folder{"out/03_kd_tree"};
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

// The split planes of the first levels as rectangles clipped to their node boxes, coloured by level.
std::vector<line_segment> plane_lines(const kd_tree& tree, int levels) {
    static const color palette[] = {{1.0f, 0.15f, 0.1f}, {1.0f, 0.6f, 0.0f}, {1.0f, 1.0f, 0.1f},
                                    {0.2f, 1.0f, 0.3f}, {0.2f, 0.8f, 1.0f}, {0.7f, 0.4f, 1.0f}};
    std::vector<line_segment> lines;
    for (const kd_plane& p : split_planes(tree, levels))
        for (int k = 0; k < 4; ++k)
            lines.push_back({p.corners[k], p.corners[(k + 1) % 4], palette[std::min(p.level, 5)]});
    return lines;
}

// runs.csv: a row per scene and primitive set, the table the program prints. Columns: scene, triangles,
// width and height (primary rays), set (triangles or virtual), nodes, leaves, depth, refs_per_tri
// (references per triangle), memory_bytes (8-byte nodes and 4-byte references) and the same in KiB and
// MiB, build_ms, sah (the tree's SAH cost), nodes and triangle tests per ray, hit_percent (the share of
// primary rays that hit a triangle), mrays_per_s (one timed run on all threads), and speed_vs_triangles:
// this row's Mrays/s over the scene's triangles row (1 for that row).
const char* const runs_header =
    "scene,triangles,width,height,set,nodes,leaves,depth,refs_per_tri,memory_bytes,memory_kib,memory_mib,build_ms,"
    "sah,nodes_per_ray,prim_tests_per_ray,hit_percent,mrays_per_s,speed_vs_triangles";

void run_scene(const scene& s, const options& o, std::ostream& csv) {
    const camera cam(s.camera, o.width, o.height);
    const fs::path render_path = o.folder / (s.name + ".png"), planes_path = o.folder / (s.name + "_planes.png");
    prepare_output(render_path, o.user_named, o.force);
    prepare_output(planes_path, o.user_named, o.force);
    std::printf("%s: %zu triangles, %d x %d primary rays\n", s.name.c_str(), s.mesh.triangle_count(), o.width,
                o.height);
    std::printf("  %-9s %8s %8s %5s %9s %9s %9s %6s %10s %10s %8s\n", "set", "nodes", "leaves", "depth",
                "refs/tri", "memory", "build ms", "SAH", "nodes/ray", "tris/ray", "Mrays/s");
    double triangles_mrays = 0.0;
    for (const bool is_virtual : {false, true}) {
        const auto a = make_kd_accel(is_virtual);
        a->build(s);
        const kd_tree& t = a->tree();
        const primary_trace r = trace_primary(*a, cam, s.name + (is_virtual ? " virtual" : " triangles"));
        const double rays = double(r.hits.size());
        std::printf("  %-9s %8zu %8zu %5d %9.2f %8.1fK %9.1f %6.1f %10.1f %10.1f %8.2f\n",
                    is_virtual ? "virtual" : "triangles", t.nodes.size(), t.stats.leaves, t.stats.depth,
                    t.stats.refs_per_prim(), double(t.memory_bytes()) / 1024.0, t.stats.build_ms, t.sah_cost(),
                    r.counts.per_ray(r.counts.nodes_visited), r.counts.per_ray(r.counts.prim_tests),
                    rays / r.seconds * 1e-6);
        const double mrays = rays / r.seconds * 1e-6;
        if (!is_virtual) triangles_mrays = mrays;
        const double hits = double(std::count_if(r.hits.begin(), r.hits.end(), [](const hit& h) { return h.found(); }));
        csv << s.name << ',' << s.mesh.triangle_count() << ',' << o.width << ',' << o.height << ','
            << (is_virtual ? "virtual" : "triangles") << ',' << t.nodes.size() << ',' << t.stats.leaves << ','
            << t.stats.depth << ',' << t.stats.refs_per_prim() << ',' << t.memory_bytes() << ','
            << double(t.memory_bytes()) / 1024.0 << ',' << double(t.memory_bytes()) / (1024.0 * 1024.0) << ','
            << t.stats.build_ms << ',' << t.sah_cost() << ',' << r.counts.per_ray(r.counts.nodes_visited) << ','
            << r.counts.per_ray(r.counts.prim_tests) << ',' << 100.0 * hits / std::max(1.0, rays) << ',' << mrays
            << ',' << mrays / triangles_mrays << '\n';
        if (is_virtual) continue;
        // The picture: the render, then the same with the first levels' planes drawn over it.
        image img = shade(s, cam, r.hits);
        write_image(render_path, img);
        draw_lines(img, cam, plane_lines(t, o.levels), 1.0f);
        write_image(planes_path, img);
        std::printf("  tree     %zu inner nodes, %zu empty leaves, largest leaf %zu, depth limit %d; "
                    "memory: nodes + references only (the triangles are the set's)\n",
                    t.stats.inner, t.stats.empty_leaves, t.stats.max_leaf, t.stats.depth_limit);
    }
    std::printf("  wrote    %s, %s\n", render_path.string().c_str(), planes_path.string().c_str());
}

int run(int argc, const char* const* argv) {
    cli args("ch03", "Chapter 03, the k-d tree (" + std::string(track_name()) + "): SAH k-d trees over plain triangles and "
             "virtual objects, primary rays through them, tree statistics and the split planes drawn.");
    args.scene_option({"teapot", "stadium", "bunny", "sponza"}, {"teapot", "stadium", "bunny"}, "Sponza only with --sponza")
        .option("width", "N", "", "image width, 1..16384 (default 640, 320 with --quick; 16384 x 16384 needs over "
                                  "20 GB of memory: refused where the machine has less)")
        .option("height", "N", "", "image height, 1..16384 (default 3/4 of the width)")
        .option("levels", "N", "4", "draw the split planes of this many levels")
        .threads_option("0", "worker threads, 0..1024 (0: one per core)")
        .output_options("write the images and runs.csv into DIR/ (default out/03_kd_tree/)")
        .flag("sponza", "with --scene all: also Sponza (262k triangles, a build of seconds)")
        .flag("quick", "smaller images and only the built-in scenes")
        .option("diagrams", "DIR", "", "only draw the chapter's figure into DIR/ (near_far.svg; --force to replace it)");
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
    o.levels = args.get_int("levels");
    if (o.levels < 0 || o.levels > 12) throw usage_error("--levels must lie in [0, 12]");
    if (args.has("out")) {
        o.folder = args.get("out");
        o.user_named = true;
    }
    o.force = args.has("force");

    std::vector<std::string> all = {"teapot", "stadium"};
    if (!quick) all.push_back("bunny");
    if (!quick && args.has("sponza")) all.push_back("sponza");
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
    std::printf("against the uniform grid (chapter 02) and Embree, on the same rays:\n"
                "  build/release/bin/race --quick --accels brute,ch02-grid,ch03-kd,ch03-kd-virtual,embree-medium\n");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch03_exercise" : "ch03", run, argc, argv);
}
