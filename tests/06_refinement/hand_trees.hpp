// Small hand-made trees for chapter 06's exercises, with boxes whose areas are worked out by hand.
#pragma once
#include "strahl/ch06/refine.hpp"
#include <initializer_list>

namespace strahl::test {

inline aabb box(vec3 lo, vec3 hi) { return {lo, hi}; }

// A leaf with the given box (one primitive), returns its index.
inline std::uint32_t add_leaf(ch06::refine_tree& t, const aabb& b) {
    ch06::refine_node n;
    n.box = b;
    n.first = std::uint32_t(t.prim_ids.size());
    n.count = 1;
    t.prim_ids.push_back(n.first);
    t.nodes.push_back(n);
    return std::uint32_t(t.nodes.size() - 1);
}
// An inner node over two existing nodes (box and height refitted), returns its index.
inline std::uint32_t add_inner(ch06::refine_tree& t, std::uint32_t l, std::uint32_t r) {
    ch06::refine_node n;
    n.left = l;
    n.right = r;
    t.nodes.push_back(n);
    const auto i = std::uint32_t(t.nodes.size() - 1);
    t.nodes[l].parent = t.nodes[r].parent = i;
    t.refit(i);
    return i;
}

// Unit cross-section (y and z in [0, 1]) from x0 to x1: area 4 (x1 - x0) + 2.
inline aabb bar(float x0, float x1) { return box(vec3(x0, 0, 0), vec3(x1, 1, 1)); }

// Tree 1: N = (A, R), R = (X, Y); A = bar(10, 11), X = bar(0, 1), Y = bar(11, 12). A(R) = 50.
//   L <-> RL: R becomes (A, Y) = bar(10, 12), area 10: -40.  L <-> RR: R becomes (X, A) = bar(0, 11): -4.
//   R <-> LL and R <-> LR: L is a leaf, impossible.
struct tree1 {
    ch06::refine_tree t;
    std::uint32_t n, a, r, x, y;
};
inline tree1 make_tree1() {
    tree1 k;
    k.a = add_leaf(k.t, bar(10, 11));
    k.x = add_leaf(k.t, bar(0, 1));
    k.y = add_leaf(k.t, bar(11, 12));
    k.r = add_inner(k.t, k.x, k.y);
    k.n = add_inner(k.t, k.a, k.r);
    k.t.root = k.n;
    return k;
}

// Tree 2: N = (L, R), L = (LL, LR), R = (RL, RR), boxes in 3D:
//   LL = [0,1]x[0,2]x[0,3], LR = [4,5]x[0,1]x[0,1], RL = [0,1]x[0,1]x[5,6], RR = [4,6]x[1,2]x[0,1];
//   L = [0,5]x[0,2]x[0,3], area 62; R = [0,6]x[0,2]x[0,6], area 120.
//   L <-> RL: R' = L u RR = [0,6]x[0,2]x[0,3], area 72: -48;  L <-> RR: R' = RL u L = [0,5]x[0,2]x[0,6], 104: -16;
//   R <-> LL: L' = R u LR = [0,6]x[0,2]x[0,6], 120: +58;     R <-> LR: L' = LL u R, also 120: +58.
struct tree2 {
    ch06::refine_tree t;
    std::uint32_t n, l, r, ll, lr, rl, rr;
};
inline tree2 make_tree2() {
    tree2 k;
    k.ll = add_leaf(k.t, box(vec3(0, 0, 0), vec3(1, 2, 3)));
    k.lr = add_leaf(k.t, box(vec3(4, 0, 0), vec3(5, 1, 1)));
    k.rl = add_leaf(k.t, box(vec3(0, 0, 5), vec3(1, 1, 6)));
    k.rr = add_leaf(k.t, box(vec3(4, 1, 0), vec3(6, 2, 1)));
    k.l = add_inner(k.t, k.ll, k.lr);
    k.r = add_inner(k.t, k.rl, k.rr);
    k.n = add_inner(k.t, k.l, k.r);
    k.t.root = k.n;
    return k;
}

// Tree 3: N = (L, R), L = (A, C), R = (B, D); A = bar(0, 1), B = bar(1, 2), C = bar(10, 11), D = bar(11, 12).
//   A(L) = A(R) = 46. L <-> RL: R' = bar(0, 12): +4; L <-> RR: R' = bar(0, 11): 0; R <-> LL: L' = bar(1, 12):
//   0; R <-> LR: L' = bar(0, 12): +4. No rotation lowers the cost.
inline ch06::refine_tree make_tree3() {
    ch06::refine_tree t;
    const auto a = add_leaf(t, bar(0, 1)), b = add_leaf(t, bar(1, 2)), c = add_leaf(t, bar(10, 11)),
               d = add_leaf(t, bar(11, 12));
    const auto l = add_inner(t, a, c), r = add_inner(t, b, d);
    t.root = add_inner(t, l, r);
    return t;
}

inline bool same_box(const aabb& a, const aabb& b) { return a.min == b.min && a.max == b.max; }

}  // namespace strahl::test
