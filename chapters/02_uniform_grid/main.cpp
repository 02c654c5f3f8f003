// ch02: the uniform grid. Renders the teapot and the teapot in a stadium through the grid (primary rays,
// facing ratio), and prints what the grid is and costs: cells, occupancy, references per triangle, tests per
// ray, Mrays/s over plain triangles and over chapter 01's virtual objects (scenes.csv); box against exact
// insertion (insertion.csv); the same teapot alone and in a stadium; and lambda swept against build time,
// memory and rays/s (lambda_sweep.csv).
#include "strahl/ch02/accel.hpp"
#include "strahl/ch02/measure.hpp"
#include "strahl/display.hpp"
#include "strahl/machine.hpp"
#include "strahl/scene.hpp"
#include "strahl/parallel.hpp"
#include "strahl/plot.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/timer.hpp"
#include <cstdio>
#include <fstream>
#include <memory>

namespace {

using namespace strahl;
using namespace strahl::ch02;
namespace fs = std::filesystem;

struct context {
    fs::path folder = "out/02_uniform_grid";
    bool user_named = false, force = false;
    int width = 512, height = 384, runs = 3;
    fs::path file(const std::string& name) const {
        prepare_output(folder / name, user_named, force);
        return folder / name;
    }
};

struct measured {
    std::unique_ptr<accel> acc;
    double build_ms = 0.0;
    trace_result tr;
    grid_stats occ;
    grid_dims dims;
};

const uniform_grid& grid_of(const accel& a, bool virt) {
    return virt ? dynamic_cast<const grid_accel<ch01::object_set>&>(a).grid()
                : dynamic_cast<const grid_accel<ch01::triangle_set>&>(a).grid();
}

measured measure(const scene& s, bool virt, const grid_options& opt, const std::vector<ray>& rays, int runs,
                 const std::string& label = {}) {
    measured m;
    m.acc = make_accel(virt, opt);
    std::vector<double> ms;
    for (int k = 0; k < std::max(1, runs); ++k) {  // the median build of a few (the machine is shared)
        const timer t;
        m.acc->build(s);
        ms.push_back(t.milliseconds());
    }
    m.build_ms = median(ms);
    m.tr = trace(*m.acc, rays, runs, label);
    const uniform_grid& g = grid_of(*m.acc, virt);
    m.dims = g.dims();
    m.occ = occupancy(g.dims(), g.cells(), s.mesh.triangle_count());
    return m;
}

void print_row(const char* what, const measured& m) {
    const counter_values& c = m.tr.counts;
    std::printf("  %-22s %8.1f %9.2f %10.1f %9.1f %9.2f\n", what, m.build_ms, double(m.acc->memory_bytes()) / 1e6,
                c.per_ray(c.nodes_visited), c.per_ray(c.prim_tests), m.tr.mrays);
}
void print_header() {
    std::printf("  %-22s %8s %9s %10s %9s %9s\n", "", "build ms", "memory MB", "cells/ray", "tests/ray", "Mrays/s");
}

void print_grid(const measured& m) {
    const grid_stats& o = m.occ;
    std::printf("  grid     %d x %d x %d = %zu cells, %.1f%% empty; triangles per cell: mean %.2f (%.2f over "
                "non-empty cells), max %zu; %.2f references per triangle\n",
                m.dims.res.x, m.dims.res.y, m.dims.res.z, o.cells, 100.0 * double(o.empty_cells) / double(o.cells),
                o.mean_per_cell, o.mean_per_nonempty, o.max_per_cell, o.references_per_prim);
}

// scenes.csv: a row per scene and primitive kind, the grid and what a primary ray costs in it.
const char* const scenes_header =
    "scene,primitives,triangles,width,height,lambda,nx,ny,nz,cells,empty_percent,mean_per_cell,"
    "mean_per_nonempty_cell,max_per_cell,refs_per_triangle,build_ms,memory_bytes,memory_mb,cells_per_ray,"
    "tests_per_ray,mrays_per_s";

void scene_row(std::ostream& csv, const std::string& name, const char* kind, const scene& s, const camera& cam,
               const grid_options& opt, const measured& m) {
    const grid_stats& o = m.occ;
    const counter_values& c = m.tr.counts;
    csv << name << ',' << kind << ',' << s.mesh.triangle_count() << ',' << cam.width() << ',' << cam.height() << ','
        << opt.lambda << ',' << m.dims.res.x << ',' << m.dims.res.y << ',' << m.dims.res.z << ',' << o.cells << ','
        << 100.0 * double(o.empty_cells) / double(o.cells) << ',' << o.mean_per_cell << ',' << o.mean_per_nonempty
        << ',' << o.max_per_cell << ',' << o.references_per_prim << ',' << m.build_ms << ','
        << m.acc->memory_bytes() << ',' << double(m.acc->memory_bytes()) / 1e6 << ',' << c.per_ray(c.nodes_visited)
        << ',' << c.per_ray(c.prim_tests) << ',' << m.tr.mrays << '\n';
}

void render_scene(const context& ctx, const scene& s, const std::string& name, const grid_options& opt,
                  grid_stats* occ_out, std::ostream& csv, int shrink = 1) {
    const camera cam(s.camera, ctx.width / shrink, ctx.height / shrink);
    const std::vector<ray> rays = primary_rays(cam);
    std::printf("%s: %zu triangles, %d x %d primary rays, lambda %g\n", name.c_str(), s.mesh.triangle_count(),
                cam.width(), cam.height(), double(opt.lambda));
    const measured tri = measure(s, false, opt, rays, ctx.runs, name);
    print_grid(tri);
    print_header();
    print_row("triangles", tri);
    const measured obj = measure(s, true, opt, rays, ctx.runs, name + " (virtual)");
    print_row("virtual objects", obj);
    scene_row(csv, name, "triangles", s, cam, opt, tri);
    scene_row(csv, name, "virtual objects", s, cam, opt, obj);
    const fs::path img = ctx.file(name + ".png"), heat = ctx.file(name + "_tests.png");
    write_image(img, facing_image(s.mesh, cam, rays, tri.tr.hits));
    write_image(heat, heat_map(tests_per_pixel(*tri.acc, rays), cam.width(), cam.height(), "triangle tests per ray"));
    std::printf("  wrote    %s, %s\n", img.string().c_str(), heat.string().c_str());
    *occ_out = tri.occ;
}

// The stadium seen from outside, large, with its grid drawn: the cell lattice on the floor of the grid's
// box, the box's edges, and in red the cells that hold at least `crowd` triangles, all of them the teapot's,
// in the middle of a bowl of mostly empty cells.
void stadium_from_outside(const context& ctx, const scene& s, const grid_options& opt, std::size_t crowd) {
    const auto acc = make_accel(false, opt);
    acc->build(s);
    const uniform_grid& g = grid_of(*acc, false);
    const grid_dims& d = g.dims();
    camera_desc view = frame_camera(s.mesh.bounds(), 30.0f);
    const vec3 centre = s.mesh.bounds().centroid(), back = view.eye - centre;
    view.eye = centre + glm::length(back) * glm::normalize(vec3(0.45f, 1.0f, 0.8f));  // above and beside
    const camera cam(view, ctx.width * 3 / 2, ctx.height * 3 / 2);  // larger: 68 cells across must show
    const std::vector<ray> rays = primary_rays(cam);
    const trace_result tr = trace(*acc, rays, 1);
    image img = facing_image(s.mesh, cam, rays, tr.hits);
    std::vector<line_segment> lines;
    const color lattice{0.15f, 0.35f, 0.85f}, red{1.0f, 0.15f, 0.1f};
    for (int x = 0; x <= d.res.x; ++x) {
        const float px = d.box.min.x + float(x) * d.cell_size.x;
        lines.push_back({vec3(px, d.box.min.y, d.box.min.z), vec3(px, d.box.min.y, d.box.max.z), lattice});
    }
    for (int z = 0; z <= d.res.z; ++z) {
        const float pz = d.box.min.z + float(z) * d.cell_size.z;
        lines.push_back({vec3(d.box.min.x, d.box.min.y, pz), vec3(d.box.max.x, d.box.min.y, pz), lattice});
    }
    const auto frame = box_wireframe(d.box, color{1.0f, 1.0f, 1.0f});
    lines.insert(lines.end(), frame.begin(), frame.end());
    std::size_t crowded = 0;
    for (int z = 0; z < d.res.z; ++z)
        for (int y = 0; y < d.res.y; ++y)
            for (int x = 0; x < d.res.x; ++x) {
                const int c = d.index(ivec3(x, y, z));
                if (g.cells().offsets[std::size_t(c) + 1] - g.cells().offsets[std::size_t(c)] < crowd) continue;
                ++crowded;
                const auto e = box_wireframe(d.cell_box(ivec3(x, y, z)), red);
                lines.insert(lines.end(), e.begin(), e.end());
            }
    draw_lines(img, cam, lines, 1.0f);
    const fs::path file = ctx.file("stadium_grid.png");
    write_image(file, img);
    std::printf("  the grid from outside: %d x %d x %d cells; %zu of them (red) hold %zu or more triangles\n"
                "  wrote    %s\n", d.res.x, d.res.y, d.res.z, crowded, crowd, file.string().c_str());
}

// Box against exact insertion: a triangle's box overlaps more cells than the triangle does.
void box_vs_exact(const context& ctx, const scene& s) {
    const std::vector<ray> rays = primary_rays(camera(s.camera, ctx.width, ctx.height));
    grid_options exact;
    exact.exact_overlap = true;
    const measured b = measure(s, false, {}, rays, ctx.runs), e = measure(s, false, exact, rays, ctx.runs);
    std::printf("insertion, %s (%zu triangles): by box against by triangle/box overlap (Akenine-Moeller)\n",
                s.name.c_str(), s.mesh.triangle_count());
    std::printf("  %-22s %8s %9s %10s %9s %9s %12s %8s\n", "", "build ms", "memory MB", "cells/ray", "tests/ray",
                "Mrays/s", "refs/tri", "empty %");
    const fs::path csv_path = ctx.file("insertion.csv");
    std::ofstream csv(csv_path);
    csv << "insertion,triangles,cells,build_ms,memory_bytes,memory_mb,cells_per_ray,tests_per_ray,mrays_per_s,"
           "refs_per_triangle,empty_percent\n";
    for (const auto* m : {&b, &e}) {
        const counter_values& c = m->tr.counts;
        csv << (m == &b ? "box" : "exact") << ',' << s.mesh.triangle_count() << ',' << m->occ.cells << ','
            << m->build_ms << ',' << m->acc->memory_bytes() << ',' << double(m->acc->memory_bytes()) / 1e6 << ','
            << c.per_ray(c.nodes_visited) << ',' << c.per_ray(c.prim_tests) << ',' << m->tr.mrays << ','
            << m->occ.references_per_prim << ',' << 100.0 * double(m->occ.empty_cells) / double(m->occ.cells)
            << '\n';
        std::printf("  %-22s %8.1f %9.2f %10.1f %9.1f %9.2f %12.2f %8.1f\n", m == &b ? "box" : "exact",
                    m->build_ms, double(m->acc->memory_bytes()) / 1e6, c.per_ray(c.nodes_visited),
                    c.per_ray(c.prim_tests), m->tr.mrays, m->occ.references_per_prim,
                    100.0 * double(m->occ.empty_cells) / double(m->occ.cells));
    }
    csv.close();
    stamp_machine(csv_path, parallel_threads());
    std::printf("  wrote    %s\n", csv_path.string().c_str());
}

void lambda_sweep(const context& ctx, const scene& s, bool quick) {
    const std::vector<float> lambdas = quick ? std::vector<float>{0.5f, 2, 8} : std::vector<float>{0.5f, 1, 2, 4, 8, 16};
    const std::vector<ray> rays = primary_rays(camera(s.camera, ctx.width, ctx.height));
    std::printf("lambda sweep, %s (%zu triangles), triangles:\n", s.name.c_str(), s.mesh.triangle_count());
    std::printf("  %-22s %8s %9s %10s %9s %9s %9s\n", "lambda", "build ms", "memory MB", "cells/ray", "tests/ray",
                "Mrays/s", "cells");
    const fs::path csv_path = ctx.file("lambda_sweep.csv"), svg_path = ctx.file("lambda_sweep.svg");
    std::ofstream csv(csv_path);
    csv << "lambda,cells,build_ms,memory_bytes,cells_per_ray,tests_per_ray,mrays_per_s\n";
    plot p{"ch02: lambda (cells per triangle) on " + s.name, "lambda", "", true, true, {}};
    plot_series speed, build, mem, tests;
    speed.label = "Mrays/s", build.label = "build ms", mem.label = "memory MB", tests.label = "tests/ray";
    for (const float l : lambdas) {
        grid_options opt;
        opt.lambda = l;
        const measured m = measure(s, false, opt, rays, ctx.runs);
        const counter_values& c = m.tr.counts;
        std::printf("  %-22g %8.1f %9.2f %10.1f %9.1f %9.2f %9zu\n", double(l), m.build_ms,
                    double(m.acc->memory_bytes()) / 1e6, c.per_ray(c.nodes_visited), c.per_ray(c.prim_tests),
                    m.tr.mrays, m.occ.cells);
        csv << l << ',' << m.occ.cells << ',' << m.build_ms << ',' << m.acc->memory_bytes() << ','
            << c.per_ray(c.nodes_visited) << ',' << c.per_ray(c.prim_tests) << ',' << m.tr.mrays << '\n';
        for (auto* ser : {&speed, &build, &mem, &tests}) ser->x.push_back(l);
        speed.y.push_back(m.tr.mrays), build.y.push_back(m.build_ms);
        mem.y.push_back(double(m.acc->memory_bytes()) / 1e6), tests.y.push_back(c.per_ray(c.prim_tests));
    }
    p.series = {speed, build, mem, tests};
    write_svg(svg_path, to_svg(p));
    csv.close();
    stamp_machine(csv_path, parallel_threads());
    std::printf("  wrote    %s, %s\n", csv_path.string().c_str(), svg_path.string().c_str());
}

int run(int argc, const char* const* argv) {
    cli args("ch02", "Chapter 02, the uniform grid (" + std::string(track_name()) + "): 3D-DDA traversal with mailboxing; occupancy, "
             "tests per ray and Mrays/s on the teapot and the teapot in a stadium; box against exact insertion; "
             "lambda swept.");
    args.option("teapot-res", "N", "", "teapot patches tessellated N x N: 64 N^2 triangles, alone and in the "
                "stadium (default 8: the course's teapot and teapot_stadium)")
        .option("lambda", "L", "4", "cells per triangle")
        .option("width", "N", "", "image width, 8..8192 (default 512, 256 with --quick); height 3/4 of it")
        .threads_option("0", "worker threads, 0..1024 (0: one per core)")
        .output_options("write images, CSV and SVG into DIR/ (default out/02_uniform_grid/)")
        .flag("quick", "smaller images and fewer runs, a few seconds (./course run)");
    if (!args.parse(argc, argv)) return 0;
    const bool quick = args.has("quick");
    context ctx;
    if (args.has("out")) ctx.folder = args.get("out"), ctx.user_named = true;
    ctx.force = args.has("force");
    ctx.width = args.has("width") ? args.get_int("width") : (quick ? 256 : 512);
    if (ctx.width < 8 || ctx.width > 8192) throw usage_error("--width must lie in [8, 8192]");
    ctx.height = ctx.width * 3 / 4;
    ctx.runs = quick ? 1 : 3;
    const int res = args.has("teapot-res") ? args.get_int("teapot-res") : 8;
    if (res < 1 || res > 64) throw usage_error("--teapot-res must lie in [1, 64]");
    grid_options opt;
    opt.lambda = float(args.get_double("lambda"));
    if (!(opt.lambda > 0.0f && opt.lambda <= 1000.0f)) throw usage_error("--lambda must lie in (0, 1000]");
    const thread_limit limit(read_threads(args, 0));
    // Per pixel: the primary rays and their hits, tests per ray, the images and heat maps: 120 bytes is ample.
    check_memory(std::uint64_t(ctx.width) * std::uint64_t(ctx.height) * 120,
                 "a " + std::to_string(ctx.width) + " x " + std::to_string(ctx.height) + " image");

    // Refuse before spending the time: every file this run writes.
    for (const char* f : {"teapot.png", "teapot_tests.png", "stadium.png", "stadium_tests.png", "stadium_grid.png", "scenes.csv",
                          "histogram.svg", "histogram.csv", "insertion.csv", "lambda_sweep.csv", "lambda_sweep.svg"})
        ctx.file(f);
    // The same teapot, alone and in a stadium: by default the course's builtin scenes teapot (4,096 triangles)
    // and teapot_stadium (those 4,096 and 3,136 of the stadium).
    const scene teapot = args.has("teapot-res") ? teapot_scene(res) : builtin_scene("teapot");
    const scene stadium = args.has("teapot-res") ? teapot_in_stadium(res) : builtin_scene("teapot_stadium");
    grid_stats occ_teapot, occ_stadium;
    const fs::path scenes_csv = ctx.file("scenes.csv");
    std::ofstream scenes(scenes_csv);
    scenes << scenes_header << '\n';
    render_scene(ctx, teapot, "teapot", opt, &occ_teapot, scenes);
    std::printf("the same teapot in a stadium: %zu triangles, the teapot's %zu and the stadium's %zu\n",
                stadium.mesh.triangle_count(), teapot.mesh.triangle_count(),
                stadium.mesh.triangle_count() - teapot.mesh.triangle_count());
    // A quarter of the width: in the stadium a ray costs thousands of tests, and the default run stays short.
    render_scene(ctx, stadium, "stadium", opt, &occ_stadium, scenes, 4);
    stadium_from_outside(ctx, stadium, opt, 256);
    scenes.close();
    stamp_machine(scenes_csv, parallel_threads());
    std::printf("  wrote    %s\n", scenes_csv.string().c_str());

    // What a ray meets: the share of the triangle references that sit in cells holding k triangles, k in
    // log2 bins (1, 2-3, 4-7, ...). A share of the cells would hide the stadium's crowd: its cells are
    // mostly empty, while most of its references lie in a few cells of thousands.
    std::size_t bins = 1;
    for (const grid_stats* o : {&occ_teapot, &occ_stadium})
        for (std::size_t b = 0; b < o->refs_by_log2.size(); ++b)
            if (o->refs_by_log2[b]) bins = std::max(bins, b + 1);
    bar_chart h{"ch02: where the references lie: cells holding k triangles (lambda " + args.get("lambda") + ")",
                "% of the triangle references", {}, {"teapot", "teapot in a stadium"}, {{}, {}}, false};
    const fs::path hist_csv = ctx.file("histogram.csv");
    std::ofstream csv(hist_csv);
    csv << "triangles_per_cell_from,triangles_per_cell_to,teapot_refs_percent,stadium_refs_percent\n";
    for (std::size_t b = 0; b < bins; ++b) {
        const std::size_t lo = std::size_t(1) << b, hi = (std::size_t(2) << b) - 1;
        h.categories.push_back(lo == hi ? std::to_string(lo) : std::to_string(lo) + "-" + std::to_string(hi));
        const double t = 100.0 * double(occ_teapot.refs_by_log2[b]) / double(std::max<std::size_t>(1, occ_teapot.references));
        const double st = 100.0 * double(occ_stadium.refs_by_log2[b]) / double(std::max<std::size_t>(1, occ_stadium.references));
        h.values[0].push_back(t);
        h.values[1].push_back(st);
        csv << lo << ',' << hi << ',' << t << ',' << st << '\n';
    }
    const fs::path hist = ctx.file("histogram.svg");
    write_svg(hist, to_svg(h));
    std::printf("  wrote    %s, %s\n", hist.string().c_str(), hist_csv.string().c_str());
    box_vs_exact(ctx, teapot);
    lambda_sweep(ctx, teapot, quick);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch02_exercise" : "ch02", run, argc, argv);
}
