// The binned SAH build, engineered for speed: the same tree as build_sah_bvh(..., binned) (same bins, same
// costs, same ties, so the same nodes), about three times as fast. I. Wald, "On fast construction of
// SAH-based bounding volume hierarchies", IEEE Symposium on Interactive Ray Tracing 2007, section 4 (binning
// all three axes in one pass); Embree (I. Wald et al., ACM TOG 33(4), 2014) bins the same way.
// What changes against sah_build.cpp, step by step:
//   STEP 2, binning: the bin of a centroid on all three axes at once, with exercise 05.2's formula inlined
//     in four-wide SIMD (GCC's vector extension), instead of three out-of-line calls; the bins' boxes grow
//     with two SIMD instructions; the prefix/suffix sweeps (exercise 05.3's) are inlined too.
//   Small nodes (no more primitives than bins): the same exact sweep over sorted centroids, with a shortcut
//     for two primitives, rank counting instead of a sort, and the three axes' sweeps side by side.
//   STEP 4, the partition: branch-free (Lomuto's scheme, the side as a mask); the children's boxes are
//     unions of their bins.
// The float operations are the solutions' own, in the same order (and -ffp-contract=off), so every cost
// compares the same way and the test checks the two trees node for node.
// In parallel (where more than one thread is allowed): a node of at least task_min primitives builds its
// left subtree itself and its right one as a task, into a node array of its own appended afterwards; the
// nodes of at least bin_parallel_min primitives bin in chunks on all threads. Each node's decisions depend
// on its primitives alone, and the bins merge by min, max and sums, so the tree is the same on any number
// of threads, node for node (a test checks it).
#include "strahl/ch05/sah.hpp"
#include "strahl/parallel.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace strahl::ch05 {

namespace {

using f4 = float __attribute__((vector_size(16)));          // four floats: one SSE register
using i4 = std::int32_t __attribute__((vector_size(16)));   // four ints

constexpr float inf = std::numeric_limits<float>::infinity();

f4 vmin(f4 a, f4 b) { return a < b ? a : b; }
f4 vmax(f4 a, f4 b) { return a > b ? a : b; }

// A box in two registers; lane 3 is not part of it.
struct box {
    f4 lo = {inf, inf, inf, inf}, hi = {-inf, -inf, -inf, -inf};
    void grow(f4 l, f4 h) { lo = vmin(lo, l), hi = vmax(hi, h); }
    void grow(const box& b) { grow(b.lo, b.hi); }
    // aabb::surface_area of a non-empty box, the same operations in the same order.
    float area() const {
        const f4 e = hi - lo;
        return 2.0f * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
    }
};

// A primitive in 48 bytes: its box (lane 3 of lo carries the id's bits; min/max do no arithmetic, so any
// bits are harmless there) and its centroid (lane 3 zero).
struct ref {
    f4 lo, hi, c;
    std::uint32_t id() const { return std::bit_cast<std::uint32_t>(lo[3]); }
};

// k bins on each axis over the centroid box (make_bin_mapping per lane); an axis the centroids do not
// spread along gets scale 0, which puts everything into its bin 0.
struct mapping {
    f4 lo = {}, scale = {}, top = {};
    int k = 0;
    bool usable[3] = {};
    mapping() = default;
    mapping(const box& cbox, int bins) : k(bins) {
        const f4 kf = {float(bins), float(bins), float(bins), float(bins)};
        const f4 s = kf / (cbox.hi - cbox.lo);
        for (int a = 0; a < 3; ++a) {
            usable[a] = cbox.hi[a] > cbox.lo[a] && std::isfinite(s[a]);
            lo[a] = usable[a] ? cbox.lo[a] : 0.0f;
            scale[a] = usable[a] ? s[a] : 0.0f;
        }
        top = kf - 1.0f;
    }
    // Exercise 05.2 on three axes at once: int(scale * (c - lo)), clamped in float to [0, k - 1], NaN to 0.
    i4 bins_of(f4 c) const {
        f4 f = scale * (c - lo);
        f = f >= top ? top : f;
        f = f > f4{} ? f : f4{};
        return __builtin_convertvector(f, i4);
    }
};

struct split_choice {
    int axis = -1;
    float cost = inf;
    int boundary = 0;
};

// Exercise 05.3's two sweeps over `count` boxes (bins, or single primitives in sorted order), the same
// operations as the solution: the lowest cost, ties to the lowest boundary.
template <class BoxAt, class CountAt>
void sweep(int axis, int count, BoxAt box_at, CountAt count_at, const sah_costs& c, float area_parent,
           float* right_area, split_choice& best) {
    box right;
    std::uint64_t n_right = 0;
    for (int b = count - 1; b > 0; --b) right.grow(box_at(b)), right_area[b] = right.area();
    for (int b = 0; b < count; ++b) n_right += count_at(b);
    box left;
    std::uint64_t n_left = 0;
    for (int b = 1; b < count; ++b) {
        left.grow(box_at(b - 1));
        n_left += count_at(b - 1), n_right -= count_at(b - 1);
        if (n_left == 0 || n_right == 0) continue;
        const float cost = c.traversal + c.intersection * (left.area() * float(n_left) + right_area[b] * float(n_right)) / area_parent;
        if (cost < best.cost) best = {axis, cost, b};
    }
}

// The bins of one axis set: k boxes and counts per axis.
struct bin_set {
    box bins[3][256];
    std::uint32_t counts[3][256];
};

struct fast_builder {
    sah_build_params params;
    std::vector<ref>& refs;
    std::vector<ch04::bvh_node>& nodes;
    ch04::bvh_stats& stats;
    std::size_t task_min = 0;          // 0: serial; else a node this large on both sides forks its children
    std::size_t bin_parallel_min = 0;  // 0: serial; else a node this large bins in parallel chunks
    box bins[3][256];
    std::uint32_t counts[3][256];
    float right_area[256];
    f4 right_areas[256];

