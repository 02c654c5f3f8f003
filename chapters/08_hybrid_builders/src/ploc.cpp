// BUILD-PLOC: Morton order, then rounds of nearest-neighbour search, merging of mutual pairs and
// compaction until one cluster remains.
//   D. Meister and J. Bittner, "Parallel locally-ordered clustering for bounding volume hierarchy
//   construction", IEEE TVCG 24(3), 2018.
#include "strahl/ch08/ploc.hpp"
#include "strahl/ch07/morton.hpp"
#include "strahl/ch07/radix_sort.hpp"
#include "strahl/parallel.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <limits>
#include <stdexcept>

namespace strahl::ch08 {

namespace {

// Positions per chunk of the cluster list. Fixed (not derived from the threads), so the prefix sums over
// chunks, and with them the tree, are the same on any number of threads.
constexpr std::size_t chunk_size = 1024;

// f(c) for every chunk c in [0, count): in parallel where there is more than one.
template <class F>
void for_each_chunk(std::size_t count, F&& f) {
    if (count == 1) return f(std::size_t(0));
    parallel_for_chunks(count, 1, [&](std::size_t begin, std::size_t end) {
        for (std::size_t c = begin; c < end; ++c) f(c);
    });
}

// The cluster list of one round: per position the cluster's node and its box, the boxes as six arrays
// (structure of arrays: the search below runs over 8 or 16 positions per SIMD instruction).
struct clusters {
    std::vector<std::uint32_t> node;
    std::vector<float> lo[3], hi[3];

