// The top-down SAH builders: the full sweep over sorted centroids and binning.
//   J. Goldsmith and J. Salmon, IEEE CG&A 1987; J. D. MacDonald and K. S. Booth, The Visual Computer 1990;
//   I. Wald, "On fast construction of SAH-based bounding volume hierarchies", IEEE Symposium on
//   Interactive Ray Tracing 2007 (binning).
// Per node: STEP 1 the node's box and the box around its centroids; STEP 2 the best split (sweep or bins,
// on each axis the centroids spread along); STEP 3 the termination test, C_I N against the split's cost;
// STEP 4 the in-place partition of the index array; STEP 5 the two halves, left first, written straight
// into the flat depth-first node array.
#include "strahl/ch05/sah.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace strahl::ch05 {

std::string to_string(const sah_build_params& p) {
    return p.method == sah_method::sweep ? std::string("sweep") : "binned" + std::to_string(p.bins);
}

double tree_cost(const ch04::bvh& tree, const sah_costs& c) {
    return ch04::sah_tree_cost(tree, c.traversal, c.intersection);
}

namespace {

struct split_choice {
    int axis = -1;           // -1: no split found
    float cost = std::numeric_limits<float>::infinity();
    int boundary = 0;        // binned: the first bin on the right; sweep: the first sorted entry on the right
    bin_mapping mapping;     // binned: the axis's bins
};

// What the builder partitions: a primitive's box, centroid and id side by side (48 bytes), so every pass
// over a node's range reads memory in order rather than gathering boxes[ids[i]] from all over. The box is
// kept as two groups of four floats (the fourth unused) so that growing a box compiles to two SIMD
// min/max instructions.
struct alignas(16) ref {
    float lo[4], hi[4];
    float c[3];
    std::uint32_t id;
};

struct box4 {
    float lo[4] = {inf, inf, inf, inf}, hi[4] = {-inf, -inf, -inf, -inf};
    void grow(const float* l, const float* h) {
        float nl[4], nh[4];  // all loads before all stores, so the compiler may pair them into SIMD
        for (int j = 0; j < 4; ++j) nl[j] = l[j] < lo[j] ? l[j] : lo[j], nh[j] = h[j] > hi[j] ? h[j] : hi[j];
        for (int j = 0; j < 4; ++j) lo[j] = nl[j], hi[j] = nh[j];
    }
    aabb box() const { return {vec3(lo[0], lo[1], lo[2]), vec3(hi[0], hi[1], hi[2])}; }
};

// A node's range of refs with its box and the box around its centroids.
struct range_bounds {
    box4 box;
    aabb cbox;
    void add(const ref& r) {
        box.grow(r.lo, r.hi);
        cbox.grow(vec3(r.c[0], r.c[1], r.c[2]));
    }
};

struct builder {
    sah_build_params params;
    std::vector<ref>& refs;
    std::vector<ch04::bvh_node>& nodes;
    ch04::bvh_stats& stats;
    std::vector<bin> sweep_bins = {};     // sweep: one "bin" per primitive of the node
    std::vector<float> right_area = {};   // scratch for the suffix sweep
    std::vector<bin> axis_bins = {};      // binned: k bins, handed to exercise 05.3 one axis at a time
    std::vector<box4> bin_boxes = {};     // binned: 256 boxes per axis, filled by the binning pass
    std::vector<std::uint32_t> bin_counts = {};

    // Binned: one pass over the node's primitives fills k bins on each of the three axes at once.
    split_choice best_binned(std::size_t begin, std::size_t end, const aabb& cbox, float area) {
        const int k = params.bins;
        std::array<bin_mapping, 3> maps;
        std::array<bool, 3> usable{};
        for (int a = 0; a < 3; ++a) {
            maps[a] = make_bin_mapping(cbox.min[a], cbox.max[a], k);
            usable[a] = cbox.max[a] > cbox.min[a] && std::isfinite(maps[a].scale);
            std::fill_n(bin_boxes.begin() + a * 256, k, box4{});
            std::fill_n(bin_counts.begin() + a * 256, k, 0u);
        }
        // In blocks: first the bins of a block's refs (exercise 05.2, a call each), then the updates, so the
        // box updates do not wait on each call in turn.
        constexpr std::size_t block = 64;
        int slot[block][3];
        for (std::size_t first = begin; first < end; first += block) {
            const std::size_t m = std::min(block, end - first);
            for (int a = 0; a < 3; ++a)
                for (std::size_t i = 0; i < m; ++i) slot[i][a] = a * 256 + (usable[a] ? bin_index(maps[a], refs[first + i].c[a]) : 0);
            for (std::size_t i = 0; i < m; ++i) {
                const ref& r = refs[first + i];
                for (int a = 0; a < 3; ++a) {
                    bin_boxes[slot[i][a]].grow(r.lo, r.hi);
                    ++bin_counts[slot[i][a]];
                }
            }
        }
        split_choice best;
        for (int a = 0; a < 3; ++a) {
            if (!usable[a]) continue;
            for (int b = 0; b < k; ++b) axis_bins[b] = {bin_boxes[a * 256 + b].box(), bin_counts[a * 256 + b]};
            const bin_split s = best_boundary(std::span(axis_bins).first(k), right_area, params.costs, area);
            if (s.cost < best.cost) best = {a, s.cost, s.index, maps[a]};
        }
        return best;
    }