    // Small nodes (n <= 16 here): the order on each axis by rank counting, branch-free in 16-wide SIMD: the
    // rank of primitive i is the number of primitives before it by (centroid, id), the sort's order.
    // Larger small nodes (bins > 16) sort.
    using f16 = float __attribute__((vector_size(64)));
    using u16 = std::uint32_t __attribute__((vector_size(64)));
    std::uint32_t order[3][256];
    ref reordered[256];

    void sort_axis(const ref* r, int n, int a, std::uint32_t* out) {
        if (n <= 16) {
            f16 c = {};
            u16 id = {}, rank = {};
            for (int i = 0; i < 16; ++i) c[i] = i < n ? r[i].c[a] : inf, id[i] = i < n ? r[i].id() : ~0u;
            for (int j = 0; j < n; ++j) rank -= (u16)((c[j] < c) | ((c[j] == c) & (id[j] < id)));  // true is -1
            for (int i = 0; i < n; ++i) out[rank[i]] = std::uint32_t(i);
            return;
        }
        for (int i = 0; i < n; ++i) out[i] = std::uint32_t(i);
        std::sort(out, out + n, [&](std::uint32_t x, std::uint32_t y) {
            return r[x].c[a] < r[y].c[a] || (r[x].c[a] == r[y].c[a] && r[x].id() < r[y].id());
        });
    }

