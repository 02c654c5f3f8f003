// ch12: ray packets. Chapter 13's best single-ray rows (8-wide tree, optimal collapse, leaf blocks of 4 and
// of 8) against chapter 12's packet tracers (the masked, ranged and partition walks over chapter 05's binary
// tree; K rays against each child of chapter 13's 8-wide tree; its frustum alone), on the teapot in a stadium, the bunny and
// Sponza (when the shared meshes are there): primary, shadow and diffuse rays on one thread, Mrays/s (the
// median of interleaved rounds), the lanes a packet keeps busy, nodes, boxes and triangles per ray. Every
// packet tracer's answers are checked against chapter 13's. Two tables (packets.csv, lanes.csv), a plot, and
// per scene a heat map of the busy lanes of the 16-lane wide walk.
#include "strahl/diagram.hpp"
#include "strahl/ch01/ray_sets.hpp"
#include "strahl/ch05/sah.hpp"
#include "strahl/ch12/accel.hpp"
#include "strahl/ch13/accel.hpp"
#include "strahl/image.hpp"
#include "strahl/machine.hpp"
#include "strahl/parallel.hpp"
#include "strahl/plot.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

namespace strahl::ch12 {
// The chapter's figure (src/diagrams.cpp): a packet against three boxes, by the chapter's own tests.
std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force);
}  // namespace strahl::ch12

namespace {

using namespace strahl;
namespace fs = std::filesystem;

// The ray sets, in the order every table lists them.
constexpr ch01::ray_kind kinds[] = {ch01::ray_kind::primary, ch01::ray_kind::shadow, ch01::ray_kind::diffuse};

// A row of the table: one tracer on one ray set of one scene.
struct row {
    std::string scene, rays, tracer, walk, tile;
    int lanes = 0;                // K (0: chapter 13's single-ray walk)
    double mrays = 0, vs_best = 0;
    std::size_t ray_count = 0;
    std::size_t differing = 0;    // answers unlike chapter 13's, in the worst of the tracer's runs
    std::size_t alone = 0;        // rays no packet took (traced alone by chapter 05's walk)
    std::uint64_t packets = 0;
    double mean_active = 0, active_fraction = 0;  // packets only
    double nodes_per_ray = 0, boxes_per_ray = 0, tris_per_ray = 0;
    std::vector<double> share;    // percent of vector visits with k lanes entering, k = 0..K (packets only)
};

// A tracer: chapter 13's single-ray walk over its 8-wide tree (blocks of `block` triangles), or a packet
// tracer of chapter 12.
struct tracer {
    std::string label;
    std::optional<ch12::packet_config> packets;
    int block = 4;
};

std::vector<tracer> tracers(int image_width) {
    using wk = ch12::walk_kind;
    const auto p = [&](wk w, int k, int tw, int th) {
        const ch12::packet_config c{w, k, tw, th, image_width};
        return tracer{std::string(ch12::to_string(w)) + std::to_string(k) + "-" + std::to_string(tw) + "x" +
                          std::to_string(th), c, 0};
    };
    return {
        {"bvh8-optimal", std::nullopt, 4}, {"bvh8-block8", std::nullopt, 8},
        p(wk::masked, 4, 2, 2),            p(wk::masked, 8, 4, 2),            p(wk::masked, 16, 4, 4),
        p(wk::ranged, 16, 8, 8),           p(wk::ranged, 16, 16, 16),         p(wk::partition, 16, 8, 8),
        p(wk::partition, 16, 16, 16),      p(wk::wide, 8, 4, 2),              p(wk::wide, 16, 4, 4),
        p(wk::frustum, 16, 4, 4),
    };
}

// The tracer of the heat maps.
const char* const map_tracer = "wide16-4x4";

std::unique_ptr<accel> make(const tracer& t) {
    if (t.packets) return ch12::make_accel(t.label, *t.packets);
    ch13::wide_config c;
    c.width = 8, c.block = t.block, c.collapse.method = ch13::collapse_method::optimal;
    return ch13::make_accel(t.label, [](std::span<const aabb> boxes, std::span<const vec3> centroids) {
        return ch05::build_sah_bvh_fast(boxes, centroids);
    }, c);
}

// The rays of one scene and the answers of chapter 13's 8-wide tree, which every tracer must reproduce.
struct ray_sets {
    std::vector<ray> rays[3];
    std::vector<hit> hits[3];             // primary and diffuse: closest hit
    std::vector<std::uint8_t> blocked;    // shadow: any hit
    std::vector<hit> primary_hits;        // the pixels the secondary rays start from
};

ray_sets make_rays(const scene& s, int width, int height) {
    const auto exact = make(tracer{"bvh8-optimal", std::nullopt, 4});
    exact->build(s);
    ray_sets r;
    r.rays[0] = ch01::primary_rays(s, width, height);
    r.hits[0].resize(r.rays[0].size());
    exact->intersect(r.rays[0], r.hits[0]);
    r.primary_hits = r.hits[0];
    r.rays[1] = ch01::secondary_rays(ch01::ray_kind::shadow, s, r.rays[0], r.primary_hits);
    r.rays[2] = ch01::secondary_rays(ch01::ray_kind::diffuse, s, r.rays[0], r.primary_hits, 1);
    r.blocked.resize(r.rays[1].size());
    exact->occluded(r.rays[1], r.blocked);
    r.hits[2].resize(r.rays[2].size());
    exact->intersect(r.rays[2], r.hits[2]);
    return r;
}

std::size_t blocked_differing(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) n += (a[i] != 0) != (b[i] != 0);
    return n;
}

