#include "strahl/race/processes.hpp"
#include "strahl/program.hpp"
#include "strahl/timer.hpp"  // median
#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <map>
#include <optional>
#include <sstream>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>

extern char** environ;

namespace strahl::race {

namespace {

std::optional<double> optional_number(const std::filesystem::path& file, const csv_row& row, std::size_t k) {
    if (row.cells.at(k).empty()) return std::nullopt;
    return csv_number(file, row, k);
}

// The closest or any-hit half of a CSV row: columns first (Mrays/s), first + 1 (runs), then the optional
// figures at the given columns, and the row's ray count (column 6); an empty Mrays/s cell means the query
// was not run.
query_result read_query(const std::filesystem::path& file, const csv_row& row, std::size_t first, std::size_t box,
                        std::size_t prim, std::optional<std::size_t> nodes,
                        std::size_t differing) {
    query_result q;
    if (row.cells.at(first).empty()) return q;
    q.mrays = csv_number(file, row, first);
    q.runs = int(csv_number(file, row, first + 1));
    q.rays = std::size_t(csv_number(file, row, 6));
    q.box_per_ray = optional_number(file, row, box);
    q.prim_per_ray = optional_number(file, row, prim);
    if (nodes) q.nodes_per_ray = optional_number(file, row, *nodes);
    q.differing = std::size_t(csv_number(file, row, differing));
    return q;
}

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

std::string key_of(const race_row& r) { return r.scene + "\n" + r.ray_set + "\n" + r.accel; }

spread spread_of(std::vector<double> v) {
    spread s;
    if (v.empty()) return s;
    s.samples = int(v.size());
    s.median = median(v);
    s.min = *std::min_element(v.begin(), v.end());
    s.max = *std::max_element(v.begin(), v.end());
    return s;
}

std::string cell(const spread& s, const char* f) {
    if (s.samples == 0) return "-";
    char buf[128];
    if (s.samples == 1) std::snprintf(buf, sizeof buf, f, s.median);
    else {
        const std::string form = std::string(f) + " (" + f + " to " + f + ")";
        std::snprintf(buf, sizeof buf, form.c_str(), s.median, s.min, s.max);
    }
    return buf;
}

}  // namespace

std::vector<race_row> read_race_csv(const std::filesystem::path& file) {
    std::vector<race_row> rows;
    for (const csv_row& c : read_csv(file, race_csv_header, race_csv_machine_header, "a race.csv written by the race")) {
        race_row r;
        r.scene = c.cells[0];
        r.triangles = std::size_t(csv_number(file, c, 1));
        r.accel = c.cells[2];
        r.chapter = c.cells[3];
        r.exact = c.cells[4] == "1";
        r.ray_set = c.cells[5];
        r.build_ms = csv_number(file, c, 7);
        r.memory_bytes = std::size_t(csv_number(file, c, 8));
        r.sah = optional_number(file, c, 9);
        r.closest = read_query(file, c, 10, 13, 14, 15, 16);
        r.closest_vs_embree = optional_number(file, c, 12);
        r.any = read_query(file, c, 17, 20, 21, std::nullopt, 22);
        r.any_vs_embree = optional_number(file, c, 19);
        if (c.cells.size() > 23) r.cpu = c.cells[23];
        rows.push_back(std::move(r));
    }
    return rows;
}

std::vector<combined_row> combine_processes(const std::vector<std::vector<race_row>>& processes) {
    // Every process's rows under their key, in the order first seen.
    std::vector<std::string> order;
    std::map<std::string, std::vector<const race_row*>> samples;
    for (const std::vector<race_row>& rows : processes)
        for (const race_row& r : rows) {
            auto& v = samples[key_of(r)];
            if (v.empty()) order.push_back(key_of(r));
            v.push_back(&r);
        }
    std::vector<combined_row> out;
    for (const std::string& key : order) {
        const std::vector<const race_row*>& v = samples[key];
        for (const race_row* r : v) {
            // Only the same race combines: the same scene (its triangle count) and the same rays (their count)...
            if (r->triangles != v.front()->triangles || std::max(r->closest.rays, r->any.rays) !=
                                                            std::max(v.front()->closest.rays, v.front()->any.rays))
                throw std::runtime_error("the processes did not run the same race: " + r->scene + ", " + r->ray_set +
                                         ", " + r->accel + " has other triangles or rays in one of them (run without --more "
                                         "to start afresh)");
            // ... on one machine: processes that name their CPUs must name the same one.
            if (!r->cpu.empty() && !v.front()->cpu.empty() && r->cpu != v.front()->cpu)
                throw std::runtime_error("the processes ran on different CPUs (" + v.front()->cpu + ", " + r->cpu +
                                         "): one table, one machine (run without --more to start afresh)");
        }
        combined_row c;
        c.row = *v.front();
        std::vector<double> build, closest, any, closest_ratio, any_ratio;
        c.row.closest.runs = c.row.any.runs = 0;
        for (const race_row* r : v) {
            build.push_back(r->build_ms);
            if (r->closest.runs) closest.push_back(r->closest.mrays);
            if (r->any.runs) any.push_back(r->any.mrays);
            if (r->closest_vs_embree) closest_ratio.push_back(*r->closest_vs_embree);
            if (r->any_vs_embree) any_ratio.push_back(*r->any_vs_embree);
            c.row.closest.runs += r->closest.runs;
            c.row.any.runs += r->any.runs;
            c.row.closest.differing = std::max(c.row.closest.differing, r->closest.differing);
            c.row.any.differing = std::max(c.row.any.differing, r->any.differing);
        }
        c.build_ms = spread_of(build);
        c.closest = spread_of(closest);
        c.any = spread_of(any);
        c.closest_vs_embree = spread_of(closest_ratio);
        c.any_vs_embree = spread_of(any_ratio);
        c.row.build_ms = c.build_ms.median;
        c.row.closest.mrays = c.closest.median;
        c.row.any.mrays = c.any.median;
        c.row.closest_vs_embree = c.closest_vs_embree.samples ? std::optional(c.closest_vs_embree.median) : std::nullopt;
        c.row.any_vs_embree = c.any_vs_embree.samples ? std::optional(c.any_vs_embree.median) : std::nullopt;
        out.push_back(std::move(c));
    }
    return out;
}

std::string spread_markdown(const std::vector<combined_row>& rows, int processes, const std::string& machine) {
    std::ostringstream out;
    out << "# The race's spread across processes\n\nMachine: " << machine << ". " << processes
        << " fresh processes, every second one measuring the structures in reverse order. Each cell: the median "
           "across processes (the smallest and the largest in brackets) of the figure each process measured (itself "
           "a median of timed runs). xEmbree: each process's own speed ratio to embree-medium. n: processes that "
           "measured the row.\n\n"
        << "| scene | structure | rays | n | build ms | closest Mrays/s | xEmbree | any-hit Mrays/s | xEmbree |\n"
        << "|---|---|---|---:|---:|---:|---:|---:|---:|\n";
    for (const combined_row& c : rows)
        out << "| " << c.row.scene << " | " << c.row.accel << " | " << c.row.ray_set << " | " << c.build_ms.samples
            << " | " << cell(c.build_ms, "%.2f") << " | " << cell(c.closest, "%.3f") << " | "
            << cell(c.closest_vs_embree, "%.3g") << " | " << cell(c.any, "%.3f") << " | "
            << cell(c.any_vs_embree, "%.3g") << " |\n";
    return out.str();
}

std::string verdict_of(const std::vector<double>& ratios) {
    if (int(ratios.size()) < min_processes) return "too few processes";
    const auto [lo, hi] = std::minmax_element(ratios.begin(), ratios.end());
    return *lo > 1.0 ? "faster" : *hi < 1.0 ? "slower" : "level";
}

std::vector<comparison> compare_rows(const std::vector<std::vector<race_row>>& processes, const std::string& a,
                                     const std::string& b) {
    for (const std::string& name : {a, b}) {
        bool found = false;
        for (const auto& rows : processes)
            for (const race_row& r : rows) found = found || r.accel == name;
        if (!found) throw std::invalid_argument("--compare: no process of the race measured '" + name + "'");
    }
    std::vector<comparison> out;
    const auto find = [&](const std::vector<race_row>& rows, const race_row& like, const std::string& name) {
        for (const race_row& r : rows)
            if (r.accel == name && r.scene == like.scene && r.ray_set == like.ray_set) return &r;
        return static_cast<const race_row*>(nullptr);
    };
    for (const race_row& first : processes.front()) {
        if (first.accel != a) continue;
        for (const bool any : {false, true}) {
            comparison c{first.scene, first.ray_set, any ? "any" : "closest", a, b, {}, {}, {}};
            for (const auto& rows : processes) {
                const race_row *ra = find(rows, first, a), *rb = find(rows, first, b);
                if (!ra || !rb) continue;
                const query_result &qa = any ? ra->any : ra->closest, &qb = any ? rb->any : rb->closest;
                if (qa.runs && qb.runs && qb.mrays > 0.0) c.ratios.push_back(qa.mrays / qb.mrays);
            }
            if (c.ratios.empty()) continue;
            c.ratio = spread_of(c.ratios);
            c.verdict = verdict_of(c.ratios);
            out.push_back(std::move(c));
        }
    }
    return out;
}

std::string comparisons_csv(const std::vector<comparison>& cs) {
    std::ostringstream out;
    out << compare_csv_header << '\n';
    for (const comparison& c : cs) {
        out << csv_field(c.scene) << ',' << csv_field(c.ray_set) << ',' << c.query << ',' << csv_field(c.a) << ','
            << csv_field(c.b) << ',' << c.ratios.size() << ',' << num(c.ratio.median) << ','
            << num(c.ratio.min) << ',' << num(c.ratio.max) << ',' << c.verdict << ',';
        for (std::size_t i = 0; i < c.ratios.size(); ++i) out << (i ? " " : "") << num(c.ratios[i]);
        out << '\n';
    }
    return out.str();
}

std::string comparisons_markdown(const std::vector<comparison>& cs, const std::string& machine) {
    std::ostringstream out;
    out << "# Paired comparisons\n\nMachine: " << machine << ". A / B: the ratio of A's Mrays/s to B's within "
           "each process, the median across processes (the smallest and the largest in brackets). Verdict: "
           "faster where A beat B in every process, slower where B beat A in every one, level otherwise (at least "
        << min_processes << " processes).\n\n| scene | rays | query | A | B | n | A / B | verdict |\n"
        << "|---|---|---|---|---|---:|---:|---|\n";
    for (const comparison& c : cs)
        out << "| " << c.scene << " | " << c.ray_set << " | " << c.query << " | " << c.a << " | " << c.b << " | "
            << c.ratios.size() << " | " << cell(c.ratio, "%.3f") << " | " << c.verdict << " |\n";
    return out.str();
}

std::vector<comparison> read_comparisons_csv(const std::filesystem::path& file) {
    std::vector<comparison> out;
    for (const csv_row& c : read_csv(file, compare_csv_header, "a compare.csv written by the race (--compare)")) {
        comparison k{c.cells[0], c.cells[1], c.cells[2], c.cells[3], c.cells[4], {}, {}, {}};
        if (k.query != "closest" && k.query != "any")
            throw std::runtime_error(file.string() + ", line " + std::to_string(c.line) + ": query '" + k.query +
                                     "' is neither closest nor any");
        k.ratio.samples = int(csv_number(file, c, 5));
        k.ratio.median = csv_number(file, c, 6), k.ratio.min = csv_number(file, c, 7), k.ratio.max = csv_number(file, c, 8);
        k.verdict = c.cells[9];
        std::istringstream ratios(c.cells[10]);
        for (std::string r; ratios >> r;) {
            char* end = nullptr;
            k.ratios.push_back(std::strtod(r.c_str(), &end));
            if (end != r.c_str() + r.size())
                throw std::runtime_error(file.string() + ", line " + std::to_string(c.line) + ": ratio '" + r +
                                         "' is not a number");
        }
        out.push_back(std::move(k));
    }
    return out;
}

verdict_stability compare_verdicts(const std::vector<comparison>& earlier, const std::vector<comparison>& now) {
    const auto key = [](const comparison& c) { return c.scene + "\n" + c.ray_set + "\n" + c.query + "\n" + c.a + "\n" + c.b; };
    std::map<std::string, const comparison*> before;
    for (const comparison& c : earlier) before[key(c)] = &c;
    verdict_stability s;
    for (const comparison& c : now) {
        const auto found = before.find(key(c));
        if (found == before.end()) continue;
        ++s.both;
        const comparison& e = *found->second;
        if (e.verdict == c.verdict) {
            ++s.held;
            continue;
        }
        const bool opposite = (e.verdict == "faster" && c.verdict == "slower") || (e.verdict == "slower" && c.verdict == "faster");
        s.opposite += opposite;
        s.changed.push_back({e, c});
    }
    return s;
}

std::string stability_markdown(const verdict_stability& s, const std::string& earlier_name) {
    std::ostringstream out;
    out << "# Verdicts against an earlier run\n\nThe same comparisons in " << earlier_name << " and in this run: "
        << s.both << " in both, " << s.held << " with the same verdict, " << s.changed.size() << " changed ("
        << s.opposite << " from faster to slower or back).\n\n";
    if (s.changed.empty()) return out.str();
    out << "| scene | rays | query | A | B | earlier A / B | verdict | now A / B | verdict |\n"
        << "|---|---|---|---|---|---:|---|---:|---|\n";
    for (const verdict_change& v : s.changed)
        out << "| " << v.now.scene << " | " << v.now.ray_set << " | " << v.now.query << " | " << v.now.a << " | "
            << v.now.b << " | " << cell(v.earlier.ratio, "%.3f") << " | " << v.earlier.verdict << " | "
            << cell(v.now.ratio, "%.3f") << " | " << v.now.verdict << " |\n";
    return out.str();
}

std::vector<plot> spread_plot(const std::vector<std::vector<race_row>>& processes) {
    std::vector<plot> panels;
    std::map<std::string, std::size_t> panel_of;  // scene and ray set
    for (std::size_t k = 0; k < processes.size(); ++k)
        for (const race_row& r : processes[k]) {
            const bool closest = r.closest.runs > 0;
            if (!closest && r.any.runs == 0) continue;
            const std::string key = r.scene + "\n" + r.ray_set;
            if (!panel_of.count(key)) {
                panel_of[key] = panels.size();
                plot p;
                p.title = r.scene + ", " + r.ray_set + " rays: speed per process";
                p.x_label = "process";
                p.y_label = std::string(closest ? "closest-hit" : "any-hit") + " speed [Mrays/s]";
                p.log_y = true;
                panels.push_back(std::move(p));
            }
            plot& p = panels[panel_of[key]];
            auto s = std::find_if(p.series.begin(), p.series.end(),
                                  [&](const plot_series& x) { return x.label == r.accel; });
            if (s == p.series.end()) {
                plot_series line;
                line.label = r.accel;
                s = p.series.insert(p.series.end(), std::move(line));
            }
            s->x.push_back(double(k + 1));
            s->y.push_back(closest ? r.closest.mrays : r.any.mrays);
        }
    return panels;
}

int run_self(const std::vector<std::string>& args, const std::filesystem::path& log) {
    std::vector<std::string> all = {"/proc/self/exe"};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);

    // The child's standard output and error: the log file (created or truncated).
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&files, 1, 2);
    pid_t pid = 0;
    const int failed = posix_spawn(&pid, argv[0], &files, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&files);
    if (failed) throw std::runtime_error(std::string("cannot start the race again: ") + std::strerror(failed));

    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw std::runtime_error(std::string("waiting for the race: ") + std::strerror(errno));
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

}  // namespace strahl::race