    split_choice best_sweep(std::size_t begin, std::size_t end, const box& cbox, float area) {
        const int n = int(end - begin);
        const ref* r = refs.data() + begin;
        split_choice best;
        if (n == 2) {
            // Half of all small nodes. One boundary, and on every axis the same two sides, so the same cost:
            // the first axis the centroids differ on wins the tie, and the order on it is (centroid, id).
            for (int a = 0; a < 3 && best.axis < 0; ++a) {
                if (!(cbox.hi[a] > cbox.lo[a])) continue;
                const box first{r[0].lo, r[0].hi}, second{r[1].lo, r[1].hi};
                best = {a, params.costs.traversal + params.costs.intersection *
                                                        (first.area() * 1.0f + second.area() * 1.0f) / area, 1};
                if (r[1].c[a] < r[0].c[a] || (r[1].c[a] == r[0].c[a] && r[1].id() < r[0].id()))
                    std::swap(refs[begin], refs[begin + 1]);
            }
            return best;
        }
        // The three axes' sweeps at once, one axis per lane: lane a holds the boxes grown in axis a's order.
        // Per lane these are the solution's operations in its order, so every cost is the same float.
        bool usable[3];
        for (int a = 0; a < 3; ++a)
            if ((usable[a] = cbox.hi[a] > cbox.lo[a])) sort_axis(r, n, a, order[a]);
            else for (int i = 0; i < n; ++i) order[a][i] = std::uint32_t(i);  // swept, never chosen
        struct boxes3 {  // x, y, z of the lower and upper corners, one axis's box per lane
            f4 lx = box{}.lo, ly = lx, lz = lx, hx = box{}.hi, hy = hx, hz = hx;
            void grow(const ref& p0, const ref& p1, const ref& p2) {
                lx = vmin(lx, f4{p0.lo[0], p1.lo[0], p2.lo[0], 0}), hx = vmax(hx, f4{p0.hi[0], p1.hi[0], p2.hi[0], 0});
                ly = vmin(ly, f4{p0.lo[1], p1.lo[1], p2.lo[1], 0}), hy = vmax(hy, f4{p0.hi[1], p1.hi[1], p2.hi[1], 0});
                lz = vmin(lz, f4{p0.lo[2], p1.lo[2], p2.lo[2], 0}), hz = vmax(hz, f4{p0.hi[2], p1.hi[2], p2.hi[2], 0});
            }
            f4 area() const {
                const f4 ex = hx - lx, ey = hy - ly, ez = hz - lz;
                return 2.0f * (ex * ey + ey * ez + ez * ex);
            }
        } left, right;
        const std::uint32_t *o0 = order[0], *o1 = order[1], *o2 = order[2];
        for (int b = n - 1; b > 0; --b) right.grow(r[o0[b]], r[o1[b]], r[o2[b]]), right_areas[b] = right.area();
        const f4 traversal = f4{} + params.costs.traversal, intersection = f4{} + params.costs.intersection;
        f4 best_cost = f4{} + inf;
        i4 best_b = {};
        for (int b = 1; b < n; ++b) {
            left.grow(r[o0[b - 1]], r[o1[b - 1]], r[o2[b - 1]]);
            const f4 cost = traversal + intersection * (left.area() * float(b) + right_areas[b] * float(n - b)) / area;
            const i4 better = cost < best_cost;
            best_cost = better ? cost : best_cost;
            best_b = better ? i4{} + b : best_b;
        }
        for (int a = 0; a < 3; ++a)
            if (usable[a] && best_cost[a] < best.cost) best = {a, best_cost[a], best_b[a]};
        if (best.axis >= 0) {
            for (int i = 0; i < n; ++i) reordered[i] = r[order[best.axis][i]];
            std::copy_n(reordered, n, refs.begin() + std::ptrdiff_t(begin));
        }
        return best;
    }

    // Bins refs [begin, end) into bins and counts (emptied first).
    void bin_range(std::size_t begin, std::size_t end, const mapping& m, box (&bins)[3][256],
                   std::uint32_t (&counts)[3][256]) const {
        const int k = m.k;
        for (int a = 0; a < 3; ++a) std::fill_n(bins[a], k, box{}), std::fill_n(counts[a], k, 0u);
        for (std::size_t i = begin; i < end; ++i) {
            const ref& r = refs[i];
            const i4 b = m.bins_of(r.c);
            bins[0][b[0]].grow(r.lo, r.hi), ++counts[0][b[0]];
            bins[1][b[1]].grow(r.lo, r.hi), ++counts[1][b[1]];
            bins[2][b[2]].grow(r.lo, r.hi), ++counts[2][b[2]];
        }
    }

    split_choice best_binned(std::size_t begin, std::size_t end, const mapping& m, float area) {
        const int k = m.k;
        if (bin_parallel_min && end - begin >= bin_parallel_min) {
            // In parallel: a bin set per chunk, merged in chunk order (min, max, sums: the same bins).
            const std::size_t chunk = std::max<std::size_t>(16384, (end - begin) / 64);
            const std::size_t chunks = (end - begin + chunk - 1) / chunk;
            std::vector<bin_set> part(chunks);
            parallel_for_chunks(chunks, 1, [&](std::size_t c0, std::size_t c1) {
                for (std::size_t c = c0; c < c1; ++c)
                    bin_range(begin + c * chunk, std::min(end, begin + (c + 1) * chunk), m, part[c].bins, part[c].counts);
            });
            for (int a = 0; a < 3; ++a) std::fill_n(bins[a], k, box{}), std::fill_n(counts[a], k, 0u);
            for (const bin_set& p : part)
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < k; ++b) bins[a][b].grow(p.bins[a][b]), counts[a][b] += p.counts[a][b];
        } else {
            bin_range(begin, end, m, bins, counts);
        }
        split_choice best;
        for (int a = 0; a < 3; ++a)
            if (m.usable[a])
                sweep(a, k, [&](int b) { return bins[a][b]; }, [&](int b) { return counts[a][b]; }, params.costs,
                      area, right_area, best);
        return best;
    }

