// ch10: two-level BVHs. An animation (a field of bunnies that bob and turn, an armadillo that twists; the
// teapot and a sphere with --quick or without the shared meshes) updated every frame five ways: the
// two-level BVH with the twisting mesh's tree refit, partially rebuilt or rebuilt (the top level rebuilt
// each time), the flattened scene rebuilt whole with chapter 05's binned SAH, and the flattened scene's k-d
// tree rebuilt whole (chapter 03: a k-d tree cannot be refit). Per frame and method: update ms, trace ms of
// the frame's primary rays, the twisting mesh's SAH cost; every two-level method's hits checked against the
// rebuilt one's. Then a scene of many instances (10 million triangles and more), built and traced
// instanced, its memory against its flattened copy's.
#include "strahl/diagram.hpp"
#include "strahl/machine.hpp"
#include "strahl/parallel.hpp"
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch03/accel.hpp"
#include "strahl/ch05/accel.hpp"
#include "strahl/ch10/accel.hpp"
#include "strahl/ch10/animation.hpp"
#include "strahl/image.hpp"
#include "strahl/plot.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/progress.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

namespace strahl::ch10 {
// The chapter's figure (src/diagrams.cpp): three instances and a ray moved into one, by the chapter's own code.
std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force);
}  // namespace strahl::ch10