// One timed trace of one ray set (closest hit, any hit for shadow rays), in milliseconds, into hits or blocked.
double trace_ms(const accel& a, const ray_sets& r, int k, std::vector<hit>& hits, std::vector<std::uint8_t>& blocked) {
    const timer t;
    if (ch01::is_any_hit(kinds[k])) a.occluded(r.rays[k], blocked);
    else a.intersect(r.rays[k], hits);
    return t.milliseconds();
}

// The answers of one run of a tracer on ray set k that differ from chapter 13's.
std::size_t differing(const ray_sets& r, int k, const std::vector<hit>& hits,
                      const std::vector<std::uint8_t>& blocked) {
    return ch01::is_any_hit(kinds[k]) ? blocked_differing(blocked, r.blocked) : hits_differing(hits, r.hits[k]);
}

// One counted run of a tracer on ray set k: counters, and for a packet tracer its lanes and per-ray
// utilisation; its answers against chapter 13's.
row count(const accel& a, const tracer& t, const ray_sets& r, int k, std::vector<float>* per_ray) {
    const bool any = ch01::is_any_hit(kinds[k]);
    const std::vector<ray>& rays = r.rays[k];
    row out;
    out.rays = ch01::to_string(kinds[k]);
    out.tracer = t.label;
    out.ray_count = rays.size();
    std::vector<hit> hits(rays.size());
    std::vector<std::uint8_t> blocked(rays.size(), 2);
    counter_values c;
    if (const auto* p = dynamic_cast<const ch12::packet_accel_base*>(&a)) {
        std::vector<float> used;
        const ch12::lane_stats l = any ? p->any_lanes(rays, blocked, &used) : p->closest_lanes(rays, hits, &used);
        c = l.counts;
        out.walk = ch12::to_string(p->config().walk);
        out.lanes = p->config().lanes;
        out.tile = std::to_string(p->config().tile_w) + "x" + std::to_string(p->config().tile_h);
        out.packets = l.packets;
        out.mean_active = l.mean_active();
        out.active_fraction = out.mean_active / double(out.lanes);
        std::uint64_t visits = 0;
        for (std::uint64_t v : l.visits) visits += v;
        for (std::uint64_t v : l.visits) out.share.push_back(visits ? 100.0 * double(v) / double(visits) : 0.0);
        out.alone = std::size_t(std::count_if(used.begin(), used.end(), [](float f) { return f < 0.0f; }));
        if (per_ray) *per_ray = std::move(used);
    } else {
        const auto counted = any ? a.occluded_counted(rays, blocked) : a.intersect_counted(rays, hits);
        if (counted) c = *counted;
        out.walk = "single ray";
    }
    out.differing = differing(r, k, hits, blocked);
    out.nodes_per_ray = c.per_ray(c.nodes_visited);
    out.boxes_per_ray = c.per_ray(c.box_tests);
    out.tris_per_ray = c.per_ray(c.prim_tests);
    return out;
}

