// ch11: model only what the scene requires. Chapter 05's binned SAH tree and chapter 05's fast walk, the
// same rays throughout, and six ways for a leaf to reach its primitives (virtual objects, a variant,
// type-sorted arrays, triangles only, inlined, structure of arrays): Mrays/s on one thread for primary,
// diffuse and shadow rays on the bunny and Sponza (the teapot in a stadium where they are absent), each
// step's speed-up over the first. Then chapter 01's Whitted renderer with rough reflection on the Cornell
// box with the bunny: virtual primitives and materials, a variant of both, triangles only with virtual
// materials and with a switch; rays per second, the images compared bit for bit. Tables, CSV files, plots.
#include "strahl/diagram.hpp"
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch05/accel.hpp"
#include "strahl/ch11/step_report.hpp"
#include "strahl/ch11/steps.hpp"
#include "strahl/machine.hpp"
#include "strahl/parallel.hpp"
#include "strahl/plot.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/race_csv.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace strahl::ch11 {
// The chapter's figure (src/diagrams.cpp): one leaf as each step holds it in memory.
std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force);
}  // namespace strahl::ch11

namespace {

using namespace strahl;
namespace fs = std::filesystem;

struct step_row {
    std::string scene, step;
    double memory_mib = 0, primary = 0, diffuse = 0, shadow = 0;
    std::size_t differing = 0;
};

void write_staircase(const std::vector<step_row>& steps, const fs::path& svg, const std::string& how);

std::vector<step_row> run_steps(const scene& s, const std::string& name, int width, int height, int repeats) {
    std::printf("%s: %zu triangles; %d x %d primary rays, as many diffuse and shadow rays; one thread, median of %d\n",
                name.c_str(), s.mesh.triangle_count(), width, height, repeats);
    const auto reference = ch05::make_accel(false, {}, ch05::walk_kind::fast);
    reference->build(s);
    const ch01::checked_rays rays = ch01::make_checked_rays(s, width, height, *reference);
    const std::vector<ray> shadow = ch01::secondary_rays(ch01::ray_kind::shadow, s, rays.primary, rays.primary_hits);
    std::vector<std::uint8_t> shadow_ref(shadow.size());
    reference->occluded(shadow, shadow_ref);
    std::printf("  %-12s %8s %9s %9s %9s %6s   %s\n", "step", "MiB", "primary", "diffuse", "shadow", "differ",
                "(Mrays/s; x step 1)");
    std::vector<step_row> rows;
    for (const ch11::step_info& st : ch11::all_steps()) {
        step_row r{name, st.name};
        const auto a = ch11::make_accel(st.id);
        a->build(s);
        r.memory_mib = double(a->memory_bytes()) / (1024.0 * 1024.0);
        const ch01::checked_speed speed = ch01::time_checked(*a, rays, repeats);
        r.primary = speed.primary_mrays, r.diffuse = speed.diffuse_mrays, r.differing = speed.differing;
        std::vector<std::uint8_t> blocked(shadow.size());
        const double ms = median_ms(repeats, [&] { a->occluded(shadow, blocked); });
        r.shadow = ms > 0 ? double(shadow.size()) / ms * 1e-3 : 0.0;
        for (std::size_t i = 0; i < shadow.size(); ++i) r.differing += blocked[i] != shadow_ref[i];
        const step_row& first = rows.empty() ? r : rows.front();
        std::printf("  %-12s %8.2f %9.2f %9.2f %9.2f %6zu   x%.2f x%.2f x%.2f\n", r.step.c_str(), r.memory_mib, r.primary,
                    r.diffuse, r.shadow, r.differing, r.primary / first.primary, r.diffuse / first.diffuse,
                    r.shadow / first.shadow);
        std::fflush(stdout);
        rows.push_back(r);
    }
    return rows;
}

// The Cornell box with its mirror and rough-mirror spheres, and the bunny (or chapter 01's teapot where the
// shared meshes are absent) standing at the back right in a white Lambert.
scene render_scene() {
    scene s = cornell_box(true);
    s.name = "cornell+bunny";
    triangle_mesh m;
    if (const auto bunny = load_shared_mesh("bunny.ply", "bunny")) m = bunny->mesh;
    else m = teapot_mesh(6), s.name = "cornell+teapot";
    aabb box;
    for (const vec3& p : m.positions) box.grow(p);
    const float scale = 0.38f / std::max(box.extent().x, std::max(box.extent().y, box.extent().z));
    const vec3 foot((box.min.x + box.max.x) / 2, box.min.y, (box.min.z + box.max.z) / 2);
    for (vec3& p : m.positions) p = (p - foot) * scale + vec3(0.68f, 0.0f, 0.32f);
    const std::uint32_t white = std::uint32_t(s.materials.size());
    s.materials.push_back(material_desc{"bunny", material_kind::diffuse, color(0.75f)});
    if (s.triangle_materials.empty()) s.triangle_materials.assign(s.mesh.triangle_count(), 0);
    s.mesh.append(m);
    s.triangle_materials.resize(s.mesh.triangle_count(), white);
    return s;
}

struct render_row {
    std::string renderer;
    double mrays = 0, seconds = 0;
    std::uint64_t rays = 0;
    bool same_image = true;
};

std::vector<render_row> run_renderers(const scene& s, int width, int glossy, int repeats, const fs::path& png) {
    const int height = width;
    const camera cam(s.camera, width, height);
    ch01::render_settings settings;
    std::printf("\n%s: %zu triangles, %zu spheres; Whitted with rough reflection (%d rays per rough hit), %d x %d, one "
                "thread, median of %d renders\n", s.name.c_str(), s.mesh.triangle_count(), s.spheres.size(), glossy,
                width, height, repeats);
    std::printf("  %-18s %10s %12s %10s %s\n", "renderer", "Mrays/s", "rays", "x virtual", "image");
    std::vector<render_row> rows;
    image first;
    for (const ch11::renderer& how : ch11::all_renderers()) {
        render_row r{how.name};
        std::vector<double> seconds;
        ch01::render_result res = ch11::render(s, cam, how, settings, glossy);  // warm-up, untimed
        for (int k = 0; k < repeats; ++k) res = ch11::render(s, cam, how, settings, glossy), seconds.push_back(res.seconds);
        std::sort(seconds.begin(), seconds.end());
        r.seconds = seconds[seconds.size() / 2];
        r.rays = res.counts.total();
        r.mrays = double(r.rays) / r.seconds * 1e-6;
        if (rows.empty()) first = res.img, write_image(png, res.img);
        else r.same_image = first.pixels.size() == res.img.pixels.size() &&
                            std::memcmp(first.pixels.data(), res.img.pixels.data(), first.pixels.size() * sizeof(color)) == 0;
        std::printf("  %-18s %10.2f %12llu %10.2f %s\n", r.renderer.c_str(), r.mrays, (unsigned long long)r.rays,
                    r.mrays / (rows.empty() ? r.mrays : rows.front().mrays), r.same_image ? "same" : "DIFFERS");
        std::fflush(stdout);
        rows.push_back(r);
    }
    return rows;
}

void write_outputs(const std::vector<step_row>& steps, const std::vector<render_row>& renders, const fs::path& folder) {
    std::ostringstream csv;
    csv << "scene,step,memory_mib,primary_mrays_s,diffuse_mrays_s,shadow_mrays_s,differing\n";
    for (const step_row& r : steps)
        csv << r.scene << ',' << r.step << ',' << r.memory_mib << ',' << r.primary << ',' << r.diffuse << ',' << r.shadow
            << ',' << r.differing << '\n';
    write_text(folder / "steps.csv", with_machine(csv.str(), this_machine(parallel_threads())));
    std::ostringstream rcsv;
    // x_virtual: each renderer's speed over the first's (chapter 01's virtual materials).
    rcsv << "renderer,mrays_s,rays,seconds,same_image,x_virtual\n";
    for (const render_row& r : renders)
        rcsv << r.renderer << ',' << r.mrays << ',' << r.rays << ',' << r.seconds << ',' << (r.same_image ? 1 : 0) << ','
             << (renders.front().mrays > 0 ? r.mrays / renders.front().mrays : 0.0) << '\n';
    write_text(folder / "render.csv", with_machine(rcsv.str(), this_machine(parallel_threads())));
    write_staircase(steps, folder / "staircase.svg", "same tree, same rays, one thread");
}

// The staircase: each structure's speed over the first's (step 1), one bar per scene and ray set.
void write_staircase(const std::vector<step_row>& steps, const fs::path& svg, const std::string& how) {
    bar_chart c{"Speed over chapter 01's virtual objects (" + how + ")", "x step 1", {}, {}, {}, false};
    std::vector<std::string> scenes;
    for (const step_row& r : steps) {
        if (std::find(c.categories.begin(), c.categories.end(), r.step) == c.categories.end()) c.categories.push_back(r.step);
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    }
    for (const std::string& name : scenes)
        for (int kind = 0; kind < 3; ++kind) {
            const step_row* base = nullptr;
            std::vector<double> v;
            for (const std::string& st : c.categories) {
                double x = 0;
                for (const step_row& r : steps)
                    if (r.scene == name && r.step == st) {
                        if (!base) base = &r;
                        const double ratio[] = {r.primary / base->primary, r.diffuse / base->diffuse, r.shadow / base->shadow};
                        x = ratio[kind];
                    }
                v.push_back(x);
            }
            c.series_labels.push_back(name + (kind == 0 ? " primary" : kind == 1 ? " diffuse" : " shadow"));
            c.values.push_back(v);
        }
    write_svg(svg, to_svg(c, 860, 460));
}

// staircase.csv: the staircase's figures, a row per scene, structure and ray set: its speed (closest hit on
// primary and diffuse rays, any hit on shadow rays) and that speed over step 1's on the same rays.
std::string staircase_csv(const std::vector<step_row>& steps) {
    std::ostringstream out;
    out << "scene,structure,rays,mrays_s,x_step1\n";
    for (const step_row& r : steps) {
        const step_row* base = nullptr;
        for (const step_row& b : steps)
            if (!base && b.scene == r.scene) base = &b;
        const double speed[] = {r.primary, r.diffuse, r.shadow}, first[] = {base->primary, base->diffuse, base->shadow};
        const char* rays[] = {"primary", "diffuse", "shadow"};
        for (int k = 0; k < 3; ++k)
            out << csv_field(r.scene) << ',' << csv_field(r.step) << ',' << rays[k] << ',' << speed[k] << ','
                << (first[k] > 0 ? speed[k] / first[k] : 0.0) << '\n';
    }
    return out.str();
}

// --from-race: the race's medians across processes (race.csv of race --processes N), its ch11 rows and,
// where present, ch13-bvh16 and embree-medium beside them. Closest-hit speed for primary and diffuse rays,
// any-hit speed for shadow rays.
std::vector<step_row> read_race(const fs::path& csv) {
    std::vector<step_row> rows;
    const auto find = [&](const std::string& scene, const std::string& step) -> step_row& {
        for (step_row& r : rows)
            if (r.scene == scene && r.step == step) return r;
        return rows.emplace_back(step_row{scene, step});
    };
    for (const race_csv_row& r : read_race_rows(csv)) {
        const std::string& structure = r.structure;
        const bool wanted = structure.rfind("ch11-", 0) == 0 || structure == "ch13-bvh16" || structure == "embree-medium";
        if (!wanted) continue;
        step_row& row = find(r.scene, structure.rfind("ch11-", 0) == 0 ? structure.substr(5) : structure);
        if (r.rays == "primary") row.primary = r.closest_mrays_s;
        else if (r.rays == "diffuse") row.diffuse = r.closest_mrays_s;
        else if (r.rays == "shadow") row.shadow = r.any_mrays_s;
    }
    if (rows.empty() || rows.front().step != "virtual")
        throw std::runtime_error(csv.string() + ": no ch11-virtual rows first: race with --accels ch11-virtual,...");
    return rows;
}

// --step-report DIR (exercise 11.4): the prediction beside what the race in DIR measured, process by process
// (DIR/processes/*/race.csv of race --processes N); step_report.csv.
void step_report(const fs::path& race_dir, const fs::path& csv) {
    using namespace strahl::ch11;
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(race_dir / "processes", ec))
        if (fs::exists(e.path() / "race.csv")) files.push_back(e.path() / "race.csv");
    if (ec || files.empty())
        throw std::runtime_error((race_dir / "processes").string() + ": no race.csv of a race --processes N run there");
    std::sort(files.begin(), files.end());
    std::vector<std::vector<race_csv_row>> processes;
    for (const fs::path& f : files) processes.push_back(read_race_rows(f));
    const step_prediction p = my_prediction();  // exercise 11.4a
    const std::vector<step_ratio> ratios = compare_steps(processes, p.before, p.after);  // exercise 11.4c
    if (ratios.empty())
        throw std::runtime_error(race_dir.string() + ": no process has both " + p.before + " and " + p.after +
                                 ": race --processes N --accels " + p.before + "," + p.after);
    std::printf("your prediction: %s over %s, x%.3g on diffuse rays, explained by: %s\n", p.after.c_str(),
                p.before.c_str(), p.ratio, p.counter.c_str());
    std::printf("measured in %zu processes (paired: %s / %s in each process):\n", files.size(), p.after.c_str(), p.before.c_str());
    std::printf("  %-16s %-8s %9s %17s %8s   %s\n", "scene", "rays", "median", "range", "verdict", "the counter that moved");
    std::ostringstream out;
    out << "scene,rays,before,after,processes,median,min,max,verdict,moved,moved_ratio,predicted_ratio,predicted_counter\n";
    for (const step_ratio& s : ratios) {
        std::printf("  %-16s %-8s %9.3f %8.3f to %5.3f %8s   %s (x%.3g)\n", s.scene.c_str(), s.rays.c_str(), s.median,
                    s.lo, s.hi, s.verdict.c_str(), s.moved.c_str(), s.moved_ratio);
        out << s.scene << ',' << s.rays << ',' << p.before << ',' << p.after << ',' << s.ratios.size() << ','
            << s.median << ',' << s.lo << ',' << s.hi << ',' << s.verdict << ',' << s.moved << ',' << s.moved_ratio << ','
            << p.ratio << ',' << p.counter << '\n';
    }
    write_text(csv, out.str());
    std::printf("wrote %s\n", csv.string().c_str());
}

