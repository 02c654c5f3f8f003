// ch14: hybrid traversal. Chapter 12's packets on chapter 13's 8-wide tree, each ray going on alone (chapter
// 13's single-ray walk) where its packet has thinned out to `threshold` busy lanes or fewer. Three parts:
// the threshold swept from 0 (never leave: chapter 12's wide walk) to K (every ray alone from the root), and
// chosen per packet from its coherence, for K = 8 and 16, against chapter 13's 8-wide tree (blocks of 8) and
// chapter 12's wide and frustum walks, on the teapot in a stadium, the bunny and Sponza (when the shared
// meshes are there): primary, shadow and diffuse rays on one thread, Mrays/s (the median of interleaved
// rounds), nodes, boxes and triangles per ray, busy lanes and the share of rays that left their packet, every
// answer checked against chapter 13's; per scene a heat map of where the primary rays left their packets; and
// a camera flight through Sponza with a mirror floor (chapter 11's Whitted shading, all threads), each frame
// rendered by the hybrid in packets, by chapter 13's tree and by Embree one ray at a time, the hybrid's image
// equal to chapter 13's bit for bit. Tables (sweep.csv, flight.csv), a plot, heat maps and an animation.
#include "strahl/diagram.hpp"
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch05/sah.hpp"
#include "strahl/ch12/accel.hpp"
#include "strahl/ch12/render.hpp"
#include "strahl/ch13/accel.hpp"
#include "strahl/ch14/accel.hpp"
#include "strahl/ch14/embree_tracer.hpp"
#include "strahl/ch14/flight.hpp"
#include "strahl/image.hpp"
#include "strahl/machine.hpp"
#include "strahl/parallel.hpp"
#include "strahl/plot.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/progress.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <sstream>

namespace strahl::ch14 {
// The chapter's figure (src/diagrams.cpp): two packets through the hybrid tracer, where their rays left.
std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force);
}  // namespace strahl::ch14

