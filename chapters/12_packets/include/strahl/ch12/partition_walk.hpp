// Large packets (64 to 256 rays) with an active-ray list partitioned at every node: the rays that enter a
// node's box are moved to the front of the list, and the node's subtree sees only them, however scattered
// they were in the packet (R. Overbeck, R. Ramamoorthi and W. R. Mark, "Large ray packets for real-time
// Whitted ray tracing", IEEE Symposium on Interactive Ray Tracing 2008). Rays are tested K at a time,
// gathered from the list. As in the ranged walk, the first ray of the list is tested first (if it enters,
// the node is entered with the whole list, unpartitioned), and a coherent packet's frustum may cull a node
// for every ray at once.
#pragma once
#include "strahl/ch04/bvh.hpp"
#include "strahl/ch12/binary_walks.hpp"
#include "strahl/ch12/packet.hpp"
#include <bit>
#include <cstdint>

namespace strahl::ch12 {

// Exercise 12.3 (packet_tests.cpp): the partition step. ids[0 .. count-1] lists rays of the packet; enters(i)
// says whether ray ids[i] enters the node (bits, K rays a call: see partition_walk). Reorders ids[0 ..
// count-1] so that the rays that enter come first, keeping every id in the range (the rays that miss move
// behind them: the node's siblings still need them), and returns how many enter.
template <int K, class Enters>
int partition_active(std::uint16_t* ids, int count, Enters&& enters);

template <bool Coherent, int K, int V, class Stats, class Leaf>
void partition_walk(const ch04::bvh& tree, ray_packet<K, V>& p, Stats& stats, Leaf&& leaf) {
    constexpr int P = K * V;
    std::uint16_t ids[P];
    int count = 0;
    for (int i = 0; i < P; ++i)
        if ((p.active[i / K] >> (i % K)) & 1u) ids[count++] = std::uint16_t(i);
    struct entry {
        std::uint32_t node;
        int count;
    };
    entry stack[ch04::bvh_max_depth + 2];
    int top = 0;
    const ch04::bvh_node* nodes = tree.nodes.data();
    const auto still_active = [&](int i) { return (p.active[i / K] >> (i % K)) & 1u; };
    std::uint32_t index = 0;
    for (;;) {
        if (count > 0) {
            const ch04::bvh_node& n = nodes[index];
            stats.node_visit();
            simd::vfloat<K> t;
            // The K rays of the list from position `at`, as lane bits of those that enter the box.
            const auto test = [&](int at) {
                const int m = count - at < K ? count - at : K;
                stats.box_test(m);
                const unsigned valid = m == 32 ? ~0u : (1u << m) - 1;
                const unsigned in = simd::movemask(packet_box<Coherent>(gather(p, ids + at, m), n.bmin, n.bmax, p.octant, t)) & valid;
                count_lanes(stats, std::popcount(in), K);
                return in;
            };
            int in = 0;
            // 1. The first K rays: if the first of them enters, so does the whole list.
            unsigned first = test(0);
            if (first & 1u) in = count;
            // 2. The frustum, 3. the partition.
            else if (!(Coherent && frustum_misses(p, n.bmin, n.bmax)))
                in = partition_active<K>(ids, count, [&](int at) { return at == 0 ? first : test(at); });
            // (Any hit: rays answered since are dropped from the range.)
            if (in > 0 && n.is_leaf()) {
                for (int at = 0; at < in; at += K) {
                    const int m = in - at < K ? in - at : K;
                    unsigned lanes = 0;
                    for (int j = 0; j < m; ++j) lanes |= unsigned(still_active(ids[at + j])) << j;
                    if (lanes != 0)
                        leaf(gather(p, ids + at, m), lanes, [&, at](int j) { return int(ids[at + j]); }, n.offset,
                             std::uint32_t(n.count));
                }
            } else if (in > 0) {
                const int lead = ids[0];
                const bool down = std::signbit(p.dir[n.axis][lead]);
                stack[top++] = {down ? index + 1 : n.offset, in};
                index = down ? n.offset : index + 1;
                count = in;
                continue;
            }
        }
        if (top == 0) return;
        --top;
        index = stack[top].node, count = stack[top].count;
        // Any hit: rays answered meanwhile leave the list (they are never tested again).
        int kept = 0;
        for (int i = 0; i < count; ++i)
            if (still_active(ids[i])) std::swap(ids[kept++], ids[i]);
        count = kept;
    }
}

}  // namespace strahl::ch12
