// The race: every registered structure on every scene and ray set, measured the same way, Embree beside
// them in the same run. Prints a table and writes out/16_race/race.csv, race.md, plots and scene images.
#include "strahl/image.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/huge_pages.hpp"
#include "strahl/parallel.hpp"
#include "strahl/progress.hpp"
#include "strahl/race/brute_force.hpp"
#include "strahl/race/embree_accel.hpp"
#include "strahl/race/processes.hpp"
#include "strahl/race/reference_cache.hpp"
#include "strahl/race/registry.hpp"
#include "strahl/race/report.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <map>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

using namespace strahl;
using namespace strahl::race;

namespace {

std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream in(s);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty()) out.push_back(item);
    return out;
}

// cpu: the CPU one thread's timings are pinned to (-1: none).
std::string machine_name(int cpu) {
    return this_machine(1).cpu + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads" +
           (cpu >= 0 ? " (one thread's timings on CPU " + std::to_string(cpu) + ")" : std::string()) + "; " +
           embree_configuration().summary();
}

// Default scenes: the built-in ones, and the course's shared meshes where they sit beside the clone.
std::vector<std::string> default_scenes(bool quick) {
    std::vector<std::string> s = {"builtin:cornell", "builtin:teapot", "builtin:teapot_stadium", "builtin:soup"};
    if (quick) return s;
    for (const char* mesh : {"bunny.ply", "armadillo.obj", "ogre.obj", "sponza.obj"}) {
        const std::filesystem::path p = std::filesystem::path(STRAHL_SHARED_SCENES) / mesh;
        if (std::filesystem::exists(p)) s.push_back(p.string());
    }
    return s;
}

// The scene seen through its camera: primary hits shaded by how squarely they face the ray.
image primary_image(const scene& s, std::span<const ray> rays, const std::vector<hit>& hits, int w, int h) {
    image img(w, h);
    for (std::size_t i = 0; i < hits.size(); ++i) {
        if (!hits[i].found()) continue;
        const auto t = s.mesh.triangle(hits[i].prim);
        const vec3 n = glm::normalize(glm::cross(t[1] - t[0], t[2] - t[0]));
        const float facing = std::abs(glm::dot(n, glm::normalize(rays[i].dir)));
        img.pixels[i] = color(0.1f + 0.8f * facing);
    }
    return img;
}