    // Full sweep: on each axis, sort the range by centroid (ties by id) and sweep every boundary. Sorting
    // small keys (centroid, id, position) moves less than sorting the refs; the refs are then put in the
    // best axis's order once, so the partition is the boundary itself.
    struct sort_key {
        float c;
        std::uint32_t id, pos;
    };
    std::vector<sort_key> keys = {}, best_keys = {};
    std::vector<ref> reordered = {};

    split_choice best_sweep(std::size_t begin, std::size_t end, const aabb& cbox, float area) {
        const std::size_t n = end - begin;
        split_choice best;
        for (int a = 0; a < 3; ++a) {
            if (!(cbox.max[a] > cbox.min[a])) continue;
            for (std::size_t i = 0; i < n; ++i) keys[i] = {refs[begin + i].c[a], refs[begin + i].id, std::uint32_t(i)};
            std::sort(keys.begin(), keys.begin() + std::ptrdiff_t(n), [](const sort_key& x, const sort_key& y) {
                return x.c < y.c || (x.c == y.c && x.id < y.id);
            });
            for (std::size_t i = 0; i < n; ++i) {
                const ref& r = refs[begin + keys[i].pos];
                sweep_bins[i] = bin{{vec3(r.lo[0], r.lo[1], r.lo[2]), vec3(r.hi[0], r.hi[1], r.hi[2])}, 1};
            }
            const bin_split s = best_boundary(std::span(sweep_bins).first(n), right_area, params.costs, area);
            if (s.cost < best.cost) best = {a, s.cost, s.index, {}}, std::swap(keys, best_keys);
        }
        if (best.axis >= 0) {
            for (std::size_t i = 0; i < n; ++i) reordered[i] = refs[begin + best_keys[i].pos];
            std::copy_n(reordered.begin(), n, refs.begin() + std::ptrdiff_t(begin));
        }
        return best;
    }

    // The fallback where the heuristic has no split, or deep down: the object median on the centroid box's
    // longest axis (ties by id), or, when all centroids coincide, the range halved by id.
    std::size_t median(std::size_t begin, std::size_t end, const aabb& cbox, int& axis) {
        axis = cbox.largest_axis();
        const std::size_t mid = begin + (end - begin) / 2;
        const auto first = refs.begin() + std::ptrdiff_t(begin), last = refs.begin() + std::ptrdiff_t(end);
        if (!(cbox.max[axis] > cbox.min[axis])) {  // halved by id, so the tree does not depend on the order
            std::nth_element(first, first + std::ptrdiff_t(mid - begin), last, [](const ref& x, const ref& y) { return x.id < y.id; });
            return mid;
        }
        const int a = axis;
        std::nth_element(refs.begin() + std::ptrdiff_t(begin), refs.begin() + std::ptrdiff_t(mid),
                         refs.begin() + std::ptrdiff_t(end), [a](const ref& x, const ref& y) {
                             return x.c[a] < y.c[a] || (x.c[a] == y.c[a] && x.id < y.id);
                         });
        return mid;
    }

    range_bounds bounds_of(std::size_t begin, std::size_t end) const {
        range_bounds b;
        for (std::size_t i = begin; i < end; ++i) b.add(refs[i]);
        return b;
    }

    // STEP 4 for bins: Hoare's partition at the chosen bin boundary, growing each side's bounds as it goes,
    // so the children need no pass of their own.
    std::size_t partition_bins(std::size_t begin, std::size_t end, const split_choice& s, range_bounds& left,
                               range_bounds& right) {
        const auto goes_left = [&](const ref& r) { return bin_index(s.mapping, r.c[s.axis]) < s.boundary; };
        std::size_t i = begin, j = end;
        for (;;) {
            while (i < j && goes_left(refs[i])) left.add(refs[i++]);
            while (i < j && !goes_left(refs[j - 1])) right.add(refs[--j]);
            if (i == j) return i;
            std::swap(refs[i], refs[j - 1]);  // refs[i] belonged right, refs[j - 1] left
            left.add(refs[i++]);
            right.add(refs[--j]);
        }
    }