namespace {

using namespace strahl;
namespace fs = std::filesystem;

// The ray sets, in the order every table lists them.
constexpr ch01::ray_kind kinds[] = {ch01::ray_kind::primary, ch01::ray_kind::shadow, ch01::ray_kind::diffuse};

// The reference every tracer is compared with, the row the packets are also measured against, and the
// tracer of the heat maps and the flight.
const char* const ch13_label = "bvh8-block8";
const char* const wide_label = "wide16-4x4";
const char* const hybrid_label = "hybrid16-auto";

// A tracer of the sweep: chapter 13's single-ray walk (lanes 0), a packet walk of chapter 12, or a hybrid.
struct tracer {
    std::string label;
    int lanes = 0;                        // K
    std::optional<ch12::walk_kind> walk;  // chapter 12's
    std::optional<int> threshold;         // the hybrids': 0 .. K or ch14::automatic
};

// The hybrids at thresholds 0, 1, 2, K/4, K/2, K-2, K-1, K and automatic, duplicates removed.
std::vector<tracer> tracers() {
    std::vector<tracer> out = {{ch13_label, 0, {}, {}}, {wide_label, 16, ch12::walk_kind::wide, {}},
                               {"frustum16-4x4", 16, ch12::walk_kind::frustum, {}}};
    for (const int k : {8, 16}) {
        std::vector<int> seen;
        for (const int t : {0, 1, 2, k / 4, k / 2, k - 2, k - 1, k, ch14::automatic})
            if (std::find(seen.begin(), seen.end(), t) == seen.end()) {
                seen.push_back(t);
                out.push_back({"hybrid" + std::to_string(k) + "-" + ch14::threshold_name(t), k, {}, t});
            }
    }
    return out;
}

// Chapter 13's 8-wide tree, optimal collapse, leaf blocks of 8, from chapter 05's binned SAH tree.
std::unique_ptr<accel> make_ch13() {
    ch13::wide_config c;
    c.width = 8, c.block = 8, c.collapse.method = ch13::collapse_method::optimal;
    return ch13::make_accel(ch13_label, [](std::span<const aabb> boxes, std::span<const vec3> centroids) {
        return ch05::build_sah_bvh_fast(boxes, centroids);
    }, c);
}

// image_width: the rows the packets' tiles are cut from (0: packets of consecutive rays).
std::unique_ptr<accel> make(const tracer& t, int image_width) {
    if (t.threshold) return ch14::make_accel(t.label, {t.lanes, 4, t.lanes / 4, image_width, *t.threshold});
    if (t.walk) return ch12::make_accel(t.label, {*t.walk, t.lanes, 4, t.lanes / 4, image_width});
    return make_ch13();
}

// The rays of one scene and chapter 13's answers, which every tracer must reproduce.
struct ray_sets {
    std::vector<ray> rays[3];
    std::vector<hit> hits[3];           // primary and diffuse: closest hit
    std::vector<std::uint8_t> blocked;  // shadow: any hit
};

ray_sets make_rays(const accel& exact, const scene& s, int width, int height) {
    ray_sets r;
    r.rays[0] = ch01::primary_rays(s, width, height);
    r.hits[0].resize(r.rays[0].size());
    exact.intersect(r.rays[0], r.hits[0]);
    r.rays[1] = ch01::secondary_rays(ch01::ray_kind::shadow, s, r.rays[0], r.hits[0]);
    r.rays[2] = ch01::secondary_rays(ch01::ray_kind::diffuse, s, r.rays[0], r.hits[0], 1);
    r.blocked.resize(r.rays[1].size());
    exact.occluded(r.rays[1], r.blocked);
    r.hits[2].resize(r.rays[2].size());
    exact.intersect(r.rays[2], r.hits[2]);
    return r;
}

// The answers of one run on ray set k that differ from chapter 13's.
std::size_t differing(const ray_sets& r, int k, const std::vector<hit>& hits,
                      const std::vector<std::uint8_t>& blocked) {
    if (!ch01::is_any_hit(kinds[k])) return hits_differing(hits, r.hits[k]);
    std::size_t n = 0;
    for (std::size_t i = 0; i < blocked.size(); ++i) n += (blocked[i] != 0) != (r.blocked[i] != 0);
    return n;
}

// A row of the table: one tracer on one ray set of one scene.
struct row {
    std::string scene, rays, tracer;
    int lanes = 0;
    std::optional<int> threshold;
    std::size_t ray_count = 0, differing = 0;  // differing: the worst of the tracer's runs
    double mrays = 0, vs_ch13 = 0, vs_wide16 = 0, nodes_per_ray = 0, boxes_per_ray = 0, tris_per_ray = 0;
    std::optional<double> mean_active;  // packet tracers: busy lanes per vector visit
    std::optional<double> left_share;   // hybrids: of the rays their packets took, the share that left
};

// One counted run of a tracer on ray set k: counters, lanes and (hybrids) the per-ray share of the packet's
// node visits made before the ray left (1: never left, -1: traced alone from the start) into per_ray.
row count(const accel& a, const tracer& t, const ray_sets& r, int k, std::vector<float>* per_ray) {
    const bool any = ch01::is_any_hit(kinds[k]);
    const std::vector<ray>& rays = r.rays[k];
    row out;
    out.rays = ch01::to_string(kinds[k]), out.tracer = t.label, out.lanes = t.lanes, out.threshold = t.threshold;
    out.ray_count = rays.size();
    std::vector<hit> hits(rays.size());
    std::vector<std::uint8_t> blocked(rays.size(), 2);
    counter_values c;
    if (const auto* p = dynamic_cast<const ch12::packet_accel_base*>(&a)) {
        std::vector<float> used;
        const ch12::lane_stats l = any ? p->any_lanes(rays, blocked, &used) : p->closest_lanes(rays, hits, &used);
        c = l.counts;
        out.mean_active = l.mean_active();
        if (t.threshold) {
            std::size_t packed = 0, left = 0;
            for (const float f : used) packed += f >= 0.0f, left += f >= 0.0f && f < 1.0f;
            out.left_share = packed ? double(left) / double(packed) : 0.0;
            if (per_ray) *per_ray = std::move(used);
        }
    } else if (const auto counted = any ? a.occluded_counted(rays, blocked) : a.intersect_counted(rays, hits)) {
        c = *counted;
    }
    out.differing = differing(r, k, hits, blocked);
    out.nodes_per_ray = c.per_ray(c.nodes_visited);
    out.boxes_per_ray = c.per_ray(c.box_tests);
    out.tris_per_ray = c.per_ray(c.prim_tests);
    return out;
}

// Where the primary rays left their packets: per pixel, the share of its packet's node visits made before
// the ray went on alone (1: it never left); grey: a ray no packet took.
image left_map(const std::vector<float>& left, int width, int height) {
    std::vector<float> values(left.size());
    for (std::size_t i = 0; i < left.size(); ++i) values[i] = left[i] < 0.0f ? std::nanf("") : left[i];
    const char* label = width >= 400   ? "share of the packet's node visits before the ray left"
                        : width >= 224 ? "share of visits before leaving"
                        : width >= 160 ? "visits before leaving"
                                       : "left at";
    image img = heat_map(values, width, height, label);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if (left[std::size_t(y) * width + x] < 0.0f) img.at(x, y) = color(0.12f);
    return img;
}

std::string cell(const std::optional<double>& v) {
    char text[32];
    std::snprintf(text, sizeof text, "%6.2f", v.value_or(0.0));
    return v ? text : "     -";
}

std::vector<row> run_scene(const scene& s, const std::string& name, int width, int height, int repeats,
                           const fs::path& map_path) {
    // Every tracer built, then timed in interleaved rounds (as chapter 12's program): a warm-up round, then
    // `repeats` rounds, each tracing every ray set once with every tracer; a figure is the median of its rounds.
    const std::vector<tracer> list = tracers();
    std::vector<std::unique_ptr<accel>> built;
    for (const tracer& t : list) {
        built.push_back(make(t, width));
        built.back()->build(s);
    }
    const ray_sets r = make_rays(*built[0], s, width, height);
    std::printf("%s: %zu triangles; %d x %d primary rays, %zu shadow and %zu diffuse rays; one thread, median of %d "
                "interleaved rounds\n", name.c_str(), s.mesh.triangle_count(), width, height, r.rays[1].size(),
                r.rays[2].size(), repeats);
    std::printf("  %-15s %23s   %20s   %20s\n", "", "Mrays/s", "x bvh8-block8", "left their packet");
    std::printf("  %-15s %7s %7s %7s   %6s %6s %6s   %6s %6s %6s %7s\n", "tracer", "primary", "shadow", "diffuse",
                "prim.", "shadow", "diff.", "prim.", "shadow", "diff.", "differ");
    std::vector<hit> hits[3];
    std::vector<std::uint8_t> blocked(r.rays[1].size());
    for (int k = 0; k < 3; ++k) hits[k].resize(r.rays[k].size());
    std::vector<std::vector<double>> ms(list.size() * 3);
    std::vector<std::size_t> wrong(list.size() * 3, 0);
    for (int round = 0; round <= repeats; ++round)
        for (std::size_t i = 0; i < list.size(); ++i)
            for (int k = 0; k < 3; ++k) {
                const timer t;
                if (ch01::is_any_hit(kinds[k])) built[i]->occluded(r.rays[k], blocked);
                else built[i]->intersect(r.rays[k], hits[k]);
                if (round > 0) ms[i * 3 + k].push_back(t.milliseconds());
                wrong[i * 3 + k] = std::max(wrong[i * 3 + k], differing(r, k, hits[k], blocked));
            }
    std::vector<row> rows;
    std::vector<float> left;
    for (std::size_t i = 0; i < list.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            row x = count(*built[i], list[i], r, k, list[i].label == hybrid_label && k == 0 ? &left : nullptr);
            x.scene = name;
            const double m = median(ms[i * 3 + k]);
            x.mrays = m > 0 ? double(r.rays[k].size()) / m * 1e-3 : 0.0;
            x.differing = std::max(x.differing, wrong[i * 3 + k]);
            rows.push_back(std::move(x));
        }
    // Each row against chapter 13's and chapter 12's wide walk on the same rays (rows of tracer i at i * 3 + k).
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const double ch13 = rows[i % 3].mrays, wide = rows[3 + i % 3].mrays;
        rows[i].vs_ch13 = ch13 > 0 ? rows[i].mrays / ch13 : 0.0;
        rows[i].vs_wide16 = wide > 0 ? rows[i].mrays / wide : 0.0;
    }
    for (std::size_t i = 0; i + 2 < rows.size(); i += 3) {
        const row *p = &rows[i], *sh = &rows[i + 1], *d = &rows[i + 2];
        std::printf("  %-15s %7.2f %7.2f %7.2f   %6.2f %6.2f %6.2f   %s %s %s %7zu\n", p->tracer.c_str(), p->mrays,
                    sh->mrays, d->mrays, p->vs_ch13, sh->vs_ch13, d->vs_ch13, cell(p->left_share).c_str(),
                    cell(sh->left_share).c_str(), cell(d->left_share).c_str(),
                    p->differing + sh->differing + d->differing);
    }
    if (left.size() == std::size_t(width) * std::size_t(height)) {
        write_image(map_path, left_map(left, width, height));
        std::printf("  wrote %s\n", map_path.string().c_str());
    }
    std::fflush(stdout);
    return rows;
}