    std::size_t size() const { return node.size(); }
    void resize(std::size_t m) {
        node.resize(m);
        for (int a = 0; a < 3; ++a) lo[a].resize(m), hi[a].resize(m);
    }
    aabb box(std::size_t i) const {
        return {vec3(lo[0][i], lo[1][i], lo[2][i]), vec3(hi[0][i], hi[1][i], hi[2][i])};
    }
    void set(std::size_t i, std::uint32_t n, const aabb& b) {
        node[i] = n;
        for (int a = 0; a < 3; ++a) lo[a][i] = b.min[a], hi[a][i] = b.max[a];
    }
};

// One row of distances: out[q] = the distance of positions first + q and first + q + k, q < count.
void pair_distances(const clusters& c, std::size_t first, std::size_t count, std::size_t k, float* __restrict out) {
    constexpr float cap = std::numeric_limits<float>::max();
    const float *__restrict lx = c.lo[0].data() + first, *__restrict ly = c.lo[1].data() + first,
                *__restrict lz = c.lo[2].data() + first, *__restrict hx = c.hi[0].data() + first,
                *__restrict hy = c.hi[1].data() + first, *__restrict hz = c.hi[2].data() + first;
    for (std::size_t q = 0; q < count; ++q) {
        const float dx = std::max(hx[q], hx[q + k]) - std::min(lx[q], lx[q + k]);
        const float dy = std::max(hy[q], hy[q + k]) - std::min(ly[q], ly[q + k]);
        const float dz = std::max(hz[q], hz[q + k]) - std::min(lz[q], lz[q + k]);
        const float d = dx * dy + dy * dz + dz * dx;
        out[q] = d < cap ? d : cap;  // inf and NaN: cap
    }
}

// Per position at = begin + p, p in [0, count): the better of its two pairs at gap k (row holds the
// distances at gap k from position begin - r on: row[r + p] is the pair (at, at + k), row[r + p - k] the
// pair (at - k, at)) replaces its best (best[p], nn[p]) where strictly nearer. Equal distances at one gap:
// the pair whose lower position is even, so the left pair unless k is odd and at even. Branch-free, so
// that it vectorises.
void offer_gap(const float* __restrict row, std::uint32_t begin, std::uint32_t count, std::uint32_t k,
               std::uint32_t r, float* __restrict best, std::uint32_t* __restrict nn) {
    for (std::uint32_t p = 0; p < count; ++p) {
        const std::uint32_t at = begin + p;
        const float right = row[r + p], left = row[r + p - k];
        const bool take_left = left < right || (left == right && !((k & 1) != 0 && (at & 1) == 0));
        const float d = take_left ? left : right;
        const std::uint32_t j = take_left ? at - k : at + k;
        const bool nearer = d < best[p];
        best[p] = nearer ? d : best[p];
        nn[p] = nearer ? j : nn[p];
    }
}

// a. Nearest neighbour of every position p in [begin, end) among the positions within r of it.
//    The distance of two clusters: the surface area of the box around both (halved: the order is the
//    same), in float; an area that overflows (a 1e30 box), or is NaN (inf times a zero extent), counts as
//    FLT_MAX, and +inf marks "no such position".
//    First every distance of a pair at gap k (1..r) with a member in the chunk, once per pair, gap by gap:
//    dist[k - 1][q] for the pair (i, i + k), q = i - (begin - r), a contiguous row per gap (vectorised).
//    Then per gap k ascending, per position p, the better of its two pairs at that gap, (p - k, p) and
//    (p, p + k), replaces p's best only where strictly nearer. Equal distances are thus ordered by the gap,
//    then by the parity of the pair's lower position (even first), then by the lower position (the left
//    pair): a strict order on pairs, the same seen from both members, so the least pair of all is mutual
//    and every round merges at least once; equal boxes (copies) pair up as (0,1), (2,3), ... instead of
//    all choosing the first one.
void nearest_neighbours(const clusters& c, std::size_t begin, std::size_t end, std::size_t r,
                        std::vector<std::uint32_t>& nn) {
    const std::size_t m = c.size(), width = end - begin + r;  // positions begin - r .. end - 1
    constexpr float none_here = std::numeric_limits<float>::infinity();
    std::vector<float> dist(r * width);
    for (std::size_t k = 1; k <= r; ++k) {
        float* row = dist.data() + (k - 1) * width;
        // Valid pairs (i, i + k): i >= 0 and i + k < m, i.e. q in [q0, q1) with i = begin - r + q.
        const std::size_t q0 = begin >= r ? 0 : r - begin;
        const std::size_t q1 = std::max(q0, m >= k ? std::min(width, m - k + r - begin) : q0);
        std::fill(row, row + q0, none_here);
        pair_distances(c, begin + q0 - r, q1 - q0, k, row + q0);
        std::fill(row + q1, row + width, none_here);
    }
    std::vector<float> best(end - begin, none_here);
    for (std::size_t k = 1; k <= r; ++k)
        offer_gap(dist.data() + (k - 1) * width, std::uint32_t(begin), std::uint32_t(end - begin), std::uint32_t(k),
                  std::uint32_t(r), best.data(), nn.data() + begin);
}

}  // namespace

std::vector<std::uint32_t> ploc_nearest_neighbours(std::span<const aabb> boxes, int radius) {
    if (boxes.size() < 2) throw std::invalid_argument("ploc_nearest_neighbours: fewer than two clusters");
    clusters c;
    c.resize(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) c.set(i, std::uint32_t(i), boxes[i]);
    std::vector<std::uint32_t> nn(boxes.size(), 0);
    nearest_neighbours(c, 0, boxes.size(), std::size_t(std::clamp(radius, 1, 256)), nn);
    return nn;
}

std::string to_string(const ploc_params& p) {
    return "ploc" + std::to_string(p.radius) + (p.bits_per_axis == 21 ? "-63" : "");
}

binary_tree build_ploc(std::span<const aabb> boxes, std::span<const vec3> centroids, const ploc_params& params,
                       ploc_report* report) {
    if (boxes.size() != centroids.size()) throw std::invalid_argument("build_ploc: one centroid per box");
    if (params.bits_per_axis != 10 && params.bits_per_axis != 21)
        throw std::invalid_argument("build_ploc: bits_per_axis must be 10 or 21");
    const std::size_t r = std::size_t(std::clamp(params.radius, 1, 256));
    ploc_report rep;
    timer phase;
    binary_tree t;

    // 1. Codes and sort (chapter 07): the loose primitives set aside, the others in Morton order.
    ch07::morton_codes codes = ch07::compute_morton_codes(boxes, centroids, params.bits_per_axis);
    ch07::radix_sort_params sort;
    sort.key_bits = 3 * params.bits_per_axis;
    ch07::radix_sort(codes.keys, codes.ids, sort);
    t.loose = std::move(codes.loose);
    rep.codes_sort_ms = phase.milliseconds(), phase.restart();
    const std::size_t n = codes.ids.size();
    if (n == 0) {
        if (report) *report = rep;
        return t;
    }

    // 2. Clusters: the sorted leaves. Leaf k (node k) holds the k-th primitive in Morton order.
    t.nodes.resize(2 * n - 1);
    clusters cur, next;
    cur.resize(n);
    for_each_chunk((n + chunk_size - 1) / chunk_size, [&](std::size_t c) {
        for (std::size_t k = c * chunk_size, end = std::min(n, k + chunk_size); k < end; ++k) {
            t.nodes[k].box = boxes[codes.ids[k]];
            t.nodes[k].prim = codes.ids[k];
            cur.set(k, std::uint32_t(k), t.nodes[k].box);
        }
    });

    // 3. Rounds until one cluster remains.
    std::size_t made = 0;  // inner nodes so far: the next is node n + made
    std::vector<std::uint32_t> nn, kept_before, made_before;
    while (cur.node.size() > 1) {
        ++rep.iterations;
        const std::size_t m = cur.node.size(), chunks = (m + chunk_size - 1) / chunk_size;
        // a. Nearest neighbours.
        nn.assign(m, 0);
        for_each_chunk(chunks, [&](std::size_t c) {
            nearest_neighbours(cur, c * chunk_size, std::min(m, (c + 1) * chunk_size), r, nn);
        });
        // b. and c., counting: per chunk, the clusters it keeps and the inner nodes it makes (the lower
        //    member of a mutual pair makes the parent and keeps its place; the upper one's place goes).
        kept_before.assign(chunks + 1, 0), made_before.assign(chunks + 1, 0);
        for_each_chunk(chunks, [&](std::size_t c) {
            std::uint32_t kept = 0, merged = 0;
            for (std::size_t i = c * chunk_size, end = std::min(m, i + chunk_size); i < end; ++i) {
                const bool mutual = nn[nn[i]] == i;
                kept += !mutual || i < nn[i];
                merged += mutual && i < nn[i];
            }
            kept_before[c + 1] = kept, made_before[c + 1] = merged;
        });
        for (std::size_t c = 0; c < chunks; ++c)  // exclusive prefix sums over the chunks
            kept_before[c + 1] += kept_before[c], made_before[c + 1] += made_before[c];
        // b. Merge and c. compact: each chunk writes its clusters from its prefix sums on.
        next.resize(kept_before[chunks]);
        for_each_chunk(chunks, [&](std::size_t c) {
            std::size_t out = kept_before[c], node = n + made + made_before[c];
            for (std::size_t i = c * chunk_size, end = std::min(m, i + chunk_size); i < end; ++i) {
                const std::size_t j = nn[i];
                const bool mutual = nn[j] == i;
                if (mutual && j < i) continue;  // merged into the cluster at j
                if (!mutual) {
                    next.set(out++, cur.node[i], cur.box(i));
                    continue;
                }
                tree_node& parent = t.nodes[node];
                parent.box = unite(cur.box(i), cur.box(j));
                parent.left = cur.node[i], parent.right = cur.node[j];
                t.nodes[cur.node[i]].parent = t.nodes[cur.node[j]].parent = std::uint32_t(node);
                next.set(out++, std::uint32_t(node++), parent.box);
            }
        });
        made += made_before[chunks];
        std::swap(cur, next);
    }
    t.root = cur.node[0];
    rep.cluster_ms = phase.milliseconds();
    if (report) *report = rep;
    return t;
}

}  // namespace strahl::ch08
