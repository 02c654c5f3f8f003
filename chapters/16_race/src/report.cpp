#include "strahl/race/report.hpp"
#include "strahl/race/embree_accel.hpp"
#include "strahl/plot.hpp"
#include "strahl/program.hpp"
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <utility>

namespace strahl::race {

namespace {

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}
std::string opt(const std::optional<double>& v, const char* f) { return v ? fmt(f, *v) : "-"; }
std::string kib(std::size_t bytes) { return fmt("%.1f", double(bytes) / 1024.0); }
std::string diffs(const race_row& r, const query_result& q) {
    return std::to_string(q.differing) + (r.exact && q.differing ? " WRONG" : "");
}

}  // namespace

void add_embree_ratios(std::vector<race_row>& rows) {
    // The key ignores the "~" of a sampled row: its rays are an even spread of the same set.
    auto key = [](const race_row& r) {
        return r.scene + "/" + (r.ray_set.ends_with('~') ? r.ray_set.substr(0, r.ray_set.size() - 1) : r.ray_set);
    };
    std::map<std::string, const race_row*> embree;
    for (const race_row& r : rows)
        if (r.accel == "embree-medium") embree[key(r)] = &r;
    for (race_row& r : rows) {
        const auto it = embree.find(key(r));
        if (it == embree.end()) continue;
        if (it->second->closest.mrays > 0.0 && r.closest.runs > 0) r.closest_vs_embree = r.closest.mrays / it->second->closest.mrays;
        if (it->second->any.mrays > 0.0 && r.any.runs > 0) r.any_vs_embree = r.any.mrays / it->second->any.mrays;
    }
}

void print_table(std::ostream& out, const std::vector<race_row>& rows) {
    char line[400];
    std::string scene;
    for (const race_row& r : rows) {
        if (r.scene != scene) {
            scene = r.scene;
            out << "\n" << r.scene << " (" << r.triangles << " triangles)\n";
            std::snprintf(line, sizeof line, "  %-22s %-8s %9s %8s %7s %10s %7s %10s %7s %8s %8s %8s %8s\n", "structure",
                          "rays", "build ms", "KiB", "SAH", "closest", "xEmbree", "any-hit", "xEmbree", "box/ray",
                          "prim/ray", "diff cl", "diff any");
            out << line;
            std::snprintf(line, sizeof line, "  %-22s %-8s %9s %8s %7s %10s %7s %10s %7s %8s %8s %8s %8s\n", "", "", "",
                          "", "", "Mrays/s", "", "Mrays/s", "", "", "", "", "");
            out << line;
        }
        std::snprintf(line, sizeof line, "  %-22s %-8s %9.2f %8s %7s %10s %7s %10s %7s %8s %8s %8s %8s\n", r.accel.c_str(),
                      r.ray_set.c_str(), r.build_ms, kib(r.memory_bytes).c_str(), opt(r.sah, "%.2f").c_str(),
                      r.closest.runs ? fmt("%.3f", r.closest.mrays).c_str() : "-",
                      opt(r.closest_vs_embree, "%.3g").c_str(), r.any.runs ? fmt("%.3f", r.any.mrays).c_str() : "-",
                      opt(r.any_vs_embree, "%.3g").c_str(), opt(r.closest.box_per_ray, "%.1f").c_str(),
                      opt(r.closest.prim_per_ray, "%.1f").c_str(), r.closest.runs ? diffs(r, r.closest).c_str() : "-",
                      r.any.runs ? diffs(r, r.any).c_str() : "-");
        out << line;
    }
}

std::string to_csv(const std::vector<race_row>& rows, const machine_columns& machine) {
    std::ostringstream out;
    out << race_csv_header << ',' << race_csv_machine_header << '\n';
    auto o = [](const std::optional<double>& v) { return v ? fmt("%.6g", *v) : std::string(); };
    for (const race_row& r : rows) {
        out << csv_field(r.scene) << ',' << r.triangles << ',' << csv_field(r.accel) << ',' << csv_field(r.chapter) << ','
            << (r.exact ? 1 : 0) << ',' << csv_field(r.ray_set) << ',' << std::max(r.closest.rays, r.any.rays) << ',' << fmt("%.3f", r.build_ms) << ',' << r.memory_bytes << ','
            << o(r.sah) << ',' << (r.closest.runs ? fmt("%.6g", r.closest.mrays) : "") << ',' << r.closest.runs << ','
            << o(r.closest_vs_embree) << ',' << o(r.closest.box_per_ray) << ',' << o(r.closest.prim_per_ray) << ','
            << o(r.closest.nodes_per_ray) << ',' << (r.closest.runs ? std::to_string(r.closest.differing) : "") << ','
            << (r.any.runs ? fmt("%.6g", r.any.mrays) : "") << ',' << r.any.runs << ',' << o(r.any_vs_embree) << ','
            << o(r.any.box_per_ray) << ',' << o(r.any.prim_per_ray) << ','
            << (r.any.runs ? std::to_string(r.any.differing) : "") << ',' << csv_field(r.cpu.empty() ? machine.cpu : r.cpu)
            << ',' << machine.threads << ',' << csv_field(machine.kernels) << ',' << machine.date << '\n';
    }
    return out.str();
}

