// The two hierarchy builders over sorted codes (radix_tree.hpp): the lecture's, top down with exercise
// 07.3's split search, and Karras's, every inner node independently (Karras 2012, section 4, figure 4).
#include "strahl/ch07/radix_tree.hpp"
#include "strahl/parallel.hpp"
#include <stdexcept>
#include <tbb/parallel_invoke.h>

namespace strahl::ch07 {

void radix_tree::resize(std::size_t n_leaves) {
    const std::size_t inner = n_leaves > 1 ? n_leaves - 1 : 0;
    for (std::vector<std::uint32_t>* v : {&left, &right, &parent, &first, &last}) v->assign(inner, none);
    leaf_parent.assign(n_leaves, none);
}

namespace {

void check(std::span<const std::uint64_t> codes) {
    if (codes.size() >= std::size_t(leaf_bit))
        throw std::invalid_argument("radix tree: at most 2^31 - 1 codes (a child reference has 31 bits)");
}

// Links inner node `node` (range [first, last], split after g) to its two children, numbered as Karras's.
void link(radix_tree& t, std::uint32_t node, std::uint32_t first, std::uint32_t last, std::uint32_t g) {
    t.first[node] = first;
    t.last[node] = last;
    if (first == g) {
        t.left[node] = g | leaf_bit;
        t.leaf_parent[g] = node;
    } else {
        t.left[node] = g;
        t.parent[g] = node;
    }
    if (last == g + 1) {
        t.right[node] = (g + 1) | leaf_bit;
        t.leaf_parent[g + 1] = node;
    } else {
        t.right[node] = g + 1;
        t.parent[g + 1] = node;
    }
}

// The lecture's BUILD(first, last) for inner node `node`: split, link, recurse into the inner children;
// ranges of more than 2^14 leaves hand their halves to TBB as two tasks.
void build_lecture(std::span<const std::uint64_t> codes, radix_tree& t, std::uint32_t node, std::uint32_t first,
                   std::uint32_t last) {
    const std::uint32_t g = find_split(codes, first, last);
    link(t, node, first, last, g);
    const auto left = [&] {
        if (first != g) build_lecture(codes, t, g, first, g);
    };
    const auto right = [&] {
        if (last != g + 1) build_lecture(codes, t, g + 1, g + 1, last);
    };
    if (last - first > (1u << 14))
        tbb::parallel_invoke(left, right);
    else
        left(), right();
}

}  // namespace

void build_radix_tree_lecture(std::span<const std::uint64_t> codes, radix_tree& out) {
    check(codes);
    out.resize(codes.size());
    if (codes.size() > 1) build_lecture(codes, out, 0, 0, std::uint32_t(codes.size() - 1));
}

void build_radix_tree_karras(std::span<const std::uint64_t> codes, radix_tree& out) {
    check(codes);
    out.resize(codes.size());
    const auto n = std::int64_t(codes.size());
    const auto delta = [&](std::int64_t i, std::int64_t j) { return karras_delta(codes, i, j); };
    parallel_for_chunks(std::size_t(n > 1 ? n - 1 : 0), 1024, [&](std::size_t begin, std::size_t end) {
        for (std::int64_t i = std::int64_t(begin); i < std::int64_t(end); ++i) {
            // 1. The direction of node i's range: towards the neighbour sharing the longer prefix.
            const std::int64_t d = delta(i, i + 1) - delta(i, i - 1) > 0 ? 1 : -1;
            // 2. An upper bound on the range's length: double l_max while the prefix stays longer than
            //    the one i shares with its neighbour on the other side.
            const int delta_min = delta(i, i - d);
            std::int64_t l_max = 2;
            while (delta(i, i + l_max * d) > delta_min) l_max *= 2;
            // 3. The other end j, by binary search below l_max.
            std::int64_t l = 0;
            for (std::int64_t step = l_max / 2; step >= 1; step /= 2)
                if (delta(i, i + (l + step) * d) > delta_min) l += step;
            const std::int64_t j = i + l * d;
            // 4. The split: the last position from i (towards j) sharing more than the node's prefix.
            const int delta_node = delta(i, j);
            std::int64_t s = 0;
            for (std::int64_t step = (l + 1) / 2;; step = (step + 1) / 2) {
                if (delta(i, i + (s + step) * d) > delta_node) s += step;
                if (step == 1) break;
            }
            const std::int64_t g = i + s * d + std::min<std::int64_t>(d, 0);
            // 5. Children and parents: each child has one parent, so no two threads write one entry.
            link(out, std::uint32_t(i), std::uint32_t(std::min(i, j)), std::uint32_t(std::max(i, j)), std::uint32_t(g));
        }
    });
}

}  // namespace strahl::ch07