// The heat map: three panels side by side (primary | shadow | diffuse rays), each pixel the mean, over the
// rays of its 4x4 tile of pixels, of the busy fraction of the lanes of the packet that traced each ray. A
// secondary ray belongs to the pixel of the primary hit it starts from (one per hit, in pixel order). Grey:
// no ray (or a ray traced alone); black: the lines between the panels. The scale runs from 0 to 1.
image lane_map(const ray_sets& r, const std::vector<float> (&per_ray)[3], int width, int height) {
    constexpr int tile = 4, sep = 2;
    const int total = 3 * width + 2 * sep;
    std::vector<float> values(std::size_t(total) * std::size_t(height), 0.0f);
    std::vector<std::uint8_t> blank(values.size(), 0);  // 1: no ray, 2: separator
    std::vector<std::size_t> pixel_of_hit;
    for (std::size_t p = 0; p < r.primary_hits.size(); ++p)
        if (r.primary_hits[p].found()) pixel_of_hit.push_back(p);
    for (int k = 0; k < 3; ++k) {
        std::vector<float> pixel(std::size_t(width) * std::size_t(height), -1.0f);
        for (std::size_t i = 0; i < per_ray[k].size(); ++i) {
            const std::size_t p = k == 0 ? i : (i < pixel_of_hit.size() ? pixel_of_hit[i] : pixel.size());
            if (p < pixel.size()) pixel[p] = per_ray[k][i];
        }
        const int x0 = k * (width + sep);
        for (int ty = 0; ty < height; ty += tile)
            for (int tx = 0; tx < width; tx += tile) {
                double sum = 0;
                int n = 0;
                for (int y = ty; y < std::min(height, ty + tile); ++y)
                    for (int x = tx; x < std::min(width, tx + tile); ++x) {
                        const float v = pixel[std::size_t(y) * width + x];
                        if (v >= 0.0f) sum += v, ++n;
                    }
                for (int y = ty; y < std::min(height, ty + tile); ++y)
                    for (int x = tx; x < std::min(width, tx + tile); ++x) {
                        const std::size_t at = std::size_t(y) * total + std::size_t(x0 + x);
                        values[at] = n ? float(sum / n) : 0.0f;
                        blank[at] = n ? 0 : 1;
                    }
            }
    }
    // The separators hold the scale's ends (0 everywhere, 1 in one pixel), then are painted over.
    for (int y = 0; y < height; ++y)
        for (int s = 0; s < 2; ++s)
            for (int x = 0; x < sep; ++x) {
                const std::size_t at = std::size_t(y) * total + std::size_t((s + 1) * width + s * sep + x);
                blank[at] = 2;
                values[at] = y == 0 && s == 0 && x == 0 ? 1.0f : 0.0f;
            }
    const char* label = total >= 480   ? "busy share of 16 lanes per node: primary | shadow | diffuse"
                        : total >= 240 ? "primary | shadow | diffuse"
                                       : "busy lanes";
    image img = heat_map(values, total, height, label);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < total; ++x) {
            const std::uint8_t b = blank[std::size_t(y) * total + x];
            if (b == 1) img.at(x, y) = color(0.12f);
            if (b == 2) img.at(x, y) = color(0.0f);
        }
    return img;
}