void write_table(const std::vector<row>& rows, const fs::path& csv) {
    std::ostringstream o;
    o << "scene,rays,ray_count,tracer,lanes,threshold,mrays_s,vs_ch13,vs_wide16,nodes_per_ray,boxes_per_ray,"
         "tris_per_ray,mean_active_lanes,left_share,differing\n";
    for (const row& r : rows) {
        o << r.scene << ',' << r.rays << ',' << r.ray_count << ',' << r.tracer << ',';
        if (r.lanes) o << r.lanes;
        o << ',' << (r.threshold ? ch14::threshold_name(*r.threshold) : "") << ',' << r.mrays << ',' << r.vs_ch13
          << ',' << r.vs_wide16 << ',' << r.nodes_per_ray << ',' << r.boxes_per_ray << ',' << r.tris_per_ray << ',';
        if (r.mean_active) o << *r.mean_active;
        o << ',';
        if (r.left_share) o << *r.left_share;
        o << ',' << r.differing << '\n';
    }
    write_text(csv, with_machine(o.str(), this_machine(1)));  // the sweep runs on one thread
}

// The 16-lane hybrid's speed over chapter 13's against the threshold as a fraction of K, a line per scene
// and ray set; the automatic threshold as a dashed level line in the same colour.
void write_plot(const std::vector<row>& rows, const fs::path& svg) {
    plot p{"Hybrid traversal, 16 lanes, one thread (dashed: the threshold chosen per packet)",
           "threshold / K  (0: rays never leave the packet; 1: every ray alone from the root)",
           "x chapter 13 (bvh8-block8)", false, false, {}};
    std::vector<std::string> keys;
    std::vector<plot_series> lines, levels;
    for (const row& r : rows) {
        if (r.lanes != 16 || !r.threshold) continue;
        const std::string key = r.scene + " " + r.rays;
        const auto at = std::find(keys.begin(), keys.end(), key);
        const std::size_t c = std::size_t(at - keys.begin());
        if (at == keys.end()) {
            keys.push_back(key);
            lines.emplace_back();
            lines.back().label = key, lines.back().color = int(c);
        }
        if (*r.threshold != ch14::automatic) {
            lines[c].x.push_back(double(*r.threshold) / 16.0), lines[c].y.push_back(r.vs_ch13);
            continue;
        }
        plot_series level;
        level.label = key + " auto", level.x = {0.0, 1.0}, level.y = {r.vs_ch13, r.vs_ch13};
        level.color = int(c), level.dashed = true, level.in_legend = false, level.markers = false;
        levels.push_back(level);
    }
    p.series = lines;
    p.series.insert(p.series.end(), levels.begin(), levels.end());
    write_svg(svg, to_svg(p, 960, 520));
}