namespace {

using namespace strahl;
namespace fs = std::filesystem;

struct options {
    int width = 256, height = 192, frames = 24, big = 150;
    bool kd = true;
};

// The frame's primary rays through the structure: ms and hits.
std::pair<double, std::vector<hit>> trace(const accel& a, const std::vector<ray>& rays) {
    std::vector<hit> hits(rays.size());
    timer t;
    a.intersect(rays, hits);
    return {t.milliseconds(), std::move(hits)};
}

// Chapter 01's primary rays through a camera of our own (the scene holds nothing else).
std::vector<ray> camera_rays(const camera_desc& desc, int w, int h) {
    scene view;
    view.camera = desc;
    return ch01::primary_rays(view, w, h);
}

// Primary hits shaded by how squarely they face the ray (the flattened mesh names every triangle).
image shade(const triangle_mesh& flat, const std::vector<ray>& rays, const std::vector<hit>& hits, int w, int h) {
    image img(w, h, color(0.08f, 0.09f, 0.12f));
    for (std::size_t i = 0; i < hits.size(); ++i) {
        if (!hits[i].found()) continue;
        const auto t = flat.triangle(hits[i].prim);
        const vec3 n = glm::normalize(glm::cross(t[1] - t[0], t[2] - t[0]));
        const float c = std::abs(glm::dot(n, glm::normalize(rays[i].dir)));
        const float tint = float(hits[i].inst % 7) / 7.0f;
        img.pixels[i] = (0.15f + 0.85f * c) * color(0.75f + 0.2f * tint, 0.7f, 0.85f - 0.3f * tint);
    }
    return img;
}

struct frame_row {
    int frame;
    std::string method;
    double update_ms, trace_ms, sah;
    std::size_t differing;
};

void run_animation(const ch10::animation& anim, const options& o, const fs::path& folder, std::ostream& csv,
                   std::vector<frame_row>& rows) {
    const std::vector<ray> rays = camera_rays(anim.camera, o.width, o.height);
    const std::uint64_t triangles = anim.start.triangle_count();
    std::printf("animation: %s triangles in %zu instances of %zu meshes, %d frames, %d x %d primary rays per frame\n",
                std::to_string(triangles).c_str(), anim.start.instances.size(), anim.start.meshes.size(), anim.frames,
                o.width, o.height);
    const ch10::mesh_update methods[] = {ch10::mesh_update::refit, ch10::mesh_update::partial, ch10::mesh_update::rebuild};
    std::vector<std::unique_ptr<ch10::two_level_accel_base>> two(3);
    scene start;
    start.instances = std::make_shared<const instanced_meshes>(anim.start);
    for (auto& a : two) a = ch10::make_accel(), a->build(start);
    std::vector<image> frames;
    progress_bar progress("frames", std::size_t(anim.frames), "frames");
    for (int f = 0; f < anim.frames; ++f) {
        const std::vector<affine> moved = anim.transforms(f);
        const std::vector<vec3> twisted = anim.vertices(f);
        std::vector<hit> reference;
        std::vector<std::pair<std::string, std::pair<double, std::pair<double, std::size_t>>>> results;
        // The three two-level methods; the rebuilt one (last) is the reference for the other two.
        std::vector<std::vector<hit>> two_hits(3);
        for (int m = 0; m < 3; ++m) {
            ch10::two_level& s = two[m]->structure();
            timer t;
            s.set_vertices(anim.deforming, twisted, methods[m], {}, false);
            s.set_transforms(moved);
            const double update = t.milliseconds();
            auto [trace_ms, hits] = trace(*two[m], rays);
            rows.push_back({f, std::string("two-level ") + ch10::to_string(methods[m]), update, trace_ms,
                            s.mesh_cost(anim.deforming), 0});
            two_hits[m] = std::move(hits);
        }
        for (int m = 0; m < 3; ++m) rows[rows.size() - 3 + m].differing = hits_differing(two_hits[m], two_hits[2]);
        // The flattened scene, rebuilt whole: the vertices moved, chapter 05's binned SAH over all of them.
        const instanced_meshes now = anim.at(f);
        scene flat;
        {
            timer t;
            flat.mesh = now.flatten();
            auto a = ch05::make_accel(false, ch05::sah_build_params{}, ch05::walk_kind::fast);
            a->build(flat);
            const double update = t.milliseconds();
            const double trace_ms = trace(*a, rays).first;
            rows.push_back({f, "flattened binned SAH", update, trace_ms, ch05::tree_cost(a->tree()), 0});
        }
        frames.push_back(shade(flat.mesh, rays, two_hits[2], o.width, o.height));
        char name[32];
        std::snprintf(name, sizeof name, "frame_%03d.png", f);
        write_image(folder / "frames" / name, frames.back());
        progress.add();
    }
    progress.finish();
    // The k-d tree, rebuilt whole every frame, in a pass of its own: its builds allocate gigabytes, and the
    // page faults of memory handed back and taken again would slow whatever ran after them.
    if (o.kd) {
        progress_bar kd_progress("k-d tree", std::size_t(anim.frames), "frames");
        for (int f = 0; f < anim.frames; ++f) {
            scene flat;
            flat.mesh = anim.at(f).flatten();
            timer t;
            auto kd = ch03::make_accel(false);
            kd->build(flat);
            const double update = t.milliseconds();
            rows.push_back({f, "flattened k-d tree", update, trace(*kd, rays).first, 0.0, 0});
            kd_progress.add();
        }
        kd_progress.finish();
        std::stable_sort(rows.begin(), rows.end(), [](const frame_row& a, const frame_row& b) { return a.frame < b.frame; });
    }
    for (const frame_row& r : rows)
        csv << r.frame << ',' << r.method << ',' << r.update_ms << ',' << r.trace_ms << ','
            << double(rays.size()) / (r.trace_ms * 1e3) << ',' << r.sah << ',' << r.differing << '\n';
    if (write_animation(folder / "animation.gif", frames, 8))
        std::printf("wrote %s\n", (folder / "animation.gif").string().c_str());
}

// Per method: update ms and trace ms against the frame; the twisting mesh's SAH cost against the frame.
void plot_animation(const std::vector<frame_row>& rows, const fs::path& folder) {
    std::map<std::string, plot_series> update, tracing, cost;
    std::vector<std::string> order;
    for (const frame_row& r : rows) {
        if (!update.count(r.method)) order.push_back(r.method);
        for (auto* m : {&update, &tracing, &cost}) (*m)[r.method].label = r.method;
        update[r.method].x.push_back(r.frame), update[r.method].y.push_back(r.update_ms);
        tracing[r.method].x.push_back(r.frame), tracing[r.method].y.push_back(r.trace_ms);
        if (r.sah > 0 && r.method.rfind("two-level", 0) == 0)
            cost[r.method].x.push_back(r.frame), cost[r.method].y.push_back(r.sah);
    }
    plot u{"Update per frame", "frame", "update (ms)", false, true, {}};
    plot t{"Tracing the frame's primary rays (one thread)", "frame", "trace (ms)", false, false, {}};
    plot c{"SAH cost of the twisting mesh's tree", "frame", "SAH cost", false, false, {}};
    c.y_from_zero = false;
    for (std::size_t k = 0; k < order.size(); ++k) {
        for (auto* m : {&update, &tracing, &cost}) (*m)[order[k]].color = int(k);
        u.series.push_back(update[order[k]]);
        t.series.push_back(tracing[order[k]]);
        if (!cost[order[k]].x.empty()) c.series.push_back(cost[order[k]]);
    }
    write_svg(folder / "update_vs_trace.svg", to_svg(std::vector<plot>{u, t}, 2, 560, 400));
    write_svg(folder / "sah_drift.svg", to_svg(c));
}

// Per method, over the frames: the median update and trace times, and the update's speed-up over
// rebuilding the flattened scene with the binned SAH (median over median).
std::string summary(const std::vector<frame_row>& rows) {
    std::map<std::string, std::vector<double>> update, tracing;
    std::vector<std::string> order;
    for (const frame_row& r : rows) {
        if (!update.count(r.method)) order.push_back(r.method);
        update[r.method].push_back(r.update_ms), tracing[r.method].push_back(r.trace_ms);
    }
    const auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
    };
    const double flat = update.count("flattened binned SAH") ? median(update["flattened binned SAH"]) : 0.0;
    std::ostringstream csv;
    csv << "method,frames,update_ms,trace_ms,update_speedup_vs_flattened\n";
    for (const std::string& m : order)
        csv << m << ',' << update[m].size() << ',' << median(update[m]) << ',' << median(tracing[m]) << ','
            << (flat > 0 ? flat / median(update[m]) : 0.0) << '\n';
    return csv.str();
}

