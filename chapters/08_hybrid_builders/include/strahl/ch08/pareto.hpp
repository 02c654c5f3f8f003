// The build/trace trade, measured by the race: per scene and ray set, every BVH builder of chapters 04 to
// 08 walked by chapter 05's fast traversal (the race's rows *-fast, so that the trace time measures the
// tree) as a point (build time, trace time), and the course's Pareto frontier: the builders that no other
// builder of the course both builds and traces faster than. Embree's three qualities stand beside them as
// the yardstick. Times, not rays per second, so that lower is better on both axes.
#pragma once
#include "strahl/race_csv.hpp"
#include <string>
#include <vector>

namespace strahl::ch08 {

struct pareto_point {
    std::string scene, rays, structure, chapter;
    double build_ms = 0, trace_ms = 0;  // trace_ms: the ray set's closest-hit time on one thread
    bool on_frontier = false;           // on the course's frontier (never an Embree point)
};

// The points of a race's rows (primary and diffuse rays; chapters 04-08's *-fast rows and
// embree-low/medium/high), the course's frontier marked: in order of build time, a course point is on it
// when it traces faster than every course point that builds faster.
std::vector<pareto_point> pareto_points(const std::vector<race_csv_row>& rows);

// pareto.csv (scene,rays,structure,chapter,build_ms,trace_ms,on_frontier) and pareto.svg (one panel per
// scene and ray set, log-log, a colour per chapter and one for Embree, the course's frontier dashed and its
// points named, Embree's points named).
std::string pareto_csv(const std::vector<pareto_point>& points);
std::string pareto_svg(const std::vector<pareto_point>& points);

}  // namespace strahl::ch08