struct flight_options {
    int frames = 24, width = 400, height = 225, threads = 0;
};

// The flight: every frame rendered by each tracer in turn (after one untimed frame each), timed on the wall
// clock; the hybrid's image must equal chapter 13's. Returns the exit code.
int run_flight(scene s, const std::string& name, const flight_options& o, const fs::path& folder) {
    const aabb box = s.mesh.bounds();
    const auto single = make_ch13();
    single->build(s);
    const std::size_t mirrors = ch14::make_floor_mirror(s, *single);
    if (s.lights.empty()) {
        const float d = 0.5f * box.extent().y;
        s.lights.push_back({box.centroid() + vec3(0.0f, d, 0.0f), color(pi * 4.0f * d * d)});
    }
    const auto hybrid = ch14::make_accel(hybrid_label, {16, 4, 4, 0, ch14::automatic});
    hybrid->build(s);
    std::unique_ptr<accel> embree;
    if (ch14::embree_available()) {
        embree = ch14::make_embree_tracer();
        embree->build(s);
    }
    const thread_limit limit(o.threads);
    std::printf("flight: %s with a mirror floor (%zu triangles), %d frames of %d x %d, Whitted shading to depth 3, "
                "%d threads\n", name.c_str(), mirrors, o.frames, o.width, o.height, parallel_threads());
    if (!embree) std::printf("  embree-medium: not in this build (Embree 3 not found)\n");
    struct entry {
        std::string label;
        const accel* a;
        bool packets;  // through the packet renderer (else one ray at a time)
        double seconds = 0;
        std::uint64_t rays = 0;
    };
    std::vector<entry> entries = {{hybrid_label, hybrid.get(), true}, {ch13_label, single.get(), false}};
    if (embree) entries.push_back({embree->name(), embree.get(), false});
    ch01::render_settings settings;
    settings.max_depth = 3;
    const auto render = [&](const entry& e, const camera& cam) {
        return e.packets ? ch12::render_packets(*e.a, *e.a, s, cam, settings, 1)
                         : ch12::render_single(*e.a, s, cam, settings, 1);
    };
    for (const entry& e : entries) render(e, camera(ch14::flight_camera(box, 0, o.frames), o.width, o.height));
    std::ostringstream csv;
    csv << "frame,tracer,ms,rays,mrays_s\n";
    std::vector<image> frames;
    image_difference embree_off;  // Embree's image against chapter 13's: the largest difference, pixels beyond 1/255
    progress_bar bar("flight", std::uint64_t(o.frames), "frames");
    for (int f = 0; f < o.frames; ++f) {
        const camera cam(ch14::flight_camera(box, f, o.frames), o.width, o.height);
        std::vector<ch01::render_result> got;
        for (entry& e : entries) {
            const timer t;
            got.push_back(render(e, cam));
            const double ms = t.milliseconds();
            const std::uint64_t rays = got.back().counts.total();
            e.seconds += ms * 1e-3, e.rays += rays;
            csv << f << ',' << e.label << ',' << ms << ',' << rays << ',' << double(rays) / (ms * 1e3) << '\n';
        }
        const std::vector<color>& want = got[1].img.pixels;
        if (std::memcmp(got[0].img.pixels.data(), want.data(), want.size() * sizeof(color)) != 0) {
            bar.finish();
            std::printf("flight frame %d: the hybrid's image differs from chapter 13's in %zu pixels: a bug\n", f,
                        compare(got[0].img, got[1].img).differing_pixels);
            return 1;
        }
        if (embree) {
            const image_difference d = compare(got[2].img, got[1].img, 1.0f / 255.0f);
            embree_off.max_error = std::max(embree_off.max_error, d.max_error);
            embree_off.differing_pixels += d.differing_pixels;
        }
        frames.push_back(std::move(got[0].img));
        bar.add();
    }
    bar.finish();
    write_text(folder / "flight.csv", with_machine(csv.str(), this_machine(parallel_threads())));
    // The pictures exposed for the eye (the scene's light is dim for a camera in the atrium): every frame scaled
    // by one factor, the 99th percentile of the first frame's brightest channel mapped to 0.9. Only the files:
    // the comparisons above are on the rendered values.
    std::vector<float> bright;
    for (const color& c : frames.front().pixels) bright.push_back(std::max(c.r, std::max(c.g, c.b)));
    std::sort(bright.begin(), bright.end());
    const float p99 = bright.empty() ? 0.0f : bright[bright.size() * 99 / 100];
    const float exposure = p99 > 0.0f && std::isfinite(p99) ? 0.9f / p99 : 1.0f;
    for (image& img : frames)
        for (color& c : img.pixels) c *= exposure;
    std::printf("images exposed by x%.3g (the first frame's 99th percentile to 0.9)\n", double(exposure));
    write_image(folder / "flight_first.png", frames.front());
    write_image(folder / "flight_last.png", frames.back());
    const bool gif = write_animation(folder / "flight.gif", frames, 8);
    for (const entry& e : entries) {
        std::printf("  %-15s %7.2f frames/s %8.2f Mrays/s", e.label.c_str(), double(o.frames) / e.seconds,
                    double(e.rays) / e.seconds * 1e-6);
        if (&e != &entries[0]) std::printf("   hybrid x%.2f", e.seconds / entries[0].seconds);
        std::printf("\n");
    }
    std::printf("  every frame of the hybrid equals chapter 13's bit for bit");
    if (embree)
        std::printf("; Embree's by at most %.2g in a channel, %zu pixels by more than 1/255 (its own triangle test)",
                    embree_off.max_error, embree_off.differing_pixels);
    std::printf("\nwrote %s, flight_first.png, flight_last.png%s\n", (folder / "flight.csv").string().c_str(),
                gif ? ", flight.gif" : " (no flight.gif: this OpenImageIO writes no animated GIF)");
    return 0;
}