// When a rebuild pays off: per frame, the rebuild's extra update time against the refit tree's extra trace
// time per ray; their ratio is the number of rays per frame above which rebuilding wins.
std::string break_even(const std::vector<frame_row>& rows, std::size_t rays_per_frame) {
    std::map<int, const frame_row*> refit, rebuild;
    for (const frame_row& r : rows) {
        if (r.method == "two-level refit") refit[r.frame] = &r;
        if (r.method == "two-level rebuild") rebuild[r.frame] = &r;
    }
    std::ostringstream csv;
    csv << "frame,refit_sah,rebuild_sah,sah_ratio,extra_update_ms,refit_trace_ms,rebuild_trace_ms,break_even_mrays\n";
    int first = -1;
    for (const auto& [f, refit_row] : refit) {
        const frame_row& a = *refit_row;
        const frame_row& b = *rebuild.at(f);
        const double extra = b.update_ms - a.update_ms, saved_per_ray = (a.trace_ms - b.trace_ms) / double(rays_per_frame);
        const double mrays = saved_per_ray > 0 ? extra / saved_per_ray / 1e6 : std::numeric_limits<double>::infinity();
        if (first < 0 && f > 0 && mrays * 1e6 <= double(rays_per_frame)) first = f;
        csv << f << ',' << a.sah << ',' << b.sah << ',' << a.sah / b.sah << ',' << extra << ',' << a.trace_ms << ','
            << b.trace_ms << ',' << mrays << '\n';
    }
    if (first >= 0)
        std::printf("a rebuild of the twisting mesh pays off at %zu rays per frame from frame %d on\n", rays_per_frame, first);
    else
        std::printf("at %zu rays per frame, refitting stays cheaper than rebuilding through the last frame "
                    "(breakeven.csv: how many rays a frame would need)\n", rays_per_frame);
    return csv.str();
}