std::string to_markdown(const std::vector<race_row>& rows, const std::string& machine, int processes) {
    std::ostringstream out;
    out << "# The race\n\nMachine: " << machine << ". Single rays; ";
    if (processes > 1)
        out << "every figure is the median across " << processes << " fresh processes, each figure of which is a "
            << "median of timed runs; xEmbree is the median of each process's speed ratio to embree-medium; diff "
            << "counts rays whose result differs from brute force, in the worst process. spread.md gives each "
            << "figure's spread.\n\n";
    else
        out << "Mrays/s are medians (runs in the CSV); xEmbree is the speed ratio to embree-medium in the same run; "
            << "diff counts rays whose result differs from brute force.\n\n";
    out
        << "| scene | structure | rays | build ms | KiB | SAH | closest Mrays/s | xEmbree | any-hit Mrays/s | xEmbree | "
           "box/ray | prim/ray | diff closest | diff any |\n"
        << "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const race_row& r : rows)
        out << "| " << r.scene << " | " << r.accel << " | " << r.ray_set << " | " << fmt("%.2f", r.build_ms) << " | "
            << kib(r.memory_bytes) << " | " << opt(r.sah, "%.2f") << " | "
            << (r.closest.runs ? fmt("%.3f", r.closest.mrays) : "-") << " | " << opt(r.closest_vs_embree, "%.3g") << " | "
            << (r.any.runs ? fmt("%.3f", r.any.mrays) : "-") << " | " << opt(r.any_vs_embree, "%.3g") << " | "
            << opt(r.closest.box_per_ray, "%.1f") << " | " << opt(r.closest.prim_per_ray, "%.1f") << " | "
            << (r.closest.runs ? diffs(r, r.closest) : "-") << " | " << (r.any.runs ? diffs(r, r.any) : "-") << " |\n";
    return out.str();
}

namespace {

// A structure's family for the plots' colours ("brute", "ch05", "embree") and its name within it ("binned16").
std::pair<std::string, std::string> family_of(const std::string& accel) {
    const std::size_t dash = accel.find('-');
    if (dash == std::string::npos) return {accel, accel};
    return {accel.substr(0, dash), accel.substr(dash + 1)};
}

}  // namespace

void write_plots(const std::filesystem::path& folder, const std::vector<race_row>& rows) {
    // Build time against trace speed: one panel per scene, one colour per chapter (and Embree), each point
    // labelled with its structure's name within the chapter.
    std::vector<plot> panels;
    std::map<std::string, std::size_t> panel_of_scene;
    std::map<std::string, int> colour_of_family;
    bar_chart stairs{"The staircase: primary rays, closest hit, single ray", "Mrays/s", {}, {}, {}, true};
    std::map<std::string, std::size_t> category_of_accel;
    for (const race_row& r : rows) {
        if (r.ray_set != "primary" || r.closest.runs == 0) continue;
        if (!panel_of_scene.count(r.scene)) {
            panel_of_scene[r.scene] = panels.size();
            panels.push_back({r.scene + ": build time against trace speed (primary rays)", "build time [ms]",
                              "trace speed [Mrays/s]", true, true, {}});
            stairs.series_labels.push_back(r.scene);
            stairs.values.emplace_back();
        }
        const auto [family, name] = family_of(r.accel);
        if (!colour_of_family.count(family)) colour_of_family.emplace(family, int(colour_of_family.size()));
        plot& panel = panels[panel_of_scene[r.scene]];
        auto ser = std::find_if(panel.series.begin(), panel.series.end(),
                                [&](const plot_series& x) { return x.label == family; });
        if (ser == panel.series.end())
            ser = panel.series.insert(panel.series.end(), {family, {}, {}, false, {}, colour_of_family[family]});
        ser->x.push_back(std::max(r.build_ms, 1e-3));
        ser->y.push_back(r.closest.mrays);
        ser->point_labels.push_back(name);
        if (!category_of_accel.count(r.accel)) {
            category_of_accel[r.accel] = stairs.categories.size();
            stairs.categories.push_back(r.accel);
        }
    }
    for (auto& v : stairs.values) v.assign(stairs.categories.size(), 0.0);
    for (const race_row& r : rows)
        if (r.ray_set == "primary" && r.closest.runs)
            stairs.values[panel_of_scene[r.scene]][category_of_accel[r.accel]] = r.closest.mrays;
    write_svg(folder / "speed_vs_build.svg", to_svg(panels, 2));
    write_svg(folder / "staircase.svg", to_svg(stairs));
}

std::size_t wrong_rows(const std::vector<race_row>& rows) {
    std::size_t n = 0;
    for (const race_row& r : rows) n += r.exact && (r.closest.differing || r.any.differing);
    return n;
}

}  // namespace strahl::race
