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

// The largest --width and --height of generated rays.
constexpr int max_side = 16384;

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
        .option("width", "W", "256", "image width of generated rays, 1..16384 (16384 x 16384 rays need 14 GB of memory or more: "
                "refused where the machine has less)")
        .option("height", "H", "256", "image height of generated rays, 1..16384")
        .option("seed", "S", "1", "seed of diffuse rays")
        .option("rays-out", "FILE", "", "write the rays traced to this file")
        .option("out", "FILE", "", "write the hits to this file (STRAHLH1)")
        .flag("any-hit", "ask for any hit instead of the closest (shadow rays always do)")
        .threads_option("1", "threads tracing, 1..1024 (the structure is built once)")
        .option("repeat", "K", "1", "trace K times, report the median")
        .flag("force", "replace existing output files");
    if (!args.parse(argc, argv)) return 0;
    const int threads = read_threads(args, 1), repeat = args.get_int("repeat");
    if (repeat < 1) throw usage_error("--repeat must be at least 1");
    // The image size is checked before anything uses it, --list included: the width also sets Embree's
    // packet entry, which a width of 0 would drop from the list without a word.
    const int w = args.get_int("width"), h = args.get_int("height");
    if (w < 1 || h < 1 || w > max_side || h > max_side)
        throw usage_error("--width and --height must lie in 1.." + std::to_string(max_side));
    const registry_options reg{threads, w};

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
    const accel_entry entry = find_accel(args.get("accel"), reg);

    // The memory the rays, their answers and the files written take, checked before any is allocated: at
    // 16384 x 16384, 14 to 41 GB, more than many machines have.
    const std::uint64_t per_ray = sizeof(ray) + sizeof(hit) + 1 + (args.has("rays-out") ? 32 : 0) +
                                  (args.has("out") ? 16 : 0);
    if (args.has("rays")) {
        std::error_code ec;
        const std::uintmax_t bytes = std::filesystem::file_size(args.get("rays"), ec);
        if (!ec && bytes >= 16)  // (else read_rays below says what is wrong with the file)
            check_memory(bytes + (bytes - 16) / 32 * per_ray, "tracing the " + std::to_string((bytes - 16) / 32) +
                                                                  " rays of '" + args.get("rays") + "'");
    } else {
        // Secondary rays are made from primary rays and their hits, all held at once.
        const bool secondary = parse_ray_kind(args.get("gen")) != ray_kind::primary;
        check_memory(std::uint64_t(w) * std::uint64_t(h) * (per_ray + (secondary ? sizeof(ray) + sizeof(hit) : 0)),
                     std::to_string(w) + " x " + std::to_string(h) + " " + args.get("gen") + " rays");
    }
    // Only now, with the whole command line found good, anything is created.
    for (const char* o : {"out", "rays-out"})
        if (args.has(o)) prepare_output(args.get(o), true, args.has("force"));

    const scene s = load_scene_spec(args.get("scene"), &std::cout);
    std::vector<ray> rays;
    bool any_hit = args.has("any-hit");
    if (args.has("rays")) {
        rays = read_rays(args.get("rays"));
    } else {
        const ray_kind kind = parse_ray_kind(args.get("gen"));
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
