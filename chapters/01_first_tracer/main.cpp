// ch01: the first tracer. Renders the Cornell box (with a mirror and a rough-mirror sphere) and the
// teapot with brute-force Whitted ray tracing, and prints what it cost: rays by kind, rays per pixel,
// Mrays/s, primitive tests per ray, also as tables (renders.csv; glossy.csv: the Cornell box's rays at 1 to 32
// glossy samples). --sweep measures how that cost grows with the triangle count.
#include "strahl/ch01/render.hpp"
#include "strahl/machine.hpp"
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

// Where the S samples per glossy hit are paid: the pixels whose primary ray meets a rough mirror first,
// which the average over the whole image dilutes. Scenes without a rough mirror skip the extra pass.
struct rough_share {
    std::size_t pixels = 0;
    double rays = 0.0;  // the rays those pixels cost, in all
};

rough_share rough_pixels_of(const job& j, const world& w, const camera& cam, const std::vector<float>& rays_per_pixel) {
    rough_share out;
    if (std::none_of(j.s.materials.begin(), j.s.materials.end(),
                     [](const material_desc& m) { return m.kind == material_kind::rough_mirror; }))
        return out;
    counting uncounted;
    for (int y = 0; y < j.height; ++y)
        for (int x = 0; x < j.width; ++x) {
            surface sf;
            if (!w.closest_hit(cam.pixel_ray(x, y), sf, uncounted)) continue;
            const std::uint32_t m = w.primitives[sf.h.prim]->material();
            if (m >= j.s.materials.size() || j.s.materials[m].kind != material_kind::rough_mirror) continue;
            out.rays += rays_per_pixel[std::size_t(y) * j.width + x];
            ++out.pixels;
        }
    return out;
}

// One rendered scene, as renders.csv holds it.
struct render_row {
    std::string scene;
    world_counts n;
    std::size_t primitives = 0;
    int width = 0, height = 0, depth = 0, glossy = 0;
    ray_counts rays;
    float most = 0.0f;
    rough_share rough;
    double seconds = 0.0, tests_per_ray = 0.0;
    double pixels() const { return double(width) * double(height); }
    double mrays() const { return double(rays.total()) / seconds * 1e-6; }
};

const char* const renders_header =
    "scene,triangles,spheres,planes,primitives,width,height,depth,glossy_samples,primary_rays,shadow_rays,"
    "reflection_rays,rays,rays_per_pixel,max_rays_per_pixel,rough_pixels,rough_pixels_percent,"
    "rough_rays_per_pixel,seconds,mrays_per_s,prim_tests_per_ray";

void write_render_row(std::ostream& csv, const render_row& r) {
    csv << csv_field(r.scene) << ',' << r.n.triangles << ',' << r.n.spheres << ',' << r.n.planes << ','
        << r.primitives << ',' << r.width << ',' << r.height << ',' << r.depth << ',' << r.glossy << ','
        << r.rays.primary << ',' << r.rays.shadow << ',' << r.rays.reflection << ',' << r.rays.total() << ','
        << double(r.rays.total()) / r.pixels() << ',' << r.most << ',' << r.rough.pixels << ','
        << 100.0 * double(r.rough.pixels) / r.pixels() << ','
        << (r.rough.pixels ? r.rough.rays / double(r.rough.pixels) : 0.0) << ',' << r.seconds << ',' << r.mrays()
        << ',' << r.tests_per_ray << '\n';
}

// Renders one job at S glossy samples; writes nothing.
render_row render_counted(const job& j, const cli& args, int glossy, render_result* result = nullptr) {
    render_row row;
    const world w = build_world(j.s, glossy, &row.n);
    const camera cam = scene_camera(j.s, j.width, j.height);
    render_settings settings;
    settings.max_depth = args.get_int("depth");
    settings.seed = std::uint64_t(args.get_int("seed"));
    if (result) settings.progress_label = j.name;
    render_result r = render(w, cam, settings);
    const counter_values c = r.counts.tests.values();
    row.scene = j.name, row.primitives = w.primitives.size(), row.width = j.width, row.height = j.height;
    row.depth = settings.max_depth, row.glossy = glossy, row.rays = r.counts, row.seconds = r.seconds;
    row.most = *std::max_element(r.rays_per_pixel.begin(), r.rays_per_pixel.end());
    row.tests_per_ray = c.per_ray(c.prim_tests);
    row.rough = rough_pixels_of(j, w, cam, r.rays_per_pixel);
    if (result) *result = std::move(r);
    return row;
}

