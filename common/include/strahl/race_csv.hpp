// The race's table, race.csv (chapter 16 writes it): its columns, and its rows read back by the chapters
// that draw from a race (chapter 08's Pareto plot, chapter 11's staircase), so that every chapter reads the
// one format the race writes.
#pragma once
#include "strahl/machine.hpp"
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace strahl {

// race.csv's first line: its columns.
inline constexpr const char* race_csv_header =
    "scene,triangles,structure,chapter,exact,rays,ray_count,build_ms,memory_bytes,sah_cost,"
    "closest_mrays_s,closest_runs,closest_vs_embree,closest_box_per_ray,closest_prim_per_ray,closest_nodes_per_ray,"
    "closest_differing,any_mrays_s,any_runs,any_vs_embree,any_box_per_ray,any_prim_per_ray,any_differing";

// The columns race.csv gained on 2026-12-05, at its end: the machine that ran the race (one table, one
// machine). cpu: the model /proc/cpuinfo names ("AMD EPYC"); threads: the tracing threads (race --threads);
// kernels: the instruction set of Embree's kernels ("AVX512"; "none" without Embree); date: YYYY-MM-DD (UTC).
// Readers take files with and without them.
inline constexpr const char* race_csv_machine_header = machine_header;

// One row, the columns the plots and chapter 11's step report use. scene is the file's stem ("bunny" for
// bunny.ply); rays is primary, diffuse or shadow; a cell the race left empty (shadow rays have no
// closest-hit figures) reads 0.
struct race_csv_row {
    std::string scene, structure, chapter, rays;
    std::size_t triangles = 0, ray_count = 0;
    double build_ms = 0, memory_bytes = 0, closest_mrays_s = 0, any_mrays_s = 0;
    // The exact counters, per ray: box tests, triangle tests and (closest hit only) nodes visited.
    double closest_box_per_ray = 0, closest_prim_per_ray = 0, closest_nodes_per_ray = 0;
    double any_box_per_ray = 0, any_prim_per_ray = 0;
    std::size_t closest_differing = 0, any_differing = 0;
    std::string cpu;  // empty in files written before the machine columns
};

// Reads a race.csv (a race's own, or the medians of race --processes N); throws std::runtime_error naming
// the file and line where it is not one.
std::vector<race_csv_row> read_race_rows(const std::filesystem::path& file);

}  // namespace strahl
