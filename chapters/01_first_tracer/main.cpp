// ch01: the first tracer. Renders the Cornell box (with a mirror and a rough-mirror sphere) and the
// teapot with brute-force Whitted ray tracing, and prints what it cost: rays by kind, rays per pixel,
// Mrays/s, primitive tests per ray. --sweep measures how that cost grows with the triangle count.
#include "strahl/ch01/render.hpp"
#include "strahl/parallel.hpp"
#include "strahl/plot.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/scene.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <vector>

namespace {

using namespace strahl;
using namespace strahl::ch01;
namespace fs = std::filesystem;

const fs::path default_folder = "out/01_first_tracer";

struct job {
    std::string name;
    scene s;
    int width, height;
};

std::string grouped(std::uint64_t n) {
    const std::string digits = std::to_string(n);
    std::string s;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) s += ',';
        s += digits[i];
    }
    return s;
}

// Where an image goes: the course's own folder, a folder the user named, or a file the user named.
struct output_plan {
    fs::path folder = default_folder;
    fs::path file;  // set when --out names one file
    bool user_named = false;
    fs::path path_for(const std::string& name) const { return file.empty() ? folder / (name + ".png") : file; }
};

output_plan plan_output(const cli& args, std::size_t images) {
    output_plan plan;
    if (!args.has("out")) return plan;
    const std::string out = args.get("out");
    plan.user_named = true;
    std::error_code ec;
    if (fs::is_directory(out, ec) || out.back() == '/') {
        plan.folder = out;
    } else {
        if (images != 1)
            throw usage_error("--out " + out + " names one file but " + std::to_string(images) +
                              " images are rendered: name a folder (ending in /) or pick one --scene");
        plan.file = out;
    }
    return plan;
}

// The ray heat map's file beside an image's: NAME_rays.png.
fs::path heat_path_for(const fs::path& image) {
    fs::path heat = image;
    heat.replace_filename(image.stem().string() + "_rays" + image.extension().string());
    return heat;
}

void render_job(const job& j, const cli& args, const output_plan& plan) {
    world_counts n;
    const world w = build_world(j.s, args.get_int("glossy-samples"), &n);
    const camera cam = scene_camera(j.s, j.width, j.height);
    const fs::path path = plan.path_for(j.name);
    prepare_output(path, plan.user_named, args.has("force"));  // refuse before spending the time
    render_settings settings;
    settings.max_depth = args.get_int("depth");
    settings.seed = std::uint64_t(args.get_int("seed"));
    settings.progress_label = j.name;
    const render_result r = render(w, cam, settings);
    write_image(path, r.img);
    // Where the rays went: a heat map of log2(rays per pixel) beside the image (rough mirrors light up).
    const fs::path heat_path = heat_path_for(path);
    prepare_output(heat_path, plan.user_named, args.has("force"));
    std::vector<float> log_rays(r.rays_per_pixel.size());
    std::transform(r.rays_per_pixel.begin(), r.rays_per_pixel.end(), log_rays.begin(),
                   [](float n) { return std::log2(std::max(1.0f, n)); });
    write_image(heat_path, heat_map(log_rays, j.width, j.height, "log2 of rays per pixel"));
    const float most = *std::max_element(r.rays_per_pixel.begin(), r.rays_per_pixel.end());
    // The pixels whose primary ray meets a rough mirror: there the S samples per glossy hit are paid, which
    // the average over the whole image dilutes.
    double rough_rays = 0.0;
    std::size_t rough_pixels = 0;
    counting uncounted;
    for (int y = 0; y < j.height; ++y)
        for (int x = 0; x < j.width; ++x) {
            surface sf;
            if (!w.closest_hit(cam.pixel_ray(x, y), sf, uncounted)) continue;
            const std::uint32_t m = w.primitives[sf.h.prim]->material();
            if (m >= j.s.materials.size() || j.s.materials[m].kind != material_kind::rough_mirror) continue;
            rough_rays += r.rays_per_pixel[std::size_t(y) * j.width + x];
            ++rough_pixels;
        }

    const auto pixels = std::uint64_t(j.width) * std::uint64_t(j.height);
    const counter_values c = r.counts.tests.values();
    std::printf("%s: %s triangles, %zu spheres, %zu planes (%zu primitives); %d x %d pixels, depth %d, "
                "%d glossy samples\n",
                j.name.c_str(), grouped(n.triangles).c_str(), n.spheres, n.planes, w.primitives.size(), j.width,
                j.height, settings.max_depth, args.get_int("glossy-samples"));
    std::printf("  rays     primary %s, shadow %s, reflection %s: %s in all, %.2f per pixel (at most %.0f)\n",
                grouped(r.counts.primary).c_str(), grouped(r.counts.shadow).c_str(),
                grouped(r.counts.reflection).c_str(), grouped(r.counts.total()).c_str(),
                double(r.counts.total()) / double(pixels), double(most));
    if (rough_pixels > 0)
        std::printf("  rough    %s pixels (%.1f%%) see a rough mirror first: %.2f rays per pixel there\n",
                    grouped(rough_pixels).c_str(), 100.0 * double(rough_pixels) / double(pixels),
                    rough_rays / double(rough_pixels));
    std::printf("  time     %.2f s, %.2f Mrays/s, %.1f primitive tests per ray\n", r.seconds,
                double(r.counts.total()) / r.seconds * 1e-6, c.per_ray(c.prim_tests));
    std::printf("  wrote    %s, %s\n", path.string().c_str(), heat_path.string().c_str());
}