    // STEP 1 is done by the caller: rb holds the range's box and centroid box.
    std::uint32_t build(std::size_t begin, std::size_t end, int depth, const range_bounds& rb) {
        const auto index = std::uint32_t(nodes.size());
        nodes.emplace_back();
        stats.depth = std::max(stats.depth, depth);
        const aabb box = rb.box.box(), &cbox = rb.cbox;
        for (int a = 0; a < 3; ++a) nodes[index].bmin[a] = box.min[a], nodes[index].bmax[a] = box.max[a];
        const std::size_t n = end - begin;
        const auto make_leaf = [&] {
            nodes[index].offset = std::uint32_t(begin);
            nodes[index].count = std::uint16_t(n);
            ++stats.leaves;
            stats.max_leaf = std::max(stats.max_leaf, n);
            return index;
        };
        if (n == 1) return make_leaf();
        // STEP 2: the best split. Deep down (only on pathological input) the heuristic gives way to the
        // median, which halves the range, so the depth stays bounded.
        const float area = box.surface_area();
        split_choice s;
        // A binned build sweeps a node with no more primitives than bins exactly: on so few, sorting is
        // cheaper than emptying and sweeping 3 k bins, and the exact sweep is never worse.
        const bool sweep = params.method == sah_method::sweep || n <= std::size_t(params.bins);
        if (depth < ch04::spatial_depth_limit && area > 0.0f)
            s = sweep ? best_sweep(begin, end, cbox, area) : best_binned(begin, end, cbox, area);
        // STEP 3, termination: a leaf when testing all N is no dearer than the best split.
        if (n <= std::size_t(params.max_leaf) && (s.axis < 0 || leaf_cost(params.costs, n) <= s.cost))
            return make_leaf();
        // STEP 4, the partition in place, and the children's bounds.
        std::size_t mid = begin;
        int axis = s.axis;
        range_bounds left, right;
        bool have_bounds = false;
        if (s.axis >= 0 && !sweep) mid = partition_bins(begin, end, s, left, right), have_bounds = true;
        else if (s.axis >= 0) mid = begin + std::size_t(s.boundary);  // the range is sorted on s.axis
        if (mid <= begin || mid >= end) mid = median(begin, end, cbox, axis), have_bounds = false;
        if (!have_bounds) left = bounds_of(begin, mid), right = bounds_of(mid, end);
        // STEP 5: the halves; the left child is the next node, the right child's index goes into offset.
        ++stats.inner;
        nodes[index].axis = std::uint8_t(axis);
        build(begin, mid, depth + 1, left);
        const std::uint32_t right_index = build(mid, end, depth + 1, right);
        nodes[index].offset = right_index;
        return index;
    }
};

}  // namespace

ch04::bvh build_sah_bvh(std::span<const aabb> boxes, std::span<const vec3> centroids, const sah_build_params& params) {
    if (boxes.size() != centroids.size()) throw std::invalid_argument("build_sah_bvh: one centroid per box");
    const timer clock;
    ch04::bvh t;
    t.stats.primitives = boxes.size();
    std::vector<ref> refs;
    refs.reserve(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        if (!ch04::fits_in_tree(boxes[i], centroids[i])) {
            t.loose.push_back(std::uint32_t(i));  // tested by every ray
            continue;
        }
        const aabb& b = boxes[i];
        refs.push_back({{b.min.x, b.min.y, b.min.z, 0.0f}, {b.max.x, b.max.y, b.max.z, 0.0f},
                        {centroids[i].x, centroids[i].y, centroids[i].z}, std::uint32_t(i)});
    }
    if (!refs.empty()) {
        sah_build_params p = params;
        p.bins = std::clamp(p.bins, 2, 256);
        p.max_leaf = std::clamp(p.max_leaf, 1, 255);
        const std::size_t n = refs.size();
        t.nodes.reserve(2 * n - 1);  // N primitives: at most 2N - 1 nodes, so the array never moves
        builder b{p, refs, t.nodes, t.stats};
        b.axis_bins.resize(256);
        b.bin_boxes.resize(3 * 256);
        b.bin_counts.resize(3 * 256);
        const std::size_t most_swept = p.method == sah_method::sweep ? n : std::min<std::size_t>(n, p.bins);
        b.sweep_bins.resize(most_swept);
        b.keys.resize(most_swept);
        b.best_keys.resize(most_swept);
        b.reordered.resize(most_swept);
        b.right_area.resize(std::max<std::size_t>(n, 256));
        b.build(0, n, 0, b.bounds_of(0, n));
        t.bounds = t.nodes[0].box();
        t.prim_ids.resize(n);
        for (std::size_t i = 0; i < n; ++i) t.prim_ids[i] = refs[i].id;  // the leaves' ranges, in order
    }
    t.stats.build_ms = clock.milliseconds();
    return t;
}

}  // namespace strahl::ch05