// race --processes N: this program run N times as fresh processes, each into DIR/processes/K/ and sharing one
// reference cache; their rows combined into DIR's tables and plots (processes.hpp).
// With `more`, the processes already in DIR/processes/1, 2, ... (each with its race.csv) count too, and the
// new ones follow them.
int race_processes(int n, bool more, bool reverse, int argc, const char* const* argv,
                   const std::filesystem::path& out, const std::filesystem::path& cache_dir,
                   const std::vector<std::pair<std::string, std::string>>& compare, int threads, int cpu,
                   const std::vector<comparison>* against, const std::string& against_name) {
    // Each child gets this command line without --more, --reverse, --compare and --against, and its own --out.
    std::vector<std::string> base;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--compare" || a == "--against") ++i;
        else if (a != "--reverse" && a != "--more") base.push_back(a);
    }
    const auto folder_of = [&](int k) { return out / "processes" / std::to_string(k); };
    std::vector<std::vector<race_row>> results;
    int earlier = 0;
    while (more && std::filesystem::exists(folder_of(earlier + 1) / "race.csv"))
        results.push_back(read_race_csv(folder_of(++earlier) / "race.csv"));
    if (more)
        std::cout << "race: " << earlier << " earlier processes found in " << (out / "processes").string() << "/\n";
    // Without --more, an earlier run's processes beyond this run's n must not be combined by a later --more.
    for (int k = n + 1; !more && std::filesystem::exists(folder_of(k) / "race.log"); ++k)
        std::filesystem::remove_all(folder_of(k));
    std::cout << "race: " << n << " processes, each writing into " << (out / "processes").string() << "/\n";
    timer total;
    progress_bar progress("race", n, "processes");
    for (int k = earlier + 1; k <= earlier + n; ++k) {
        const std::filesystem::path folder = folder_of(k), log = folder / "race.log";
        prepare_output(log, false, false);
        std::filesystem::remove(folder / "race.csv");  // an earlier run's must not pass for this one's
        std::vector<std::string> args = base;
        for (const std::string& a : {std::string("--processes"), std::string("1"), std::string("--out"), folder.string(),
                                     std::string("--cache"), cache_dir.string()})
            args.push_back(a);
        if (reverse != (k % 2 == 0)) args.push_back("--reverse");
        const int rc = run_self(args, log);
        // Exit 1 with a race.csv: rows differing from brute force, which the combined table shows again.
        if (rc != 0 && !(rc == 1 && std::filesystem::exists(folder / "race.csv")))
            throw std::runtime_error("process " + std::to_string(k) + " of the race failed (exit status " +
                                     std::to_string(rc) + "): see " + log.string());
        results.push_back(read_race_csv(folder / "race.csv"));
        progress.add();
    }
    progress.finish();

    n += earlier;
    if (results.empty()) throw std::runtime_error("no processes to combine in " + (out / "processes").string());
    const std::vector<combined_row> combined = combine_processes(results);
    std::vector<race_row> rows;
    for (const combined_row& c : combined) rows.push_back(c.row);
    print_table(std::cout, rows);
    const std::string machine = machine_name(cpu);
    std::ofstream(out / "race.csv") << to_csv(rows, this_machine(threads));
    std::ofstream(out / "race.md") << to_markdown(rows, machine, n);
    std::ofstream(out / "spread.md") << spread_markdown(combined, n, machine);
    write_svg(out / "spread.svg", to_svg(spread_plot(results), 2, 700, 400));
    write_plots(out, rows);
    if (!compare.empty()) {
        std::vector<comparison> all;
        for (const auto& [a, b] : compare) {
            const std::vector<comparison> c = compare_rows(results, a, b);
            all.insert(all.end(), c.begin(), c.end());
        }
        std::ofstream(out / "compare.csv") << comparisons_csv(all);
        std::ofstream(out / "compare.md") << comparisons_markdown(all, machine);
        std::cout << '\n' << comparisons_markdown(all, machine);
        if (against) {
            const std::string md = stability_markdown(compare_verdicts(*against, all), against_name);
            std::ofstream(out / "verdicts.md") << md;
            std::cout << '\n' << md;
        }
    }
    // The scene images: the first process's (every process draws the same).
    for (const auto& f : std::filesystem::directory_iterator(folder_of(1)))
        if (f.path().extension() == ".png")
            std::filesystem::copy_file(f.path(), out / f.path().filename(),
                                       std::filesystem::copy_options::overwrite_existing);
    std::printf("\nmachine: %s; %d processes took %.1f s (%d combined)\n", machine.c_str(), n - earlier,
                total.seconds(), n);
    std::cout << "every figure above is the median across the processes; each figure's spread is in "
              << (out / "spread.md").string() << "\nwrote " << (out / "race.csv").string()
              << ", race.md, spread.md, spread.svg, speed_vs_build.svg, staircase.svg and scene images\n";
    const std::size_t wrong = wrong_rows(rows);
    if (wrong) {
        std::cout << wrong << " row(s) of course structures differ from brute force in some process: a bug.\n";
        return 1;
    }
    return 0;
}