// The linear cost of brute force: the teapot ever finer, primary rays only, at a small size.
void sweep(const cli& args, bool quick, const output_plan& plan) {
    const std::vector<int> resolutions = quick ? std::vector<int>{1, 2, 4, 8} : std::vector<int>{1, 2, 4, 8, 16};
    const int w = quick ? 64 : 128, h = quick ? 48 : 96;
    const fs::path csv_path = plan.folder / "sweep.csv", svg_path = plan.folder / "sweep.svg";
    prepare_output(csv_path, plan.user_named, args.has("force"));
    prepare_output(svg_path, plan.user_named, args.has("force"));
    std::printf("sweep: the teapot tessellated ever finer, primary rays only, %d x %d pixels, median of >= 3 runs "
                "filling >= 0.25 s\n", w, h);
    std::printf("  %9s  %10s  %9s  %8s  %15s\n", "triangles", "primitives", "seconds", "Mrays/s", "tests per ray");
    struct row { std::size_t triangles; double mrays, tests; };
    std::vector<row> rows;
    std::ofstream csv(csv_path);
    csv << "triangles,primitives,seconds,mrays_per_s,prim_tests_per_ray\n";
    for (const int res : resolutions) {
        const scene s = teapot_scene(res);
        const world wd = build_world(s, args.get_int("glossy-samples"));
        render_settings settings;
        settings.primary_only = true;
        // An untimed warm-up, then the median of at least three runs, and of as many as fill a quarter of a
        // second (at most 200): the smallest meshes take milliseconds, and the machines are shared and noisy.
        const camera cam(s.camera, w, h);
        render_result r = render(wd, cam, settings);
        std::vector<double> seconds;
        for (double spent = 0.0; seconds.size() < 3 || (spent < 0.25 && seconds.size() < 200); spent += r.seconds) {
            r = render(wd, cam, settings);
            seconds.push_back(r.seconds);
        }
        r.seconds = median(seconds);
        const counter_values c = r.counts.tests.values();
        const double mrays = double(r.counts.total()) / r.seconds * 1e-6;
        rows.push_back({s.mesh.triangle_count(), mrays, c.per_ray(c.prim_tests)});
        std::printf("  %9s  %10zu  %9.3f  %8.3f  %15.1f\n", grouped(s.mesh.triangle_count()).c_str(),
                    wd.primitives.size(), r.seconds, mrays, c.per_ray(c.prim_tests));
        csv << s.mesh.triangle_count() << ',' << wd.primitives.size() << ',' << r.seconds << ',' << mrays << ','
            << c.per_ray(c.prim_tests) << '\n';
    }
    // Mrays/s against triangles on log-log axes, beside a dashed line of slope -1 through the first point:
    // what a cost growing exactly linearly with the triangle count would give.
    plot p{"ch01 brute force: primary rays on the teapot", "triangles", "Mrays/s", true, true, {}};
    plot_series measured{"measured", {}, {}, true, {}, 0};
    for (const row& r : rows) {
        char label[32];
        std::snprintf(label, sizeof label, "%.3g", r.mrays);
        measured.x.push_back(double(r.triangles));
        measured.y.push_back(r.mrays);
        measured.point_labels.push_back(label);
    }
    const double t0 = measured.x.front(), t1 = measured.x.back(), m0 = measured.y.front();
    plot_series linear{"linear cost (slope -1)", {t0, t1}, {m0, m0 * t0 / t1}, true, {}, 8};
    linear.dashed = true;
    p.series = {linear, measured};  // the measured line drawn over the reference
    write_svg(svg_path, to_svg(p));
    std::printf("  wrote    %s, %s\n", csv_path.string().c_str(), svg_path.string().c_str());
}

