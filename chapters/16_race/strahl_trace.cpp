// strahl-trace: the ray-query tool. Loads a scene, builds one registered structure, traces a ray set read
// from a file or generated, writes the hits, and prints build time, trace time and Mrays/s.
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/race/brute_force.hpp"
#include "strahl/race/ray_io.hpp"
#include "strahl/race/ray_sets.hpp"
#include "strahl/race/registry.hpp"
#include "strahl/timer.hpp"
#include <cstdio>
#include <iostream>

using namespace strahl;
using namespace strahl::race;

namespace {

// An any-hit result in a hits file: an occluded ray is written as t = 0 with this primitive id ("some
// primitive"), an unoccluded one as a miss.
constexpr std::uint32_t occluded_id = 0xFFFFFFFEu;

int run(int argc, const char* const* argv) {
    cli args("strahl-trace",
             "Traces rays through one acceleration structure: --scene FILE|builtin:NAME --accel NAME\n"
             "(--rays FILE | --gen primary|diffuse|shadow). Shadow rays (and --any-hit) ask for any hit.\n"
             "Formats: chapters/16_race/README.md. Exit 0 on success, 1 on an error, 2 on a bad command line.");
    args.flag("list", "list the structures, one a line: name, chapter, description")
        .option("scene", "FILE|builtin:NAME", "", "the scene: a mesh file or builtin:cornell|teapot|teapot_stadium|sphere|soup|clustered_soup")
        .option("accel", "NAME", "brute", "the structure (see --list)")
        .option("rays", "FILE", "", "trace the rays of this file (STRAHLR1)")
        .option("gen", "KIND", "", "generate the rays instead: primary, diffuse or shadow")
        .option("width", "W", "256", "image width of generated rays")
        .option("height", "H", "256", "image height of generated rays")
        .option("seed", "S", "1", "seed of diffuse rays")
        .option("rays-out", "FILE", "", "write the rays traced to this file")
        .option("out", "FILE", "", "write the hits to this file (STRAHLH1)")
        .flag("any-hit", "ask for any hit instead of the closest (shadow rays always do)")
        .option("threads", "N", "1", "threads tracing (the structure is built once)")
        .option("repeat", "K", "1", "trace K times, report the median")
        .flag("force", "replace existing output files");
    if (!args.parse(argc, argv)) return 0;
    const int threads = args.get_int("threads"), repeat = args.get_int("repeat");
    if (threads < 1 || repeat < 1) throw usage_error("--threads and --repeat must be at least 1");
    const registry_options reg{threads, args.get_int("width")};

    if (args.has("list")) {
        for (const accel_entry& e : registered_accels(reg))
            std::printf("%-24s ch%-3s %s\n", e.name.c_str(), e.chapter.c_str(), e.description.c_str());
        return 0;
    }
    if (!args.has("scene")) throw usage_error("--scene is required");
    if (args.has("rays") == args.has("gen")) throw usage_error("give exactly one of --rays FILE and --gen KIND");
    // Two files named alike would be written over each other (or the rays read over): refused, even with --force.
    const auto same = [](const std::string& a, const std::string& b) {
        std::error_code ec;
        const std::filesystem::path pa = std::filesystem::weakly_canonical(a, ec), pb = std::filesystem::weakly_canonical(b, ec);
        return a == b || (!pa.empty() && pa == pb);
    };
    if (args.has("out") && args.has("rays-out") && same(args.get("out"), args.get("rays-out")))
        throw usage_error("--out and --rays-out name the same file, " + args.get("out") + ": give two files");
    for (const char* o : {"out", "rays-out"})
        if (args.has(o) && args.has("rays") && same(args.get(o), args.get("rays")))
            throw usage_error(std::string("--") + o + " names the rays file it would read, " + args.get("rays"));
    for (const char* o : {"out", "rays-out"})
        if (args.has(o)) prepare_output(args.get(o), true, args.has("force"));
    const accel_entry entry = find_accel(args.get("accel"), reg);

    const scene s = load_scene_spec(args.get("scene"), &std::cout);
    std::vector<ray> rays;
    bool any_hit = args.has("any-hit");
    if (args.has("rays")) {
        rays = read_rays(args.get("rays"));
    } else {
        const ray_kind kind = parse_ray_kind(args.get("gen"));
        const int w = args.get_int("width"), h = args.get_int("height");
        if (w < 1 || h < 1 || w > 16384 || h > 16384) throw usage_error("--width and --height must lie in 1..16384");
        brute_force exact;
        exact.build(s);
        rays = make_rays(kind, s, w, h, std::uint64_t(args.get_int("seed")), exact, threads);
        any_hit = any_hit || is_any_hit(kind);
    }
    if (args.has("rays-out")) write_rays(args.get("rays-out"), rays);

    std::unique_ptr<accel> a = entry.make();
    timer build_timer;
    a->build(s);
    const double build_ms = build_timer.milliseconds();

    std::vector<hit> hits(rays.size());
    std::vector<std::uint8_t> blocked(rays.size());
    std::vector<double> ms;
    for (int k = 0; k < repeat; ++k) {
        timer t;
        if (any_hit) trace_any(*a, rays, blocked, threads);
        else trace_closest(*a, rays, hits, threads);
        ms.push_back(t.milliseconds());
    }
    const double trace_ms = median(ms);

    std::size_t found = 0;
    double sum_t = 0.0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        if (any_hit) {
            hits[i] = blocked[i] ? hit{0.0f, occluded_id, 0.0f, 0.0f, invalid_id} : hit{};
            found += blocked[i];
        } else if (hits[i].found()) {
            ++found;
            sum_t += hits[i].t;
        }
    }
    if (args.has("out")) write_hits(args.get("out"), hits);

    std::printf("structure   %s\n", a->name().c_str());
    std::printf("rays        %zu (%s)\n", rays.size(), any_hit ? "any hit" : "closest hit");
    std::printf("build       %.2f ms\n", build_ms);
    std::printf("trace       %.2f ms (median of %d, %d thread%s)\n", trace_ms, repeat, threads, threads > 1 ? "s" : "");
    std::printf("speed       %.3f Mrays/s\n", trace_ms > 0.0 ? double(rays.size()) / trace_ms / 1e3 : 0.0);
    std::printf("%-11s %zu (%.1f%%)\n", any_hit ? "occluded" : "hits", found,
                rays.empty() ? 0.0 : 100.0 * double(found) / double(rays.size()));
    if (!any_hit) std::printf("mean t      %.6g\n", found ? sum_t / double(found) : 0.0);
    std::printf("memory      %.2f MiB\n", double(a->memory_bytes()) / (1024.0 * 1024.0));
    return 0;
}

}  // namespace

int main(int argc, char** argv) { return guarded_main("strahl-trace", run, argc, argv); }
