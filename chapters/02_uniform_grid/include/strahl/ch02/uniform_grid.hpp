// Chapter 02's uniform grid over any primitive set: built from boxes, traversed with the 3D-DDA.
// J. Amanatides and A. Woo, "A Fast Voxel Traversal Algorithm for Ray Tracing", Eurographics 1987.
//
// Generic over the set (ch01::triangle_set, ch01::object_set): the build sees only boxes, the traversal
// calls set.intersect(i, r, best) / set.occludes(i, r), the leaf test. Counters as a template parameter.
#pragma once
#include "strahl/ch02/build.hpp"
#include "strahl/stats.hpp"
#include <algorithm>
#include <vector>
#include <cmath>

namespace strahl::ch02 {

// Mailboxing: a triangle in many cells is tested once per ray. Each thread keeps one stamp per triangle
// and a generation counter; a query takes the next generation, and a triangle whose stamp equals it was
// tested already. Thread-local, so intersect() stays const and thread-safe; keyed by the grid's build id,
// so one thread may query several grids (switching costs one clear of the stamps).
class mailbox {
public:
    mailbox(std::uint64_t grid_id, std::size_t prims) : s_(state()) {
        if (s_.grid != grid_id || s_.stamps.size() != prims) {
            s_.stamps.assign(prims, 0);
            s_.grid = grid_id;
            s_.generation = 0;
        }
        if (++s_.generation == 0) {  // wrapped around after 4 billion queries: start afresh
            std::fill(s_.stamps.begin(), s_.stamps.end(), 0u);
            s_.generation = 1;
        }
    }
    // True if id was tested already in this query; otherwise records it and returns false.
    bool seen(std::uint32_t id) {
        std::uint32_t& stamp = s_.stamps[id];
        if (stamp == s_.generation) return true;
        stamp = s_.generation;
        return false;
    }

private:
    struct per_thread {
        std::uint64_t grid = 0;
        std::uint32_t generation = 0;
        std::vector<std::uint32_t> stamps;
    };
    static per_thread& state() {
        thread_local per_thread s;
        return s;
    }
    per_thread& s_;
};

// A fresh id for every build (never 0), so a thread's mailbox never mistakes one grid for another.
std::uint64_t next_grid_id();

class uniform_grid {
public:
    template <class Set>
    void build(const Set& set, const grid_options& opt, const overlap_test& keep = {}) {
        std::vector<aabb> boxes(set.size());
        aabb scene_box;
        for (std::size_t i = 0; i < boxes.size(); ++i) scene_box.grow(boxes[i] = set.bounds(i));
        dims_ = bounded_resolution(scene_box, boxes, opt, &lowered_);
        cells_ = fill_cells(dims_, boxes, opt.exact_overlap ? keep : overlap_test{});
        prim_count_ = boxes.size();
        id_ = next_grid_id();
    }

    const grid_dims& dims() const { return dims_; }
    // Whether the build lowered the heuristic's resolution to keep within opt.max_references.
    bool resolution_lowered() const { return lowered_; }
    const grid_cells& cells() const { return cells_; }
    std::size_t memory_bytes() const {
        return sizeof(*this) + (cells_.offsets.size() + cells_.prims.size()) * sizeof(std::uint32_t);
    }

    // Closest hit: best must be a miss on entry; r is the query ray (its tmax shrinks as hits are found).
    template <class Set, class Stats>
    void intersect(const Set& set, ray r, hit& best, Stats& stats) const {
        stats.ray();
        if (prim_count_ == 0) return;
        if (odd_ray(r)) {  // NaN, Inf or zero direction: brute force decides (it finds nothing)
            for (std::uint32_t i = 0; i < prim_count_; ++i, stats.prim_test()) set.intersect(i, r, best);
            return;
        }
        walk(r, stats, [&](std::uint32_t i) { set.intersect(i, r, best); return false; });
    }

    // Any hit in (tmin, tmax).
    template <class Set, class Stats>
    bool occluded(const Set& set, const ray& r, Stats& stats) const {
        stats.ray();
        if (prim_count_ == 0) return false;
        if (odd_ray(r)) {
            for (std::uint32_t i = 0; i < prim_count_; ++i) {
                stats.prim_test();
                if (set.occludes(i, r)) return true;
            }
            return false;
        }
        bool blocked = false;
        walk(r, stats, [&](std::uint32_t i) { return blocked = set.occludes(i, r); });
        return blocked;
    }

private:
    static bool odd_ray(const ray& r) {
        return !is_finite(r.org) || !is_finite(r.dir) || std::isnan(r.tmin) || std::isnan(r.tmax) ||
               (r.dir.x == 0.0f && r.dir.y == 0.0f && r.dir.z == 0.0f);
    }

    // The walk: clip to the grid, set up the DDA, then cell by cell test the cell's primitives (each once,
    // mailboxing) until the search may end in the current cell (hit in cell) or the walk leaves the grid.
    // test(i) returns true to stop at once (any hit). r is read again after each cell: its tmax shrinks.
    template <class Stats, class Test>
    void walk(const ray& r, Stats& stats, Test&& test) const {
        float t_enter, t_exit;
        stats.box_test();
        if (!clip_to_grid(dims_, r, t_enter, t_exit)) return;
        dda_state s = dda_setup(dims_, r, t_enter);
        mailbox seen(id_, prim_count_);
        // A ray crosses at most res.x + res.y + res.z cells: the bound on the loop, whatever the floats do.
        const int max_cells = dims_.res.x + dims_.res.y + dims_.res.z;
        for (int k = 0; k < max_cells; ++k) {
            stats.node_visit();
            const int c = dims_.index(s.cell);
            for (std::uint32_t j = cells_.offsets[c]; j < cells_.offsets[c + 1]; ++j) {
                const std::uint32_t i = cells_.prims[j];
                if (seen.seen(i)) continue;
                stats.prim_test();
                if (test(i)) return;
            }
            // Hit in cell: the best hit (r.tmax is just above it) or the ray's end lies inside this cell.
            if (hit_in_cell(r.tmax, cell_exit(s))) return;
            if (!dda_step(dims_, s)) return;
        }
    }

    grid_dims dims_;
    grid_cells cells_;
    std::size_t prim_count_ = 0;
    std::uint64_t id_ = 0;
    bool lowered_ = false;
};

}  // namespace strahl::ch02