render_row render_job(const job& j, const cli& args, const output_plan& plan) {
    const fs::path path = plan.path_for(j.name);
    prepare_output(path, plan.user_named, args.has("force"));  // refuse before spending the time
    render_result r;
    const render_row row = render_counted(j, args, args.get_int("glossy-samples"), &r);
    write_image(path, r.img);
    // Where the rays went: a heat map of log2(rays per pixel) beside the image (rough mirrors light up).
    const fs::path heat_path = heat_path_for(path);
    prepare_output(heat_path, plan.user_named, args.has("force"));
    std::vector<float> log_rays(r.rays_per_pixel.size());
    std::transform(r.rays_per_pixel.begin(), r.rays_per_pixel.end(), log_rays.begin(),
                   [](float n) { return std::log2(std::max(1.0f, n)); });
    write_image(heat_path, heat_map(log_rays, j.width, j.height, "log2 of rays per pixel"));

    std::printf("%s: %s triangles, %zu spheres, %zu planes (%zu primitives); %d x %d pixels, depth %d, "
                "%d glossy samples\n",
                j.name.c_str(), grouped(row.n.triangles).c_str(), row.n.spheres, row.n.planes, row.primitives,
                j.width, j.height, row.depth, row.glossy);
    std::printf("  rays     primary %s, shadow %s, reflection %s: %s in all, %.2f per pixel (at most %.0f)\n",
                grouped(row.rays.primary).c_str(), grouped(row.rays.shadow).c_str(),
                grouped(row.rays.reflection).c_str(), grouped(row.rays.total()).c_str(),
                double(row.rays.total()) / row.pixels(), double(row.most));
    if (row.rough.pixels > 0)
        std::printf("  rough    %s pixels (%.1f%%) see a rough mirror first: %.2f rays per pixel there\n",
                    grouped(row.rough.pixels).c_str(), 100.0 * double(row.rough.pixels) / row.pixels(),
                    row.rough.rays / double(row.rough.pixels));
    std::printf("  time     %.2f s, %.2f Mrays/s, %.1f primitive tests per ray\n", row.seconds, row.mrays(),
                row.tests_per_ray);
    std::printf("  wrote    %s, %s\n", path.string().c_str(), heat_path.string().c_str());
    return row;
}

// What the glossy samples cost: the Cornell box at S = 1, 4, 16, 32 reflection rays per rough-mirror hit.
void glossy_table(const job& j, const cli& args, const fs::path& csv_path) {
    std::printf("glossy samples, %s: rays per pixel where a rough mirror is seen first, and over the image\n",
                j.name.c_str());
    std::printf("  %8s  %12s  %14s  %14s  %12s\n", "S", "rays", "per pixel", "at most", "rough, each");
    std::ofstream csv(csv_path);
    csv << "glossy_samples,rays,rays_per_pixel,max_rays_per_pixel,rough_pixels,rough_pixels_percent,"
           "rough_rays_per_pixel\n";
    for (const int s : {1, 4, 16, 32}) {
        const render_row r = render_counted(j, args, s);
        const double rough = r.rough.pixels ? r.rough.rays / double(r.rough.pixels) : 0.0;
        std::printf("  %8d  %12s  %14.2f  %14.0f  %12.2f\n", s, grouped(r.rays.total()).c_str(),
                    double(r.rays.total()) / r.pixels(), double(r.most), rough);
        csv << s << ',' << r.rays.total() << ',' << double(r.rays.total()) / r.pixels() << ',' << r.most << ','
            << r.rough.pixels << ',' << 100.0 * double(r.rough.pixels) / r.pixels() << ',' << rough << '\n';
    }
    std::printf("  wrote    %s\n", csv_path.string().c_str());
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
    csv.close();
    stamp_machine(csv_path, parallel_threads());
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
        .option("teapot-res", "N", "", "teapot patches tessellated N x N: 64 N^2 triangles "
                "(default 8: the course's teapot)")
        .option("depth", "N", "5", "Whitted recursion limit: reflection rays up to this depth")
        .option("glossy-samples", "S", "16", "reflection rays per rough-mirror hit")
        .threads_option("0", "worker threads, 0..1024 (0: one per core)")
        .option("seed", "N", "1", "random seed of the rough-mirror samples")
        .option("out", "FILE|DIR", "", "write the image to FILE (and its ray heat map to FILE_rays.png), or the "
                "images, renders.csv and glossy.csv into DIR/ (default out/01_first_tracer/)")
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
    // The course's teapot (builtin_scene("teapot"): resolution 8, 4,096 triangles), quick or not.
    const int teapot_res = args.has("teapot-res") ? args.get_int("teapot-res") : 8;
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
    // Into a folder the run also writes its figures as tables: renders.csv (a row per scene) and, with the
    // Cornell box, glossy.csv (its rays at S = 1, 4, 16, 32 glossy samples).
    const fs::path renders_csv = plan.folder / "renders.csv", glossy_csv = plan.folder / "glossy.csv";
    if (plan.file.empty()) {
        prepare_output(renders_csv, plan.user_named, args.has("force"));
        if (std::any_of(jobs.begin(), jobs.end(), [](const job& j) { return j.name == "cornell"; }))
            prepare_output(glossy_csv, plan.user_named, args.has("force"));
    }
    std::vector<render_row> rows;
    for (const job& j : jobs) rows.push_back(render_job(j, args, plan));
    if (plan.file.empty()) {  // into a folder: the figures as tables too
        std::ofstream csv(renders_csv);
        csv << renders_header << '\n';
        for (const render_row& r : rows) write_render_row(csv, r);
        csv.close();
        stamp_machine(renders_csv, parallel_threads());
        std::printf("  wrote    %s\n", renders_csv.string().c_str());
        for (const job& j : jobs)
            if (j.name == "cornell") glossy_table(j, args, glossy_csv);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch01_exercise" : "ch01", run, argc, argv);
}