int run(int argc, const char* const* argv) {
    cli args("ch14", "Chapter 14, hybrid traversal (" + std::string(track_name()) + "): packets of 8 and 16 rays on "
             "chapter 13's 8-wide tree whose rays go on alone where the packet thins out; the threshold swept against "
             "chapter 13's single-ray walk and chapter 12's packets (primary, shadow and diffuse rays, one thread), "
             "heat maps of where rays leave, and a flight through Sponza against chapter 13 and Embree (all threads).");
    args.scene_option({"stadium", "bunny", "sponza"}, {"stadium", "bunny", "sponza"}, "the sweep's scenes, the meshes where present")
        .option("width", "N", "", "the sweep's primary rays per row (default 192, 96 with --quick)")
        .option("height", "N", "", "the sweep's rows (default 3/4 of the width)")
        .option("repeats", "K", "5", "timed rounds after a warm-up round; the median is reported")
        .option("flight-frames", "N", "", "frames of the flight, 1..1000 (default 24, 4 with --quick)")
        .option("flight-width", "W", "", "the flight's image width, 1..4096 (default 400, 160 with --quick)")
        .option("flight-height", "H", "", "the flight's image height, 1..4096 (default 225, 90 with --quick)")
        .threads_option("0", "the flight's threads, 0..1024 (0: one per core); the sweep runs on one")
        .output_options("write sweep.csv, threshold.svg, SCENE_left.png, flight.csv, flight_first.png, "
                "flight_last.png and flight.gif into DIR/ (default out/14_hybrid_traversal/)")
        .flag("no-sweep", "skip the threshold sweep (and its heat maps)")
        .flag("no-flight", "skip the flight")
        .flag("quick", "the teapot in a stadium only: the sweep at 96 x 72 rays, a flight of 4 frames of 160 x 90")
        .option("diagrams", "DIR", "", "only draw the chapter's figure into DIR/ (switch.svg; --force to replace it)");
    if (!args.parse(argc, argv)) return 0;
    if (draw_diagrams_if_asked(args, strahl::ch14::write_diagrams)) return 0;
    const bool quick = args.has("quick"), sweep = !args.has("no-sweep"), flight = !args.has("no-flight");
    if (!sweep && !flight) throw usage_error("--no-sweep and --no-flight leave nothing to do");
    fs::path folder = "out/14_hybrid_traversal";
    const bool user_named = args.has("out");
    if (user_named) folder = args.get("out");
    const image_size size = read_image_size(args, quick ? 96 : 192, 4096);
    const int repeats = args.get_int("repeats");
    if (repeats < 1 || repeats > 100) throw usage_error("--repeats must lie in [1, 100]");
    std::vector<std::string> names = args.scene_names();
    if (quick) names = {"stadium"};
    flight_options fo;
    const auto read = [&](const char* name, int quick_value, int full_value, int hi) {
        const int v = args.has(name) ? args.get_int(name) : quick ? quick_value : full_value;
        if (v < 1 || v > hi)
            throw usage_error("--" + std::string(name) + " must lie in [1, " + std::to_string(hi) + "]");
        return v;
    };
    fo.frames = read("flight-frames", 4, 24, 1000);
    fo.width = read("flight-width", 160, 400, 4096);
    fo.height = read("flight-height", 90, 225, 4096);
    fo.threads = read_threads(args, 0);

    // The scenes first, so that only the files this run writes are checked before the work.
    std::vector<std::pair<std::string, scene>> scenes;
    if (sweep)
        for (const std::string& name : names)
            if (auto s = course_scene(name)) scenes.emplace_back(name, std::move(*s));
    // The flight: through Sponza where it is there (the stadium with --quick).
    std::optional<std::pair<std::string, scene>> flown;
    if (flight && !quick)
        for (const auto& sc : scenes)
            if (sc.first == "sponza") flown = sc;
    if (flight && !quick && !flown)
        if (auto s = load_shared_mesh("sponza.obj", "sponza")) flown.emplace("sponza", std::move(*s));
    if (flight && !flown) flown.emplace("stadium", builtin_scene("teapot_stadium"));
    const fs::path csv = folder / "sweep.csv", svg = folder / "threshold.svg";
    std::vector<fs::path> files;
    if (sweep) files = {csv, svg};
    for (const auto& sc : scenes) files.push_back(folder / (sc.first + "_left.png"));
    if (flight)
        for (const char* f : {"flight.csv", "flight_first.png", "flight_last.png", "flight.gif"})
            files.push_back(folder / f);
    for (const fs::path& p : files) prepare_output(p, user_named, args.has("force"));

    if (sweep) {
        const thread_limit one(1);
        std::printf("SIMD in this build (lanes: backend): %s\n", ch13::simd_widths().c_str());
        std::vector<row> rows;
        for (const auto& [name, s] : scenes) {
            const std::vector<row> r =
                run_scene(s, name, size.width, size.height, repeats, folder / (name + "_left.png"));
            rows.insert(rows.end(), r.begin(), r.end());
        }
        write_table(rows, csv);
        write_plot(rows, svg);
        std::printf("wrote %s, %s\n", csv.string().c_str(), svg.string().c_str());
        bool wrong = false;
        for (const row& r : rows)
            if (r.differing) {
                std::printf("%s differs from %s in %zu of %s's %s rays: a bug\n", r.tracer.c_str(), ch13_label,
                            r.differing, r.scene.c_str(), r.rays.c_str());
                wrong = true;
            }
        if (wrong) return 1;
    }
    return flight ? run_flight(std::move(flown->second), flown->first, fo, folder) : 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch14_exercise" : "ch14", run, argc, argv);
}