// A field of many instances of one mesh: built and traced instanced; memory against the flattened copy's.
void big_scene(const triangle_mesh& mesh, const std::string& name, const options& o, std::ostream& csv) {
    int side = 1;
    while (side * side < o.big) ++side;
    instanced_meshes field = make_field(mesh, name, side, (o.big + side - 1) / side, 1.3f);
    field.instances.resize(std::size_t(o.big));
    const std::uint64_t triangles = field.triangle_count();
    scene s;
    s.instances = std::make_shared<const instanced_meshes>(field);
    auto a = ch10::make_accel();
    timer t;
    a->build(s);
    const double build_ms = t.milliseconds();
    const aabb box = field.bounds();
    const vec3 mid = box.centroid();
    const float d = glm::length(box.extent());
    camera_desc cam;
    cam.eye = mid + vec3(0.0f, 0.35f * d, 0.6f * d), cam.target = mid, cam.vfov_degrees = 40.0f;
    const std::vector<ray> rays = camera_rays(cam, o.width, o.height);
    const auto [ms, hits] = trace(*a, rays);
    std::size_t found = 0;
    for (const hit& h : hits) found += h.found();
    // The flattened copy: its vertices and indices (what flatten() would hold), and chapter 05's tree over
    // it at the bytes per triangle the tree of one copy takes.
    auto one = ch05::make_accel(false, ch05::sah_build_params{}, ch05::walk_kind::fast);
    scene single;
    single.mesh = mesh;
    one->build(single);
    const double tree_per_triangle = double(one->memory_bytes()) / double(mesh.triangle_count());
    const double flat_bytes = double(field.flattened_bytes()) + tree_per_triangle * double(triangles);
    const double inst_bytes = double(field.memory_bytes() + a->memory_bytes());
    std::printf("instanced field: %s triangles (%d instances of %s), built in %.1f ms, %.2f Mrays/s primary "
                "(%zu of %zu rays hit); memory %.1f MB instanced, %.1f MB flattened (%.0fx)\n",
                std::to_string(triangles).c_str(), o.big, name.c_str(), build_ms, double(rays.size()) / (ms * 1e3),
                found, rays.size(), inst_bytes / 1e6, flat_bytes / 1e6, flat_bytes / inst_bytes);
    csv << name << ',' << o.big << ',' << triangles << ',' << build_ms << ',' << double(rays.size()) / (ms * 1e3) << ','
        << found << ',' << rays.size() << ',' << inst_bytes / 1e6 << ',' << flat_bytes / 1e6 << ','
        << flat_bytes / inst_bytes << '\n';
}

// --replot: animation.csv's rows, as run_animation wrote them.
std::vector<frame_row> read_rows(const fs::path& file) {
    std::vector<frame_row> rows;
    for (const csv_row& r : read_csv(file, "frame,method,update_ms,trace_ms,mrays_s,sah_cost,differing", machine_header, "an animation.csv written by ch10"))
        rows.push_back({int(csv_number(file, r, 0)), r.cells[1], csv_number(file, r, 2), csv_number(file, r, 3),
                        csv_number(file, r, 5), std::size_t(csv_number(file, r, 6))});
    return rows;
}

