// Collapsing a binary BVH into a wide one (wide_bvh.hpp): the greedy rule of Wald, Benthin and Boulos (2008)
// and the SAH-optimal choice by dynamic programming (Pinto 2010; Ylitie, Karras and Laine 2017, section 4).
#include "strahl/ch13/wide_bvh.hpp"
#include "strahl/timer.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <span>
#include <string>

namespace strahl::ch13 {

const char* to_string(collapse_method m) { return m == collapse_method::greedy ? "greedy" : "optimal"; }

namespace {

constexpr float infinite_cost = std::numeric_limits<float>::infinity();

template <int N, int M>
class collapser {
public:
    collapser(const ch04::bvh& t, const triangle_mesh& mesh, wide_bvh<N, M>& out) : t_(t), mesh_(mesh), out_(out) {}

    // The binary node i's two children.
    std::uint32_t left(std::uint32_t i) const { return i + 1; }
    std::uint32_t right(std::uint32_t i) const { return t_.nodes[i].offset; }
    bool leaf(std::uint32_t i) const { return t_.nodes[i].is_leaf(); }
    float area(std::uint32_t i) const { return t_.nodes[i].box().surface_area(); }

    // The triangles of binary subtree i, in leaf order, into blocks of M; its reference.
    std::uint32_t make_leaf(std::uint32_t i) {
        std::vector<std::uint32_t>& ids = scratch_;  // (reused: no allocation per leaf)
        ids.clear();
        gather(i, ids);
        const std::size_t blocks = (ids.size() + M - 1) / M;
        if (blocks > max_leaf_blocks)
            throw std::length_error("wide BVH: a leaf of " + std::to_string(ids.size()) + " triangles needs more than " +
                                    std::to_string(max_leaf_blocks) + " blocks of " + std::to_string(M));
        const std::size_t first = out_.blocks.size();
        if (first + blocks > max_blocks) throw std::length_error("wide BVH: more than 2^25 triangle blocks");
        out_.blocks.resize(first + blocks);
        for (std::size_t b = 0; b < blocks; ++b) {
            triangle_block<M>& blk = out_.blocks[first + b];
            for (int lane = 0; lane < M; ++lane) {
                // Unused lanes repeat the block's last triangle: the same answer twice changes nothing.
                const std::size_t k = std::min(b * M + std::size_t(lane), ids.size() - 1);
                const auto v = mesh_.triangle(ids[k]);
                const vec3 e1 = v[1] - v[0], e2 = v[2] - v[0];  // as exercise 01.3 computes them
                for (int a = 0; a < 3; ++a) {
                    blk.v0[a][lane] = v[0][a];
                    blk.e1[a][lane] = e1[a];
                    blk.e2[a][lane] = e2[a];
                }
                blk.id[lane] = ids[k];
            }
        }
        ++out_.stats.leaves;
        out_.stats.blocks += blocks;
        out_.stats.triangles += ids.size();
        return leaf_ref(std::uint32_t(first), std::uint32_t(blocks));
    }

    // A wide node over the given binary nodes (at most N), each child made by make(child).
    template <class Make>
    std::uint32_t make_node(std::span<const std::uint32_t> kids, Make&& make) {
        const std::uint32_t index = std::uint32_t(out_.nodes.size());
        out_.nodes.emplace_back();
        ++out_.stats.inner;
        out_.stats.used_slots += kids.size();
        std::uint32_t refs[N] = {};
        for (std::size_t k = 0; k < kids.size(); ++k) refs[k] = make(kids[k]);  // (may grow out_.nodes)
        wide_node<N>& n = out_.nodes[index];
        for (int k = 0; k < N; ++k) {
            const bool used = std::size_t(k) < kids.size();
            for (int a = 0; a < 3; ++a) {
                n.lo[a][k] = used ? t_.nodes[kids[k]].bmin[a] : std::numeric_limits<float>::infinity();
                n.hi[a][k] = used ? t_.nodes[kids[k]].bmax[a] : -std::numeric_limits<float>::infinity();
            }
            n.child[k] = used ? refs[k] : 0;
            n.order[k] = std::uint8_t(k);
        }
        if constexpr (N == 8)
            for (int o = 0; o < 8; ++o) n.set_octant_word(o, 0xFAC688u);  // the stored order: slots 0..7, 3 bits each
        return index;
    }