int run(int argc, const char* const* argv) {
    cli args("ch11", "Chapter 11, model only what the scene requires (" + std::string(track_name()) + "): one tree, the same rays, six "
             "ways to reach the primitives (virtual, variant, type-sorted, triangles, inlined, soa), one thread; then "
             "the Whitted renderer with virtual materials, a variant and a switch. Tables, CSV files, plots, an image.");
    args.scene_option({"bunny", "sponza", "stadium"}, {"bunny", "sponza"}, "where present, else the stadium")
        .option("width", "N", "", "primary rays per row (default 192, 64 with --quick)")
        .option("height", "N", "", "rows (default 3/4 of the width)")
        .option("repeats", "K", "5", "timed runs per measurement after a warm-up; the median is reported")
        .option("render-size", "N", "", "the render's width and height in pixels (default 128, 32 with --quick)")
        .option("glossy-samples", "S", "16", "reflection rays per rough-mirror hit, 1 to 64")
        .output_options("write steps.csv, render.csv, staircase.svg and render.png into DIR/ "
                                   "(default out/11_devirtualize/)")
        .option("from-race", "CSV", "", "only draw staircase.svg and write its figures, staircase.csv, from a race's medians (race.csv of race --processes N "
                                         "with the ch11 rows first; ch13-bvh16 and embree-medium where present)")
        .flag("quick", "the teapot in a stadium only, 64 x 48 rays, a 32 x 32 render, one repeat")
        .option("step-report", "DIR", "", "only exercise 11.4's report: your prediction beside what a race run with "
                "--processes N --out DIR measured (DIR/processes/*/race.csv); writes step_report.csv")
        .option("diagrams", "DIR", "", "only draw the chapter's figure into DIR/ (layouts.svg; --force to replace it)");
    if (!args.parse(argc, argv)) return 0;
    if (draw_diagrams_if_asked(args, strahl::ch11::write_diagrams)) return 0;
    if (args.has("step-report")) {
        const fs::path folder = args.has("out") ? fs::path(args.get("out")) : fs::path("out/11_devirtualize");
        prepare_output(folder / "step_report.csv", args.has("out"), args.has("force"));
        step_report(args.get("step-report"), folder / "step_report.csv");
        return 0;
    }
    if (args.has("from-race")) {
        const std::vector<step_row> rows = read_race(args.get("from-race"));
        const fs::path folder = args.has("out") ? fs::path(args.get("out")) : fs::path("out/11_devirtualize");
        prepare_output(folder / "staircase.svg", args.has("out"), args.has("force"));
        prepare_output(folder / "staircase.csv", args.has("out"), args.has("force"));
        write_staircase(rows, folder / "staircase.svg", "the race's medians, one thread");
        write_text(folder / "staircase.csv", staircase_csv(rows));
        std::printf("wrote %s and staircase.csv from %zu rows of %s\n", (folder / "staircase.svg").string().c_str(),
                    rows.size(), args.get("from-race").c_str());
        return 0;
    }
    const bool quick = args.has("quick");
    fs::path folder = "out/11_devirtualize";
    const bool user_named = args.has("out");
    if (user_named) folder = args.get("out");
    for (const char* f : {"steps.csv", "render.csv", "staircase.svg", "render.png"})
        prepare_output(folder / f, user_named, args.has("force"));
    const image_size size = read_image_size(args, quick ? 64 : 192, 4096);
    const int repeats = quick ? 1 : args.get_int("repeats");
    if (repeats < 1 || repeats > 100) throw usage_error("--repeats must lie in [1, 100]");
    const int render_size = args.has("render-size") ? args.get_int("render-size") : quick ? 32 : 128;
    if (render_size < 1 || render_size > 2048) throw usage_error("--render-size must lie in [1, 2048]");
    const int glossy = args.get_int("glossy-samples");
    if (glossy < 1 || glossy > 64) throw usage_error("--glossy-samples must lie in [1, 64]");
    // all: the meshes where present, else the stadium
    std::vector<std::string> names = args.scene_names();
    if (quick) names = {"stadium"};
    const bool all = !quick && args.get("scene") == "all";
    const thread_limit one(1);
    std::vector<step_row> rows;
    for (const std::string& name : names) {
        if (name == "stadium") continue;
        if (const auto s = course_scene(name)) {
            const auto r = run_steps(*s, name, size.width, size.height, repeats);
            rows.insert(rows.end(), r.begin(), r.end());
        }
    }
    if (names == std::vector<std::string>{"stadium"} || (all && rows.empty()))
        rows = run_steps(builtin_scene("teapot_stadium"), "stadium", size.width, size.height, repeats);
    const std::vector<render_row> renders =
        run_renderers(render_scene(), render_size, glossy, std::min(repeats, 3), folder / "render.png");
    write_outputs(rows, renders, folder);
    std::printf("wrote %s/{steps.csv, render.csv, staircase.svg, render.png}\n", folder.string().c_str());
    std::size_t wrong = 0;
    for (const step_row& r : rows) wrong += r.differing;
    for (const render_row& r : renders) wrong += !r.same_image;
    if (wrong) {
        std::printf("%zu answers or images differ from the reference: a bug\n", wrong);
        return 1;
    }
    std::printf("against Embree on the same rays: build/release/bin/race --accels ch11-virtual,ch11-soa,embree-medium\n");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch11_exercise" : "ch11", run, argc, argv);
}
