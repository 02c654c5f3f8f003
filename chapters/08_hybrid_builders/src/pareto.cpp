// The build/trace trade of every builder, from a race: per scene and ray set, each structure's build time
// against the time its rays take, and the Pareto frontier (the structures no other builds and traces
// faster than).
#include "strahl/ch08/pareto.hpp"
#include "strahl/plot.hpp"
#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace strahl::ch08 {

namespace {

// The course's BVH builders (chapters 04 to 08) walked by one traversal, chapter 05's fast one (the rows
// named *-fast), so that the trace time measures the tree; and Embree's three qualities. Not the grids,
// k-d trees, wide trees or packet variants, which trade other things.
bool compared(const race_csv_row& r) {
    if (r.structure.rfind("embree-", 0) == 0) return r.structure == "embree-low" || r.structure == "embree-medium" ||
                                                      r.structure == "embree-high";
    const bool fast = r.structure.size() > 5 && r.structure.compare(r.structure.size() - 5, 5, "-fast") == 0;
    return fast && (r.chapter == "04" || r.chapter == "05" || r.chapter == "06" || r.chapter == "07" || r.chapter == "08");
}

std::string group_of(const pareto_point& p) {
    return p.structure.rfind("embree-", 0) == 0 ? "Embree" : "chapter " + p.chapter;
}

}  // namespace

std::vector<pareto_point> pareto_points(const std::vector<race_csv_row>& rows) {
    std::vector<pareto_point> points;
    for (const race_csv_row& r : rows) {
        if (!compared(r) || (r.rays != "primary" && r.rays != "diffuse")) continue;
        if (!(r.closest_mrays_s > 0) || !(r.build_ms > 0)) continue;
        pareto_point p{r.scene, r.rays, r.structure, r.chapter, r.build_ms, 1e-3 * double(r.ray_count) / r.closest_mrays_s};
        points.push_back(p);
    }
    // The course's frontier per scene and ray set: in order of build time (then trace time), a course
    // point is on it when it traces faster than every course point that builds faster. Embree's points are
    // the yardstick beside it, not part of it.
    std::map<std::pair<std::string, std::string>, std::vector<pareto_point*>> groups;
    for (pareto_point& p : points)
        if (p.structure.rfind("embree-", 0) != 0) groups[{p.scene, p.rays}].push_back(&p);
    for (auto& [key, g] : groups) {
        std::sort(g.begin(), g.end(), [](const pareto_point* a, const pareto_point* b) {
            return a->build_ms < b->build_ms || (a->build_ms == b->build_ms && a->trace_ms < b->trace_ms);
        });
        double best = 1e300;
        for (pareto_point* p : g)
            if (p->trace_ms < best) p->on_frontier = true, best = p->trace_ms;
    }
    return points;
}

std::string pareto_csv(const std::vector<pareto_point>& points) {
    std::ostringstream out;
    out << "scene,rays,structure,chapter,build_ms,trace_ms,on_frontier\n";
    for (const pareto_point& p : points)
        out << p.scene << ',' << p.rays << ',' << p.structure << ',' << p.chapter << ',' << p.build_ms << ','
            << p.trace_ms << ',' << (p.on_frontier ? 1 : 0) << '\n';
    return out.str();
}

std::string pareto_svg(const std::vector<pareto_point>& points) {
    std::vector<std::pair<std::string, std::string>> panels;  // (scene, rays) in the race's order
    for (const pareto_point& p : points)
        if (std::find(panels.begin(), panels.end(), std::pair{p.scene, p.rays}) == panels.end()) panels.emplace_back(p.scene, p.rays);
    std::vector<std::string> groups;  // one colour per chapter, and Embree
    for (const pareto_point& p : points)
        if (std::find(groups.begin(), groups.end(), group_of(p)) == groups.end()) groups.push_back(group_of(p));
    std::sort(groups.begin(), groups.end());
    std::vector<plot> out;
    for (std::size_t k = 0; k < panels.size(); ++k) {
        const auto& [scene, rays] = panels[k];
        plot pl{scene + ", " + rays + " rays", "build time, one thread [ms]", "trace time, one thread [ms]", true, true, {}, false};
        std::vector<const pareto_point*> front;
        for (std::size_t g = 0; g < groups.size(); ++g) {
            plot_series s{groups[g], {}, {}, false, {}, int(g)};
            s.in_legend = k == 0;
            for (const pareto_point& p : points) {
                if (p.scene != scene || p.rays != rays || group_of(p) != groups[g]) continue;
                s.x.push_back(p.build_ms), s.y.push_back(p.trace_ms);
                // Labels on the frontier and for Embree only: the rest are the colour of their chapter.
                std::string label = p.structure;
                if (label.size() > 5 && label.rfind("-fast") == label.size() - 5) label.resize(label.size() - 5);
                s.point_labels.push_back(p.on_frontier || groups[g] == "Embree" ? label : "");
                if (p.on_frontier) front.push_back(&p);
            }
            if (!s.x.empty()) pl.series.push_back(s);
        }
        // The frontier as a staircase: down at each frontier point, across to the next.
        std::sort(front.begin(), front.end(), [](const pareto_point* a, const pareto_point* b) { return a->build_ms < b->build_ms; });
        plot_series stair{"the course's frontier", {}, {}, true, {}, 8};
        stair.dashed = true;
        stair.markers = false;  // its corners are not points; the frontier's points are drawn in their colours
        stair.in_legend = k == 0;
        for (std::size_t i = 0; i < front.size(); ++i) {
            if (i > 0) stair.x.push_back(front[i]->build_ms), stair.y.push_back(front[i - 1]->trace_ms);
            stair.x.push_back(front[i]->build_ms), stair.y.push_back(front[i]->trace_ms);
        }
        if (!stair.x.empty()) pl.series.insert(pl.series.begin(), stair);  // under the points
        out.push_back(pl);
    }
    if (out.empty()) throw std::runtime_error("no *-fast rows of chapters 04 to 08 and no Embree rows with primary or diffuse rays to plot");
    return to_svg(out, 2, 640, 460);
}

}  // namespace strahl::ch08