std::vector<row> run_scene(const scene& s, const std::string& name, int width, int height, int repeats,
                           const fs::path& map_path, bool strips) {
    const ray_sets r = make_rays(s, width, height);
    std::printf("%s: %zu triangles; %d x %d primary rays, %zu shadow and %zu diffuse rays; one thread, median of %d "
                "interleaved rounds%s\n", name.c_str(), s.mesh.triangle_count(), width, height, r.rays[1].size(),
                r.rays[2].size(), repeats, strips ? "; packets of consecutive rays (--strips)" : "");
    std::printf("  %-18s %23s   %20s   %20s %7s\n", "", "Mrays/s", "x chapter 13's best", "busy lanes (of K)", "");
    std::printf("  %-18s %7s %7s %7s   %6s %6s %6s   %6s %6s %6s %7s\n", "tracer", "primary", "shadow", "diffuse",
                "prim.", "shadow", "diff.", "prim.", "shadow", "diff.", "differ");
    // Every tracer built, then timed in interleaved rounds: a warm-up round, then `repeats` rounds, each
    // tracing every ray set once with every tracer; a tracer's figure is its median over the rounds, so that
    // a slow spell of the machine falls on all tracers alike.
    const std::vector<tracer> list = tracers(strips ? 0 : width);
    std::vector<std::unique_ptr<accel>> built;
    for (const tracer& t : list) {
        built.push_back(make(t));
        built.back()->build(s);
    }
    std::vector<hit> hits[3];
    std::vector<std::uint8_t> blocked(r.rays[1].size());
    for (int k = 0; k < 3; ++k) hits[k].resize(r.rays[k].size());
    std::vector<std::vector<double>> ms(list.size() * 3);
    std::vector<std::size_t> wrong(list.size() * 3, 0);
    for (int round = 0; round <= repeats; ++round)
        for (std::size_t i = 0; i < list.size(); ++i)
            for (int k = 0; k < 3; ++k) {
                const double t = trace_ms(*built[i], r, k, hits[k], blocked);
                if (round > 0) ms[i * 3 + k].push_back(t);
                wrong[i * 3 + k] = std::max(wrong[i * 3 + k], differing(r, k, hits[k], blocked));
            }
    std::vector<row> rows;
    std::vector<float> per_ray[3];
    for (std::size_t i = 0; i < list.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            row x = count(*built[i], list[i], r, k, list[i].label == map_tracer ? &per_ray[k] : nullptr);
            x.scene = name;
            const double m = median(ms[i * 3 + k]);
            x.mrays = m > 0 ? double(r.rays[k].size()) / m * 1e-3 : 0.0;
            x.differing = std::max(x.differing, wrong[i * 3 + k]);  // the worst of the runs
            rows.push_back(std::move(x));
        }
    // Each row against chapter 13's faster row on the same rays.
    for (int k = 0; k < 3; ++k) {
        double best = 0;
        for (const row& x : rows)
            if (x.rays == ch01::to_string(kinds[k]) && x.lanes == 0) best = std::max(best, x.mrays);
        for (row& x : rows)
            if (x.rays == ch01::to_string(kinds[k])) x.vs_best = best > 0 ? x.mrays / best : 0.0;
    }
    for (std::size_t i = 0; i + 2 < rows.size(); i += 3) {
        const row *p = &rows[i], *sh = &rows[i + 1], *d = &rows[i + 2];
        std::printf("  %-18s %7.2f %7.2f %7.2f   %6.2f %6.2f %6.2f", p->tracer.c_str(), p->mrays, sh->mrays, d->mrays,
                    p->vs_best, sh->vs_best, d->vs_best);
        if (p->lanes)
            std::printf("   %6.2f %6.2f %6.2f", p->active_fraction, sh->active_fraction, d->active_fraction);
        else
            std::printf("   %6s %6s %6s", "-", "-", "-");
        std::printf(" %7zu\n", p->differing + sh->differing + d->differing);
    }
    if (!per_ray[0].empty()) {
        write_image(map_path, lane_map(r, per_ray, width, height));
        std::printf("  wrote %s\n", map_path.string().c_str());
    }
    std::fflush(stdout);
    return rows;
}

const char* const packets_header = "scene,rays,ray_count,tracer,walk,lanes,tile,mrays_s,vs_ch13_best,differing,alone,packets,"
                                   "active_lanes,active_fraction,nodes_per_ray,boxes_per_ray,tris_per_ray";

void write_tables(const std::vector<row>& rows, const fs::path& packets_csv, const fs::path& lanes_csv) {
    std::ostringstream p, l;
    p << packets_header << '\n';
    l << "scene,rays,tracer,k,share_percent\n";
    for (const row& r : rows) {
        p << r.scene << ',' << r.rays << ',' << r.ray_count << ',' << r.tracer << ',' << r.walk << ',';
        if (r.lanes) p << r.lanes;
        p << ',' << r.tile << ',' << r.mrays << ',' << r.vs_best << ',' << r.differing << ',' << r.alone << ',';
        if (r.lanes) p << r.packets << ',' << r.mean_active << ',' << r.active_fraction;
        else p << ",,";
        p << ',' << r.nodes_per_ray << ',' << r.boxes_per_ray << ',' << r.tris_per_ray << '\n';
        for (std::size_t k = 0; k < r.share.size(); ++k)
            l << r.scene << ',' << r.rays << ',' << r.tracer << ',' << k << ',' << r.share[k] << '\n';
    }
    write_text(packets_csv, with_machine(p.str(), this_machine(parallel_threads())));
    write_text(lanes_csv, l.str());  // counts only: the same on any machine
}

// Each packet tracer's speed over chapter 13's faster single-ray row on the same rays: one group of bars per
// tracer, one bar per scene and ray set.
void write_plot(const std::vector<row>& rows, const fs::path& svg) {
    bar_chart c{"Packets against chapter 13's best single-ray walk (8 wide, blocks of 4 or 8), one thread",
                "x chapter 13's best", {}, {}, {}, false};
    std::vector<std::string> series;
    for (const row& r : rows) {
        if (r.lanes && std::find(c.categories.begin(), c.categories.end(), r.tracer) == c.categories.end())
            c.categories.push_back(r.tracer);
        const std::string s = r.scene + " " + r.rays;
        if (std::find(series.begin(), series.end(), s) == series.end()) series.push_back(s);
    }
    for (const std::string& s : series) {
        std::vector<double> values;
        for (const std::string& t : c.categories) {
            double v = 0;
            for (const row& r : rows)
                if (r.scene + " " + r.rays == s && r.tracer == t) v = r.vs_best;
            values.push_back(v);
        }
        c.series_labels.push_back(s);
        c.values.push_back(values);
    }
    write_svg(svg, to_svg(c, 960, 480));
}