    struct bounds {
        box b, c;
        void add(const ref& r) { b.grow(r.lo, r.hi), c.grow(r.c, r.c); }
    };

    // The partition at the bin boundary, without a branch on the side (Lomuto's scheme, branch-free): every
    // ref is swapped with the first ref of the right run, and the left run grows by one when it goes left.
    // The order differs from sah_build.cpp's Hoare partition, so leaves hold the same primitives in another
    // order. The children's boxes are the unions of their bins; their centroid boxes grow on the way, by a
    // select of the centroid or the empty box.
    std::size_t partition(std::size_t begin, std::size_t end, const mapping& m, const split_choice& s,
                          bounds& left, bounds& right) {
        const f4 empty_lo = box{}.lo, empty_hi = box{}.hi;
        const i4 axis = {s.axis, s.axis, s.axis, s.axis}, boundary = {s.boundary, s.boundary, s.boundary, s.boundary};
        std::size_t l = begin;
        for (std::size_t i = begin; i < end; ++i) {
            const ref r = refs[i];
            // The side as a mask in every lane (-1: left), so that nothing below branches on it.
            const i4 mask = __builtin_shuffle(i4(m.bins_of(r.c) < boundary), axis);
            refs[i] = refs[l], refs[l] = r;
            l -= std::size_t(std::ptrdiff_t(mask[0]));
            left.c.grow(mask ? r.c : empty_lo, mask ? r.c : empty_hi);
            right.c.grow(mask ? empty_lo : r.c, mask ? empty_hi : r.c);
        }
        for (int b = 0; b < m.k; ++b) (b < s.boundary ? left : right).b.grow(bins[s.axis][b]);
        return l;
    }

    // The object median on the centroid box's longest axis (aabb::largest_axis), ties by id.
    std::size_t median(std::size_t begin, std::size_t end, const box& cbox, int& axis) {
        axis = aabb{vec3(cbox.lo[0], cbox.lo[1], cbox.lo[2]), vec3(cbox.hi[0], cbox.hi[1], cbox.hi[2])}.largest_axis();
        const std::size_t mid = begin + (end - begin) / 2;
        const auto first = refs.begin() + std::ptrdiff_t(begin), last = refs.begin() + std::ptrdiff_t(end);
        if (!(cbox.hi[axis] > cbox.lo[axis])) {  // halved by id, as sah_build.cpp
            std::nth_element(first, first + std::ptrdiff_t(mid - begin), last, [](const ref& x, const ref& y) { return x.id() < y.id(); });
            return mid;
        }
        const int a = axis;
        std::nth_element(refs.begin() + std::ptrdiff_t(begin), refs.begin() + std::ptrdiff_t(mid),
                         refs.begin() + std::ptrdiff_t(end), [a](const ref& x, const ref& y) {
                             return x.c[a] < y.c[a] || (x.c[a] == y.c[a] && x.id() < y.id());
                         });
        return mid;
    }

    bounds bounds_of(std::size_t begin, std::size_t end) const {
        bounds b;
        for (std::size_t i = begin; i < end; ++i) b.add(refs[i]);
        return b;
    }