    // Greedy: open the largest inner child until N children (exercise 13.1 chooses which). Writes the wide
    // node's children (binary nodes) for inner node i; returns how many.
    int greedy_kids(std::uint32_t i, std::uint32_t (&kids)[N]) const {
        int count = 2;
        kids[0] = left(i), kids[1] = right(i);
        while (count < N) {
            float areas[N];
            bool leaves[N];
            for (int k = 0; k < count; ++k) areas[k] = area(kids[k]), leaves[k] = leaf(kids[k]);
            const int open = child_to_open({areas, std::size_t(count)}, {leaves, std::size_t(count)});
            if (open < 0) break;
            if (open >= count || leaves[open])
                throw std::logic_error("child_to_open chose child " + std::to_string(open) + " of " +
                                       std::to_string(count) + ", not an inner one");
            const std::uint32_t opened = kids[open];
            kids[open] = left(opened);
            kids[count++] = right(opened);
        }
        return count;
    }
    std::uint32_t greedy(std::uint32_t i) {
        if (leaf(i)) return make_leaf(i);
        std::uint32_t kids[N];
        const int count = greedy_kids(i, kids);
        return make_node({kids, std::size_t(count)}, [&](std::uint32_t k) { return greedy(k); });
    }

    // Optimal (Ylitie et al. 2017, with M-wide blocks): cost[i][j] is the cheapest SAH cost of binary subtree
    // i represented as at most j subtrees side by side (j = 1: one leaf or one wide node).
    void optimal_costs(int max_leaf, float c_node, float c_block) {
        const std::size_t n = t_.nodes.size();
        cost_.assign(n, {});
        split_.assign(n, {});
        tris_.assign(n, 0);
        leaf_choice_.assign(n, false);
        node_split_.assign(n, 1);
        for (std::size_t ii = n; ii-- > 0;) {
            const std::uint32_t i = std::uint32_t(ii);
            const float a = area(i);
            if (leaf(i)) {
                tris_[i] = t_.nodes[i].count;
                const float c = a * c_block * float((tris_[i] + M - 1) / M);
                for (int j = 1; j <= N; ++j) cost_[i][j] = c, split_[i][j] = j == 1 ? 0 : -1;  // one slot is all it uses
                leaf_choice_[i] = true;
                continue;
            }
            const std::uint32_t l = left(i), r = right(i);
            tris_[i] = tris_[l] + tris_[r];
            // Distributing j slots over the two children.
            float dist[N + 1];
            int best_k[N + 1];
            for (int j = 2; j <= N; ++j) {
                dist[j] = infinite_cost, best_k[j] = 1;
                for (int k = 1; k < j; ++k) {
                    const float c = cost_[l][k] + cost_[r][j - k];
                    if (c < dist[j]) dist[j] = c, best_k[j] = k;
                }
            }
            node_split_[i] = std::int8_t(best_k[N]);  // a wide node here splits its N slots so
            const float as_node = a * c_node + dist[N];
            const float as_leaf = tris_[i] <= std::uint32_t(max_leaf) ? a * c_block * float((tris_[i] + M - 1) / M)
                                                                      : infinite_cost;
            leaf_choice_[i] = as_leaf <= as_node;
            cost_[i][1] = std::min(as_leaf, as_node);
            split_[i][1] = 0;
            for (int j = 2; j <= N; ++j) {
                // Either fewer slots suffice, or the two children share j.
                if (cost_[i][j - 1] <= dist[j]) cost_[i][j] = cost_[i][j - 1], split_[i][j] = -1;
                else cost_[i][j] = dist[j], split_[i][j] = std::int8_t(best_k[j]);
            }
        }
    }

    // The binary nodes that become the wide children of subtree i given j slots, appended to kids[count++].
    void distribute(std::uint32_t i, int j, std::uint32_t (&kids)[N], int& count) const {
        while (j > 1 && split_[i][j] == -1) --j;
        if (j == 1) {
            kids[count++] = i;
            return;
        }
        const int k = split_[i][j];
        distribute(left(i), k, kids, count);
        distribute(right(i), j - k, kids, count);
    }
    int optimal_kids(std::uint32_t i, std::uint32_t (&kids)[N]) const {
        int count = 0;
        const int k = node_split_[i];
        distribute(left(i), k, kids, count);
        distribute(right(i), N - k, kids, count);
        return count;
    }

    std::uint32_t optimal(std::uint32_t i) {
        if (leaf_choice_[i]) return make_leaf(i);
        std::uint32_t kids[N];
        const int count = optimal_kids(i, kids);
        return make_node({kids, std::size_t(count)}, [&](std::uint32_t c) { return optimal(c); });
    }