int run(int argc, const char* const* argv) {
    cli args("ch01", "Chapter 01, the first tracer (" + std::string(track_name()) + "): object-oriented brute-force Whitted ray "
             "tracing of the Cornell box and the teapot, with rays by kind, Mrays/s and tests per ray.");
    args.option("scene", "NAME", "all", "cornell, teapot or all")
        .option("mesh", "FILE", "", "render a mesh file of your own instead (OBJ, PLY, ...): brute force, slow")
        .option("width", "N", "", "image width, 1..16384 (default 512 for cornell and teapot, 256 with --quick; "
                                  "16384 x 16384 needs about 10 GB of memory: refused where the machine has less)")
        .option("height", "N", "", "image height, 1..16384 (default: as wide for cornell, 3/4 of it otherwise)")
        .option("teapot-res", "N", "", "teapot patches tessellated N x N: 64 N^2 triangles (default 6, 4 quick)")
        .option("depth", "N", "5", "Whitted recursion limit: reflection rays up to this depth")
        .option("glossy-samples", "S", "16", "reflection rays per rough-mirror hit")
        .option("threads", "N", "0", "worker threads, 0..1024 (0: one per core)")
        .option("seed", "N", "1", "random seed of the rough-mirror samples")
        .option("out", "FILE|DIR", "", "write the image to FILE (and its ray heat map to FILE_rays.png), or the images into DIR/ "
                "(default out/01_first_tracer/)")
        .flag("force", "replace an existing file named with --out")
        .flag("quick", "smaller images for a fast look (./course run)")
        .flag("sweep", "measure brute force against the triangle count instead (writes sweep.csv, sweep.svg)");
    if (!args.parse(argc, argv)) return 0;

    const bool quick = args.has("quick");
    const int depth = args.get_int("depth"), glossy = args.get_int("glossy-samples"), threads = read_threads(args, 0);
    if (depth < 0 || depth > 64) throw usage_error("--depth must lie in [0, 64]");
    if (glossy < 1 || glossy > 4096) throw usage_error("--glossy-samples must lie in [1, 4096]");
    const thread_limit limit(threads);

    const auto size_option = [&](const char* name, int fallback) {
        if (!args.has(name)) return fallback;
        const int v = args.get_int(name);
        if (v < 1 || v > 16384) throw usage_error(std::string("--") + name + " must lie in [1, 16384]");
        return v;
    };
    const int width = size_option("width", quick ? 256 : 512);
    const int teapot_res = args.has("teapot-res") ? args.get_int("teapot-res") : (quick ? 4 : 6);
    if (teapot_res < 1 || teapot_res > 64) throw usage_error("--teapot-res must lie in [1, 64]");

    if (args.has("sweep")) {
        if (args.has("out") && !fs::is_directory(args.get("out")) && args.get("out").back() != '/')
            throw usage_error("--sweep writes sweep.csv and sweep.svg: --out must name a folder (ending in /)");
        sweep(args, quick, plan_output(args, 2));
        return 0;
    }
    std::vector<job> jobs;
    if (args.has("mesh")) {
        if (args.has("scene")) throw usage_error("--mesh and --scene exclude each other");
        const fs::path file = args.get("mesh");
        scene s = load_scene(file, &std::cout);
        std::printf("note: brute force tests all %s triangles for every ray; large meshes take long "
                    "(chapter 04's BVH makes this fast)\n", grouped(s.mesh.triangle_count()).c_str());
        jobs.push_back({file.stem().string(), std::move(s), width, size_option("height", width * 3 / 4)});
    } else {
        const std::string which = args.get("scene");
        if (which != "cornell" && which != "teapot" && which != "all")
            throw usage_error("--scene must be cornell, teapot or all, not '" + which + "'");
        if (which != "teapot") jobs.push_back({"cornell", cornell_box(true), width, size_option("height", width)});
        if (which != "cornell")
            jobs.push_back({"teapot", teapot_scene(teapot_res), width, size_option("height", width * 3 / 4)});
    }
    const output_plan plan = plan_output(args, jobs.size());
    // Before any work: the memory of the largest image (per pixel: its colour, its rays, their log, the
    // heat map, the PNG rows; 40 bytes is ample), and every file this run writes.
    for (const job& j : jobs)
        check_memory(std::uint64_t(j.width) * std::uint64_t(j.height) * 40,
                     "a " + std::to_string(j.width) + " x " + std::to_string(j.height) + " image");
    for (const job& j : jobs) {
        prepare_output(plan.path_for(j.name), plan.user_named, args.has("force"));
        prepare_output(heat_path_for(plan.path_for(j.name)), plan.user_named, args.has("force"));
    }
    for (const job& j : jobs) render_job(j, args, plan);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch01_exercise" : "ch01", run, argc, argv);
}