    std::uint32_t build(std::size_t begin, std::size_t end, int depth, const bounds& rb) {
        const auto index = std::uint32_t(nodes.size());
        nodes.emplace_back();
        stats.depth = std::max(stats.depth, depth);
        ch04::bvh_node& node = nodes[index];
        for (int a = 0; a < 3; ++a) node.bmin[a] = rb.b.lo[a], node.bmax[a] = rb.b.hi[a];
        const std::size_t n = end - begin;
        const auto make_leaf = [&] {
            nodes[index].offset = std::uint32_t(begin);
            nodes[index].count = std::uint16_t(n);
            ++stats.leaves;
            stats.max_leaf = std::max(stats.max_leaf, n);
            return index;
        };
        if (n == 1) return make_leaf();
        // STEP 2: the best split (sah_build.cpp's rules: small nodes swept exactly, the median deep down).
        const float area = rb.b.area();
        const bool small = n <= std::size_t(params.bins);
        split_choice s;
        const mapping m = small ? mapping{} : mapping(rb.c, params.bins);
        if (depth < ch04::spatial_depth_limit && area > 0.0f)
            s = small ? best_sweep(begin, end, rb.c, area) : best_binned(begin, end, m, area);
        // STEP 3, termination.
        if (n <= std::size_t(params.max_leaf) && (s.axis < 0 || leaf_cost(params.costs, n) <= s.cost))
            return make_leaf();
        // STEP 4, the partition and the children's bounds.
        std::size_t mid = begin;
        int axis = s.axis;
        bounds left, right;
        bool have_bounds = false;
        if (s.axis >= 0 && !small) mid = partition(begin, end, m, s, left, right), have_bounds = true;
        else if (s.axis >= 0) mid = begin + std::size_t(s.boundary);
        if (mid <= begin || mid >= end) mid = median(begin, end, rb.c, axis), have_bounds = false;
        if (!have_bounds) left = bounds_of(begin, mid), right = bounds_of(mid, end);
        // STEP 5: left child next, right child's index into offset.
        ++stats.inner;
        nodes[index].axis = std::uint8_t(axis);
        if (task_min && mid - begin >= task_min && end - mid >= task_min) {
            // In parallel: the left subtree here, the right one by a builder of its own (its own scratch and
            // node array), appended after the left subtree; its inner nodes' offsets move by where it lands.
            std::vector<ch04::bvh_node> right_nodes;
            right_nodes.reserve(2 * (end - mid) - 1);
            ch04::bvh_stats right_stats;
            auto other = std::make_unique<fast_builder>(params, refs, right_nodes, right_stats, task_min, bin_parallel_min);
            parallel_invoke([&] { build(begin, mid, depth + 1, left); },
                            [&] { other->build(mid, end, depth + 1, right); });
            const auto base = std::uint32_t(nodes.size());
            for (ch04::bvh_node n : right_nodes) {
                if (!n.is_leaf()) n.offset += base;
                nodes.push_back(n);
            }
            nodes[index].offset = base;
            stats.depth = std::max(stats.depth, right_stats.depth);
            stats.inner += right_stats.inner, stats.leaves += right_stats.leaves;
            stats.max_leaf = std::max(stats.max_leaf, right_stats.max_leaf);
            return index;
        }
        build(begin, mid, depth + 1, left);
        const std::uint32_t right_index = build(mid, end, depth + 1, right);
        nodes[index].offset = right_index;
        return index;
    }
};

}  // namespace

ch04::bvh build_sah_bvh_fast(std::span<const aabb> boxes, std::span<const vec3> centroids,
                             const sah_build_params& params) {
    if (params.method != sah_method::binned) return build_sah_bvh(boxes, centroids, params);
    if (boxes.size() != centroids.size()) throw std::invalid_argument("build_sah_bvh_fast: one centroid per box");
    const timer clock;
    ch04::bvh t;
    t.stats.primitives = boxes.size();
    std::vector<ref> refs;
    refs.reserve(boxes.size());
    fast_builder::bounds root;  // STEP 1 for the root, on the way
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const aabb& b = boxes[i];
        const vec3& c = centroids[i];
        if (!ch04::fits_in_tree(b, c)) {
            t.loose.push_back(std::uint32_t(i));  // tested by every ray
            continue;
        }
        refs.push_back(ref{f4{b.min.x, b.min.y, b.min.z, std::bit_cast<float>(std::uint32_t(i))},
                           f4{b.max.x, b.max.y, b.max.z, 0.0f}, f4{c.x, c.y, c.z, 0.0f}});
        root.add(refs.back());
    }
    if (!refs.empty()) {
        sah_build_params p = params;
        p.bins = std::clamp(p.bins, 2, 256);
        p.max_leaf = std::clamp(p.max_leaf, 1, 255);
        const std::size_t n = refs.size();
        t.nodes.reserve(2 * n - 1);
        auto b = std::make_unique<fast_builder>(p, refs, t.nodes, t.stats);  // ~60 KiB of scratch: on the heap
        if (parallel_threads() > 1) {
            // Enough tasks for the threads to share, few enough that appending the right subtrees stays cheap.
            b->task_min = std::max<std::size_t>(4096, n / 64);
            b->bin_parallel_min = 65536;
        }
        b->build(0, n, 0, root);
        t.bounds = t.nodes[0].box();
        t.prim_ids.resize(n);
        for (std::size_t i = 0; i < n; ++i) t.prim_ids[i] = refs[i].id();
    }
    t.stats.build_ms = clock.milliseconds();
    return t;
}

}  // namespace strahl::ch05