    // The wide tree's size before it is written: its nodes and blocks, counted along the same choices, so
    // that each array is allocated once at its size (huge_pages.hpp fills fresh memory in one go).
    void count(std::uint32_t i, bool greedy_method, std::size_t& nodes, std::size_t& blocks) const {
        if (greedy_method ? leaf(i) : bool(leaf_choice_[i])) {
            blocks += (triangles(i) + M - 1) / M;
            return;
        }
        ++nodes;
        std::uint32_t kids[N];
        const int n = greedy_method ? greedy_kids(i, kids) : optimal_kids(i, kids);
        for (int k = 0; k < n; ++k) count(kids[k], greedy_method, nodes, blocks);
    }

private:
    // Triangles under a node count() makes a leaf: the dynamic program's count, or (greedy, which computes
    // none) a binary leaf's own.
    std::size_t triangles(std::uint32_t i) const { return tris_.empty() ? t_.nodes[i].count : tris_[i]; }
    void gather(std::uint32_t i, std::vector<std::uint32_t>& ids) const {
        const ch04::bvh_node& n = t_.nodes[i];
        if (n.is_leaf()) {
            ids.insert(ids.end(), t_.prim_ids.begin() + n.offset, t_.prim_ids.begin() + n.offset + n.count);
            return;
        }
        gather(left(i), ids);
        gather(right(i), ids);
    }

    const ch04::bvh& t_;
    const triangle_mesh& mesh_;
    wide_bvh<N, M>& out_;
    huge_vector<std::array<float, N + 1>> cost_;        // (float: half the memory of double, which Sponza's
    huge_vector<std::array<std::int8_t, N + 1>> split_; // 500,000 binary nodes make worth it at N = 16)
    std::vector<std::uint32_t> scratch_;
    huge_vector<std::uint32_t> tris_;
    std::vector<bool> leaf_choice_;
    std::vector<std::int8_t> node_split_;  // slots a wide node at binary node i gives its left child
};

}  // namespace

template <int N, int M>
wide_bvh<N, M> collapse(const ch04::bvh& tree, const triangle_mesh& mesh, const collapse_config& config) {
    timer clock;
    wide_bvh<N, M> out;
    out.set_bounds(tree.bounds);
    out.loose = tree.loose;
    if (tree.nodes.empty()) return out;
    collapser<N, M> c(tree, mesh, out);
    const bool greedy = config.method == collapse_method::greedy;
    if (!greedy)
        c.optimal_costs(std::clamp(config.max_leaf, 1, int(max_leaf_blocks) * M), float(config.c_node),
                        float(config.c_block));
    std::size_t nodes = 0, blocks = 0;
    c.count(0, greedy, nodes, blocks);
    out.nodes.reserve(nodes);
    out.blocks.reserve(blocks);
    out.root_ref = greedy ? c.greedy(0) : c.optimal(0);
    out.stats.ms = clock.milliseconds();
    out.stats.sah = sah_of(out, config.c_node, config.c_block);
    return out;
}

template <int N, int M>
double sah_of(const wide_bvh<N, M>& tree, double c_node, double c_block) {
    const double root = tree.bounds.surface_area();
    if (tree.nodes.empty() && !is_leaf(tree.root_ref)) return 0.0;
    if (!(root > 0.0)) return 0.0;
    double sum = 0.0;
    // The root's area for the root (a node or a leaf), each child's box for the others.
    if (is_leaf(tree.root_ref)) return c_block * leaf_blocks(tree.root_ref);
    sum += root * c_node;
    for (const wide_node<N>& n : tree.nodes)
        for (int k = 0; k < N; ++k) {
            if (!n.used(k)) continue;
            const double a = n.box(k).surface_area();
            sum += is_leaf(n.child[k]) ? a * c_block * leaf_blocks(n.child[k]) : a * c_node;
        }
    return sum / root;
}

// The widths the course builds: nodes of 4, 8 and 16 children, blocks of 4 and 8 triangles.
template wide_bvh<4, 4> collapse<4, 4>(const ch04::bvh&, const triangle_mesh&, const collapse_config&);
template wide_bvh<8, 4> collapse<8, 4>(const ch04::bvh&, const triangle_mesh&, const collapse_config&);
template wide_bvh<8, 8> collapse<8, 8>(const ch04::bvh&, const triangle_mesh&, const collapse_config&);
template wide_bvh<16, 4> collapse<16, 4>(const ch04::bvh&, const triangle_mesh&, const collapse_config&);
template wide_bvh<16, 8> collapse<16, 8>(const ch04::bvh&, const triangle_mesh&, const collapse_config&);
template double sah_of<4, 4>(const wide_bvh<4, 4>&, double, double);
template double sah_of<8, 4>(const wide_bvh<8, 4>&, double, double);
template double sah_of<8, 8>(const wide_bvh<8, 8>&, double, double);
template double sah_of<16, 4>(const wide_bvh<16, 4>&, double, double);
template double sah_of<16, 8>(const wide_bvh<16, 8>&, double, double);

}  // namespace strahl::ch13