int run(int argc, const char* const* argv) {
    cli args("ch12", "Chapter 12, ray packets (" + std::string(track_name()) + "): chapter 13's single-ray walk over "
             "its 8-wide tree against packets of 4 to 256 rays (the masked, ranged and partition walks over chapter "
             "05's binary tree; K rays per child of the 8-wide tree, and its frustum alone); primary, shadow and diffuse rays on one "
             "thread; Mrays/s, busy lanes, nodes, boxes and triangles per ray; two tables, a plot and heat maps.");
    args.scene_option({"stadium", "bunny", "sponza"}, {"stadium", "bunny", "sponza"}, "the meshes where present")
        .option("width", "N", "", "primary rays per row (default 192, 96 with --quick); the packets' tiles are cut "
                "from its rows")
        .option("height", "N", "", "rows (default 3/4 of the width)")
        .option("repeats", "K", "5", "timed rounds after a warm-up round (each traces every ray set with every "
                "tracer); the median is reported")
        .output_options("write packets.csv, lanes.csv, vs_ch13.svg and SCENE_lanes.png into DIR/ "
                "(default out/12_packets/)")
        .flag("strips", "packets of consecutive rays (rows of 4 to 256) instead of tiles of the image")
        .flag("quick", "the teapot in a stadium only, 96 x 72 rays")
        .option("diagrams", "DIR", "", "only draw the chapter's figure into DIR/ (packet.svg; --force to replace it)");
    if (!args.parse(argc, argv)) return 0;
    if (draw_diagrams_if_asked(args, strahl::ch12::write_diagrams)) return 0;
    const bool quick = args.has("quick"), strips = args.has("strips");
    fs::path folder = "out/12_packets";
    const bool user_named = args.has("out");
    if (user_named) folder = args.get("out");
    const image_size size = read_image_size(args, quick ? 96 : 192, 4096);
    const int repeats = args.get_int("repeats");
    if (repeats < 1 || repeats > 100) throw usage_error("--repeats must lie in [1, 100]");
    std::vector<std::string> names = args.scene_names();
    if (quick) names = {"stadium"};

    // The scenes first, so that only the files this run writes are checked before the work.
    std::vector<std::pair<std::string, scene>> scenes;
    for (const std::string& name : names)
        if (auto s = course_scene(name)) scenes.emplace_back(name, std::move(*s));
    const fs::path packets_csv = folder / "packets.csv", lanes_csv = folder / "lanes.csv", svg = folder / "vs_ch13.svg";
    std::vector<fs::path> files = {packets_csv, lanes_csv, svg};
    for (const auto& sc : scenes) files.push_back(folder / (sc.first + "_lanes.png"));
    for (const fs::path& p : files) prepare_output(p, user_named, args.has("force"));

    const thread_limit one(1);
    std::printf("SIMD in this build (lanes: backend): %s\n", ch13::simd_widths().c_str());
    std::vector<row> rows;
    for (const auto& [name, s] : scenes) {
        const std::vector<row> r =
            run_scene(s, name, size.width, size.height, repeats, folder / (name + "_lanes.png"), strips);
        rows.insert(rows.end(), r.begin(), r.end());
    }
    write_tables(rows, packets_csv, lanes_csv);
    write_plot(rows, svg);
    std::printf("wrote %s, %s, %s\n", packets_csv.string().c_str(), lanes_csv.string().c_str(), svg.string().c_str());
    std::size_t wrong = 0;
    for (const row& r : rows) wrong += r.differing;
    if (wrong) {
        std::printf("%zu answers differ from chapter 13's: a bug\n", wrong);
        return 1;
    }
    std::printf("against Embree on the same rays: build/release/bin/race --accels ch13-bvh8-optimal,ch12-wide16-4x4,"
                "ch12-ranged16-8x8,embree-medium\n");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const bool exercises = std::string(track_name()) == "exercises";
    return guarded_main(exercises ? "ch12_exercise" : "ch12", run, argc, argv);
}