int run(int argc, const char* const* argv) {
    cli args("race", "Every structure on every scene and ray set, measured the same way, Embree beside them.\n"
                     "Writes out/16_race/race.csv, race.md, speed_vs_build.svg, staircase.svg and one image per scene.");
    args.option("scenes", "LIST", "", "comma-separated scenes: builtin:NAME or mesh files (default: the built-in "
                                      "scenes, plus ../shared/scenes meshes unless --quick)")
        .option("accels", "LIST", "", "comma-separated structures (default: all; see strahl-trace --list)")
        .option("rays", "LIST", "primary,diffuse,shadow", "ray sets")
        .threads_option("1", "threads tracing, 1..1024 (1: the single-thread table)")
        .option("width", "W", "", "image width of the ray sets, 4..8192 and divisible by 4 (default 192, quick 96; "
                                  "8192 x 8192 needs over 13 GB of memory: refused where the machine has less)")
        .option("height", "H", "", "image height, even, 2..8192 (default 144, quick 72)")
        .option("repeats", "K", "5", "timed runs after a warm-up; the median is reported")
        .option("budget", "S", "", "seconds one query may take before repeats stop, at least one run (default 4, quick 2)")
        .option("out", "DIR", "out/16_race", "where the tables, plots and images go; brute force's answers are "
                                             "kept in DIR/reference_cache/ for the next run on the same scene and rays")
        .option("cache", "DIR", "", "where brute force's answers are kept (default: DIR/reference_cache/ of --out)")
        .option("cache-limit", "MB", "256", "after the race, remove the cache's least recently used files (not this "
                                            "run's) until it holds at most MB megabytes")
        .flag("no-cache", "trace brute force's answers afresh, neither reading nor writing the cache")
        .option("processes", "N", "1", "run the race N times, each a fresh process (every second one measuring the "
                                       "structures in reverse order), and report each figure's median across them; "
                                       "writes DIR/spread.md, DIR/spread.svg and each process's files under DIR/processes/")
        .flag("more", "add the --processes N (default 1; 0: none, only combine) to those already in "
                      "DIR/processes/ and combine them all")
        .flag("reverse", "measure the structures in reverse order")
        .option("compare", "A:B,...", "", "with --processes N (at least 5) or --more: for each pair of rows, A's speed over "
                                          "B's within each process and the verdict (faster: A ahead in every process; "
                                          "slower: behind in every one; else level); writes DIR/compare.csv and compare.md")
        .option("against", "CSV", "", "with --compare: an earlier run's compare.csv; writes DIR/verdicts.md, how many of "
                                      "the verdicts both runs give held, and the ones that changed")
        .option("cpu", "N", "", "with one thread, time every build and query on CPU N alone (default: the "
                                "lowest-numbered CPU the race may use, the same in every process; none: wherever the "
                                "system puts it)")
        .flag("plain-pages", "the course's builds allocate without advice to the kernel (no huge pages, no "
                             "faulting in at once; strahl/huge_pages.hpp): what the advice changes")
        .flag("quick", "built-in scenes only, 96x72 rays, 3 repeats: what ./course run runs");
    if (!args.parse(argc, argv)) return 0;
    const bool quick = args.has("quick");
    const int threads = read_threads(args, 1);
    const int w = args.has("width") ? args.get_int("width") : quick ? 96 : 192;
    const int h = args.has("height") ? args.get_int("height") : quick ? 72 : 144;
    if (w < 4 || h < 2 || w > 8192 || h > 8192 || w % 4 || h % 2)
        throw usage_error("need a width in 4..8192 divisible by 4 and an even height in 2..8192");
    timing_rules rules;
    rules.repeats = args.has("repeats") ? args.get_int("repeats") : quick ? 3 : 5;
    rules.budget_s = args.has("budget") ? args.get_double("budget") : quick ? 2.0 : 4.0;
    rules.threads = threads;
    if (args.has("cpu") && args.get("cpu") == "none") rules.cpu = -1;
    else if (args.has("cpu")) {
        rules.cpu = args.get_int("cpu");
        if (!cpu_allowed(rules.cpu))
            throw usage_error("--cpu " + args.get("cpu") + ": not a CPU this process may run on (none: not pinned)");
    } else rules.cpu = first_allowed_cpu();
    if (threads > 1) rules.cpu = -1;  // threads spread over the CPUs as the system places them
    if (rules.repeats < 1 || rules.budget_s <= 0.0) throw usage_error("--repeats and --budget must be positive");
    const double cache_limit_mb = args.get_double("cache-limit");
    if (!(cache_limit_mb >= 0.0)) throw usage_error("--cache-limit must be a number of megabytes >= 0");
    const int processes = args.get_int("processes");
    if (processes < (args.has("more") ? 0 : 1) || processes > 1000)
        throw usage_error("--processes must be in 1..1000 (0 with --more: combine the processes already there)");
    // Per pixel of a scene: the primary rays and their answers, one further ray set with brute force's
    // closest and any-hit answers and a structure's, the cache's read buffer and the image: under 200 bytes.
    check_memory(std::uint64_t(w) * std::uint64_t(h) * 200,
                 "the race's " + std::to_string(w) + " x " + std::to_string(h) + " ray sets");
    std::vector<std::pair<std::string, std::string>> compare;
    if (args.has("compare")) {
        const std::vector<std::string> listed = args.has("accels") ? split(args.get("accels")) : std::vector<std::string>{};
        for (const std::string& pair : split(args.get("compare"))) {
            const std::size_t colon = pair.find(':');
            if (colon == std::string::npos || colon == 0 || colon + 1 == pair.size() ||
                pair.find(':', colon + 1) != std::string::npos)
                throw usage_error("--compare takes pairs of rows A:B, comma-separated (not '" + pair + "')");
            compare.emplace_back(pair.substr(0, colon), pair.substr(colon + 1));
            // Rows the race will have: among --accels, or registered (strahl-trace --list).
            for (const std::string& name : {compare.back().first, compare.back().second}) {
                bool known = args.has("accels") ? std::find(listed.begin(), listed.end(), name) != listed.end() : true;
                if (!args.has("accels")) try {
                        find_accel(name, registry_options{threads, w});
                    } catch (const std::exception&) {
                        known = false;
                    }
                if (!known) throw usage_error("--compare: '" + name + "' is not a row of this race (--accels, or strahl-trace --list)");
            }
        }
        if (processes < 2 && !args.has("more"))
            throw usage_error("--compare needs several processes: --processes N (at least " +
                              std::to_string(min_processes) + " for a verdict) or --more");
    }
    // The earlier verdicts, read now: a file that is not one is found before the race, not after it.
    std::vector<comparison> against;
    if (args.has("against")) {
        if (compare.empty()) throw usage_error("--against needs --compare (the pairs whose verdicts to hold against it)");
        against = read_comparisons_csv(args.get("against"));
    }
    // Every scene file there, and every built-in name known, before anything is created or traced: a missing
    // one found after the others are loaded (or after an hour of processes) is time lost.
    const std::vector<std::string> scenes = args.has("scenes") ? split(args.get("scenes")) : default_scenes(quick);
    for (const std::string& spec : scenes) {
        if (spec.starts_with("builtin:")) {
            const std::vector<std::string> known = builtin_scene_names();
            if (std::find(known.begin(), known.end(), spec.substr(8)) == known.end()) (void)load_scene_spec(spec);
        } else if (!std::filesystem::exists(spec)) {
            throw std::runtime_error(spec + ": no such file");
        }
    }
    // Only now, with the whole command line found good, anything is created.
    if (args.has("plain-pages")) page_advice = false;
    const std::filesystem::path out = args.get("out");
    prepare_output(out / "race.csv", false, false);
    const std::filesystem::path cache_dir = args.has("cache") ? std::filesystem::path(args.get("cache")) : out / "reference_cache";
    const auto started = std::filesystem::file_time_type::clock::now();
    if (processes > 1 || args.has("more"))
        return race_processes(processes, args.has("more"), args.has("reverse"), argc, argv, out, cache_dir, compare,
                              threads, rules.cpu, args.has("against") ? &against : nullptr,
                              args.has("against") ? args.get("against") : std::string());

    std::vector<ray_kind> kinds;
    for (const std::string& k : split(args.get("rays"))) kinds.push_back(parse_ray_kind(k));
    const registry_options reg{threads, w};
    std::vector<accel_entry> entries;
    if (args.has("accels")) for (const std::string& n : split(args.get("accels"))) entries.push_back(find_accel(n, reg));
    else entries = registered_accels(reg);
    if (args.has("reverse")) std::reverse(entries.begin(), entries.end());
    if (!embree_available()) std::cout << "Embree 3 was not found at build time: the race runs without it.\n";
    else std::cout << "machine: " << machine_name(rules.cpu) << " (Embree's queries run with flush-to-zero and "
                   << "denormals-are-zero set, as its documentation asks)\n";
    if (args.has("plain-pages")) std::cout << "builds without page advice (--plain-pages)\n";
    std::cout << "race: " << w << "x" << h << " rays per set, " << threads << " thread" << (threads > 1 ? "s" : "")
              << ", median of " << rules.repeats << " after a warm-up (" << rules.budget_s << " s budget per query)\n";

    const int ref_threads = int(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<race_row> rows;
    timer total;
    int cached_sets[3] = {0, 0, 0};  // brute force's answer sets: read from the cache, traced, stale
    progress_bar progress("race", scenes.size() * kinds.size() * entries.size(), "rows");
    for (const std::string& spec : scenes) {
        const scene s = load_scene_spec(spec, &std::cout);
        const std::string scene_name = s.name.empty() ? spec : s.name;
        brute_force exact;
        exact.build(s);
        // Brute force's answers, the reference every structure is checked against: traced on both cores, or
        // read from the cache of an earlier run (whose files are spot-checked by brute force).
        reference_cache cache(args.has("no-cache") ? std::filesystem::path() : cache_dir, s, exact,
                              ref_threads);
        // Other oracles (brute force with chapter 15's triangle tests), made when a row first needs one.
        std::map<std::string, std::pair<std::unique_ptr<accel>, std::unique_ptr<reference_cache>>> oracles;
        const auto oracle_cache = [&](const std::string& name) -> reference_cache& {
            auto it = oracles.find(name);
            if (it == oracles.end()) {
                std::unique_ptr<accel> a = find_accel(name).make();
                a->build(s);
                auto c = std::make_unique<reference_cache>(args.has("no-cache") ? std::filesystem::path() : cache_dir,
                                                           s, *a, ref_threads);
                it = oracles.emplace(name, std::pair{std::move(a), std::move(c)}).first;
            }
            return *it->second.second;
        };
        const std::vector<ray> primary = primary_rays(s, w, h);
        const std::vector<hit> primary_hits = cache.closest("primary", primary);
        write_image(out / (std::filesystem::path(scene_name).stem().string() + ".png"),
                    primary_image(s, primary, primary_hits, w, h));

        for (ray_kind kind : kinds) {
            const std::vector<ray> rays = kind == ray_kind::primary ? primary
                                          : secondary_rays(kind, s, primary, primary_hits, 1);
            // Shadow rays are timed on any hit only, so they need no closest-hit answers.
            reference ref{kind == ray_kind::primary  ? primary_hits
                          : kind == ray_kind::shadow ? std::vector<hit>()
                                                     : cache.closest(to_string(kind), rays),
                          cache.any(to_string(kind), rays)};
            // Linear-cost structures (brute force) on big scenes trace an evenly spread sample of the rays:
            // at most 5e8 triangle tests a run.
            const std::size_t linear_limit = std::max<std::size_t>(256, std::size_t(5e8 / double(std::max<std::size_t>(1, s.mesh.triangle_count()))));
            std::map<std::string, reference> other_refs;  // by oracle
            for (const accel_entry& e : entries) {
                std::unique_ptr<accel> a = e.make();
                race_row r;
                r.scene = scene_name;
                r.triangles = s.mesh.triangle_count();
                r.accel = a->name();
                r.chapter = e.chapter;
                r.exact = a->exact();
                r.ray_set = to_string(kind);
                r.build_ms = measure_build(*a, s, rules);
                r.memory_bytes = a->memory_bytes();
                r.sah = a->sah_cost();
                if (e.oracle != "brute" && !other_refs.count(e.oracle)) {
                    reference_cache& c = oracle_cache(e.oracle);
                    other_refs[e.oracle] = reference{kind == ray_kind::shadow ? std::vector<hit>()
                                                                              : c.closest(to_string(kind), rays),
                                                     c.any(to_string(kind), rays)};
                }
                const reference& base = e.oracle == "brute" ? ref : other_refs.at(e.oracle);
                std::span<const ray> traced = rays;
                reference sub;
                std::vector<ray> sampled;
                if (e.linear && rays.size() > linear_limit) {
                    const std::size_t stride = (rays.size() + linear_limit - 1) / linear_limit;
                    for (std::size_t i = 0; i < rays.size(); i += stride) {
                        sampled.push_back(rays[i]);
                        if (!base.closest.empty()) sub.closest.push_back(base.closest[i]);
                        sub.any.push_back(base.any[i]);
                    }
                    traced = sampled;
                    r.ray_set += "~";  // marks a sampled row in the table
                }
                const reference& compare = sampled.empty() ? base : sub;
                // Shadow rays ask for any hit only.
                r.any = measure_any(*a, traced, compare.any, rules);
                if (kind != ray_kind::shadow) r.closest = measure_closest(*a, traced, compare.closest, rules);
                rows.push_back(r);
                progress.add();
            }
        }
        cached_sets[0] += cache.loaded(), cached_sets[1] += cache.traced(), cached_sets[2] += cache.stale();
        for (const auto& [name, o] : oracles)
            cached_sets[0] += o.second->loaded(), cached_sets[1] += o.second->traced(), cached_sets[2] += o.second->stale();
    }
    progress.finish();
    if (!args.has("no-cache")) {
        std::cout << "reference: " << cached_sets[0] << " answer sets from " << cache_dir.string()
                  << ", " << cached_sets[1] << " traced by brute force (" << cached_sets[2] << " stale files replaced)\n";
        const std::uintmax_t limit = std::uintmax_t(std::min(cache_limit_mb, 1e12) * 1e6);
        const pruned_files p = prune_reference_cache(cache_dir, limit, started);
        if (p.files)
            std::printf("reference cache: removed %d files (%.1f MB) used least recently, to keep it under %g MB "
                        "(--cache-limit)\n", p.files, double(p.bytes) / 1e6, cache_limit_mb);
    }
    add_embree_ratios(rows);
    print_table(std::cout, rows);
    const std::string machine = machine_name(rules.cpu);
    std::ofstream(out / "race.csv") << to_csv(rows, this_machine(threads));
    std::ofstream(out / "race.md") << to_markdown(rows, machine);
    write_plots(out, rows);
    std::printf("\nmachine: %s; the race took %.1f s\n", machine.c_str(), total.seconds());
    std::cout << "wrote " << (out / "race.csv").string() << ", race.md, speed_vs_build.svg, staircase.svg and scene images\n";
    const std::size_t wrong = wrong_rows(rows);
    if (wrong) {
        std::cout << wrong << " row(s) of course structures differ from brute force: a bug.\n";
        return 1;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) { return guarded_main("race", run, argc, argv); }
