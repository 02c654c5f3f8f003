// REINSERT: one iteration of insertion-based optimisation.
//   J. Bittner, M. Hapala and V. Havran, "Fast insertion-based optimization of bounding volume
//   hierarchies", Computer Graphics Forum 32(1), 2013 (node selection by an inefficiency measure, the
//   branch-and-bound search for the best insertion point);
//   D. Meister and J. Bittner, "Parallel reinsertion for bounding volume hierarchy optimization", Computer
//   Graphics Forum 37(2), 2018 (moving whole subtrees, the simpler form followed here, on one thread).
// Steps:
//   1. SELECT: rank the inner nodes N by inefficiency M(N) = M_area M_sum M_min, with M_area = A(N),
//      M_sum = A(N) / ((A(L) + A(R)) / 2), M_min = A(N) / min(A(L), A(R)), and take the worst `batch`
//      not yet tried in this round (a round ends when every inner node has been tried);
//   2. REMOVE each of N's children X in turn: X's parent P leaves the tree, X's sibling S takes P's place,
//      and the ancestors are refitted;
//   3. SEARCH the insertion point by branch and bound from the root: putting X beside node K costs
//      A(K u X) (the new parent) plus the induced cost, the growth A(anc u X) - A(anc) of every ancestor
//      of K; a subtree below K costs at least the induced cost down to K's children plus A(X), so it is
//      skipped once that bound reaches the best cost found;
//   4. INSERT X beside the best K, reusing P as the new parent, and refit the ancestors.
// Putting X back beside S rebuilds the tree as it was, so the best point never costs more: no move raises
// the SAH cost. A point that would make the tree deeper than max_depth is never taken.
#include "strahl/ch06/refine.hpp"
#include <algorithm>
#include <queue>

namespace strahl::ch06 {

namespace {

double area(const aabb& b) { return double(b.surface_area()); }

// Refits n and every ancestor of it (boxes and heights).
void refit_up(refine_tree& t, std::uint32_t n) {
    for (; n != no_node; n = t.nodes[n].parent) t.refit(n);
}

// Step 1, SELECT: M(N), with zero areas kept finite (a flat or point child makes M_min very large).
double inefficiency(const refine_tree& t, const refine_node& n) {
    const double a = area(n.box), al = area(t.nodes[n.left].box), ar = area(t.nodes[n.right].box);
    if (!(a > 0.0)) return 0.0;
    const double tiny = 1e-12 * a;
    return a * (a / std::max(0.5 * (al + ar), tiny)) * (a / std::max(std::min(al, ar), tiny));
}

// The cost of putting a box b beside node k: the new parent's area plus the growth of k's ancestors.
double insertion_cost(const refine_tree& t, std::uint32_t k, const aabb& b) {
    double c = area(unite(t.nodes[k].box, b));
    for (std::uint32_t a = t.nodes[k].parent; a != no_node; a = t.nodes[a].parent)
        c += area(unite(t.nodes[a].box, b)) - area(t.nodes[a].box);
    return c;
}

struct candidate {
    double bound, induced;
    std::uint32_t node;
    int depth;
    bool operator>(const candidate& o) const { return bound > o.bound || (bound == o.bound && node > o.node); }
};

// Steps 2 to 4 for one subtree x. Returns whether it moved.
bool reinsert(refine_tree& t, std::uint32_t x, int max_depth, std::vector<candidate>& heap) {
    const std::uint32_t p = t.nodes[x].parent;
    if (p == no_node) return false;
    // Step 2, REMOVE: the sibling s takes p's place.
    const std::uint32_t s = t.nodes[p].left == x ? t.nodes[p].right : t.nodes[p].left, g = t.nodes[p].parent;
    if (g == no_node) {
        t.root = s;
        t.nodes[s].parent = no_node;
    } else {
        t.replace_child(g, p, s);
        refit_up(t, g);
    }
    // Step 3, SEARCH: the old place (beside s) is the first best; only a clearly lower cost replaces it.
    const aabb b = t.nodes[x].box;
    const double ab = area(b), old_cost = insertion_cost(t, s, b);
    const int hx = t.nodes[x].height;
    double best_cost = old_cost;
    std::uint32_t best = s;
    heap.clear();
    heap.push_back({ab, 0.0, t.root, 0});
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), std::greater<>{});
        const candidate c = heap.back();
        heap.pop_back();
        if (c.bound >= best_cost) break;  // every candidate left costs at least this much
        const refine_node& k = t.nodes[c.node];
        const double grown = area(unite(k.box, b));
        const double cost = c.induced + grown;
        if (cost < best_cost && c.depth + 1 + std::max(k.height, hx) <= max_depth) best_cost = cost, best = c.node;
        if (k.is_leaf()) continue;
        const double induced = c.induced + grown - area(k.box);
        if (induced + ab >= best_cost) continue;
        for (const std::uint32_t child : {k.left, k.right}) {
            heap.push_back({induced + ab, induced, child, c.depth + 1});
            std::push_heap(heap.begin(), heap.end(), std::greater<>{});
        }
    }
    // A gain lost in rounding is no gain: stay unless the cost falls by more than a millionth.
    if (!(best_cost < old_cost * (1.0 - 1e-6))) best = s;
    // Step 4, INSERT beside best, p reused as the new parent.
    const std::uint32_t bg = t.nodes[best].parent;
    if (bg == no_node) {
        t.root = p;
        t.nodes[p].parent = no_node;
    } else {
        t.replace_child(bg, best, p);
    }
    t.nodes[p].left = best;
    t.nodes[p].right = x;
    t.nodes[best].parent = p;
    t.nodes[x].parent = p;
    refit_up(t, p);
    return best != s;
}

}  // namespace

reinsertion_result reinsertion_pass(refine_tree& t, std::size_t batch, int max_depth, std::vector<std::uint8_t>& tried) {
    reinsertion_result out;
    if (t.root == no_node || batch == 0) return out;
    tried.resize(t.nodes.size(), 0);
    // Step 1, SELECT the batch of worst inner nodes not yet tried in this round (ties by index, so runs
    // repeat exactly); with none left the round is over and begins again.
    std::vector<std::pair<double, std::uint32_t>> ranked;
    for (std::uint32_t i = 0; i < t.nodes.size(); ++i)
        if (!t.nodes[i].is_leaf() && !tried[i]) ranked.push_back({-inefficiency(t, t.nodes[i]), i});
    batch = std::min(batch, ranked.size());
    std::partial_sort(ranked.begin(), ranked.begin() + std::ptrdiff_t(batch), ranked.end());
    std::vector<candidate> heap;
    for (std::size_t i = 0; i < batch; ++i) {
        const refine_node& n = t.nodes[ranked[i].second];
        tried[ranked[i].second] = 1;
        if (n.is_leaf()) continue;
        // Steps 2 to 4 for both children, the larger first.
        std::uint32_t a = n.left, b = n.right;
        if (area(t.nodes[b].box) > area(t.nodes[a].box)) std::swap(a, b);
        out.moves += reinsert(t, a, max_depth, heap) ? 1 : 0;
        out.moves += reinsert(t, b, max_depth, heap) ? 1 : 0;
    }
    if (batch == ranked.size()) {
        out.round_over = true;
        std::fill(tried.begin(), tried.end(), std::uint8_t(0));
    }
    return out;
}

}  // namespace strahl::ch06