int run(int argc, const char* const* argv) {
    cli args("ch10", "Chapter 10, two-level BVHs (" + std::string(track_name()) + "): an animation updated per frame "
             "by refit, partial rebuild and rebuild of a two-level BVH, against rebuilding the flattened scene (binned "
             "SAH, k-d tree); frames as PNG and an animated GIF, animation.csv and plots; then a field of many "
             "instances built and traced instanced (big.csv).");
    args.option("frames", "N", "", "frames of the animation, 2..240 (default 24, 3 with --quick)")
        .option("width", "N", "", "primary rays per row, 1..2048 (default 256, 48 with --quick)")
        .option("height", "N", "", "rows, 1..2048 (default 3/4 of the width)")
        .option("instances", "N", "", "instances in the big field, 1..1048576 (default 150 bunnies: 10.4 million "
                "triangles; 16 with --quick)")
        .output_options("write animation.csv, breakeven.csv, summary.csv, big.csv, update_vs_trace.svg, sah_drift.svg, frames/ and "
                "animation.gif into DIR/ (default out/10_two_level/)")
        .option("replot", "CSV", "", "only redraw update_vs_trace.svg and sah_drift.svg and rewrite summary.csv from an "
                "animation.csv written earlier (no building, no tracing)")
        .flag("no-kd", "leave out the k-d tree (its build is the slowest by far)")
        .flag("quick", "teapots and a sphere, 3 frames, 48 x 36 rays, 16 instances in the big field")
        .option("diagrams", "DIR", "", "only draw the chapter's figure into DIR/ (instances.svg; --force to replace it)");
    if (!args.parse(argc, argv)) return 0;
    if (draw_diagrams_if_asked(args, strahl::ch10::write_diagrams)) return 0;
    fs::path folder = "out/10_two_level";
    const bool user_named = args.has("out"), force = args.has("force");
    if (user_named) folder = args.get("out");
    if (args.has("replot")) {
        const std::vector<frame_row> rows = read_rows(args.get("replot"));  // read first: a bad file leaves nothing
        for (const char* f : {"update_vs_trace.svg", "sah_drift.svg", "summary.csv"})
            prepare_output(folder / f, user_named, force);
        plot_animation(rows, folder);
        write_text(folder / "summary.csv", summary(rows));
        std::printf("wrote %s, %s, %s from %s\n", (folder / "update_vs_trace.svg").string().c_str(),
                    (folder / "sah_drift.svg").string().c_str(), (folder / "summary.csv").string().c_str(),
                    args.get("replot").c_str());
        return 0;
    }
    const bool quick = args.has("quick");
    options o;
    const image_size size = read_image_size(args, quick ? 48 : 256, 2048, 400);
    o.width = size.width, o.height = size.height;
    o.frames = args.has("frames") ? args.get_int("frames") : quick ? 3 : 24;
    if (o.frames < 2 || o.frames > 240) throw usage_error("--frames must lie in [2, 240]");
    o.big = args.has("instances") ? args.get_int("instances") : quick ? 16 : 150;
    if (o.big < 1 || o.big > int(max_instances)) throw usage_error("--instances must lie in [1, 1048576]");
    o.kd = !args.has("no-kd");
    for (const char* f : {"animation.csv", "breakeven.csv", "summary.csv", "big.csv", "update_vs_trace.svg",
                          "sah_drift.svg", "animation.gif"})
        prepare_output(folder / f, user_named, force);
    for (int f = 0; f < o.frames; ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%03d.png", f);
        prepare_output(folder / "frames" / name, user_named, force);
    }

    // The meshes: the bunny and the armadillo where the shared scenes are, else the teapot and a sphere.
    std::optional<scene> bunny, armadillo;
    if (!quick) bunny = load_shared_mesh("bunny.ply", "bunny"), armadillo = load_shared_mesh("armadillo.obj", "armadillo");
    const bool shared = bunny && armadillo;
    const triangle_mesh rigid = shared ? bunny->mesh : teapot_mesh(quick ? 4 : 12);
    const std::string rigid_name = shared ? "bunny" : "teapot";
    const ch10::animation anim = ch10::make_animation(rigid, rigid_name, 4, 4, shared ? armadillo->mesh : tessellated_sphere(48, 96),
                                                shared ? "armadillo" : "sphere", o.frames);

    std::ostringstream csv, big;
    std::vector<frame_row> rows;
    csv << "frame,method,update_ms,trace_ms,mrays_s,sah_cost,differing\n";
    run_animation(anim, o, folder, csv, rows);
    // The measured tables with the machine's columns; summary.csv, which --replot redraws from a committed
    // animation.csv, without (the same bytes on any machine).
    const machine_columns here = this_machine(parallel_threads());
    write_text(folder / "animation.csv", with_machine(csv.str(), here));
    write_text(folder / "breakeven.csv", with_machine(break_even(rows, std::size_t(o.width) * std::size_t(o.height)), here));
    write_text(folder / "summary.csv", summary(rows));
    plot_animation(rows, folder);
    big << "mesh,instances,triangles,build_ms,primary_mrays_s,hits,rays,instanced_mb,flattened_mb,ratio\n";
    big_scene(rigid, rigid_name, o, big);
    write_text(folder / "big.csv", with_machine(big.str(), here));
    std::printf("wrote %s: animation.csv, breakeven.csv, summary.csv, big.csv, update_vs_trace.svg, sah_drift.svg, frames/\n", folder.string().c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch10_exercise" : "ch10", run, argc, argv);
}
