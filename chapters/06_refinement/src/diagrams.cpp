// The chapter's figure, computed by the chapter's own rotation code (`ch06 --diagrams DIR`):
//   rotation.svg: the four-leaf tree of the exercises' tests (tests/06_refinement/hand_trees.hpp, tree 2)
//   before and after its best rotation, every node with its box's surface area, the four rotations' cost
//   changes (rotation_cost, exercise 06.1), the one applied (apply_best_rotation, 06.2) and the tree's SAH
//   cost before and after.
#include "strahl/ch06/refine.hpp"
#include "strahl/diagram.hpp"
#include "strahl/program.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace strahl::ch06 {

namespace {

std::string number(double v, bool sign = false) { return number_text(v, sign ? "%+.4g" : "%.4g"); }

std::uint32_t add_leaf(refine_tree& t, vec3 lo, vec3 hi) {
    refine_node n;
    n.box = {lo, hi};
    n.first = std::uint32_t(t.prim_ids.size());
    n.count = 1;
    t.prim_ids.push_back(n.first);
    t.nodes.push_back(n);
    return std::uint32_t(t.nodes.size() - 1);
}

std::uint32_t add_inner(refine_tree& t, std::uint32_t l, std::uint32_t r) {
    refine_node n;
    n.left = l, n.right = r;
    t.nodes.push_back(n);
    const auto i = std::uint32_t(t.nodes.size() - 1);
    t.nodes[l].parent = t.nodes[r].parent = i;
    t.refit(i);
    return i;
}

// Sums over the tree below n: inner nodes' areas, and leaves' areas times their primitive counts; the
// inner areas also as a text, "a + b + c", in depth-first order.
void sums(const refine_tree& t, std::uint32_t n, double& inner, double& leaves, std::string& terms) {
    const refine_node& x = t.nodes[n];
    if (x.is_leaf()) { leaves += double(x.count) * x.box.surface_area(); return; }
    inner += x.box.surface_area();
    terms += (terms.empty() ? "" : " + ") + number(x.box.surface_area());
    sums(t, x.left, inner, leaves, terms);
    sums(t, x.right, inner, leaves, terms);
}

// The tree as nodes and links in the pixel rectangle (left, top, width, 4 levels): leaves side by side in
// depth-first order, each inner node above the middle of its children.
void draw_tree(diagram& d, const refine_tree& t, const std::map<std::uint32_t, std::string>& names, double left,
               double top, double width, std::uint32_t changed, std::uint32_t moved) {
    std::map<std::uint32_t, point2> at;
    int leaves = 0;
    const auto place = [&](auto&& self, std::uint32_t n, int depth) -> double {
        const refine_node& x = t.nodes[n];
        const double y = top + 72.0 * depth;
        double cx;
        if (x.is_leaf()) cx = left + 45 + (width - 90) * (leaves++) / 3.0;
        else cx = 0.5 * (self(self, x.left, depth + 1) + self(self, x.right, depth + 1));
        at[n] = {cx, y};
        return cx;
    };
    place(place, t.root, 0);
    for (const auto& [n, p] : at)
        if (!t.nodes[n].is_leaf())
            for (std::uint32_t c : {t.nodes[n].left, t.nodes[n].right})
                d.line(p.x, p.y + 20, at[c].x, at[c].y - 20, {ink::grey, "none", 1.5});
    for (const auto& [n, p] : at) {
        const bool leaf = t.nodes[n].is_leaf();
        const char* fill = n == changed ? ink::pale_red : leaf ? ink::pale_grey : ink::pale_blue;
        const char* stroke = n == moved ? ink::green : n == changed ? ink::red : ink::black;
        d.rect(p.x - 38, p.y - 20, p.x + 38, p.y + 20, {stroke, fill, n == moved || n == changed ? 2.5 : 1.2});
        d.text(p.x, p.y - 3, names.at(n), {14, "middle", ink::black, true});
        d.text(p.x, p.y + 14, "A = " + number(t.nodes[n].box.surface_area()), {12, "middle"});
    }
}

diagram rotation_figure() {
    // Tree 2 of the tests: N = (L, R), L = (LL, LR), R = (RL, RR), one primitive per leaf, boxes in 3D:
    //   LL = [0,1]x[0,2]x[0,3], LR = [4,5]x[0,1]x[0,1], RL = [0,1]x[0,1]x[5,6], RR = [4,6]x[1,2]x[0,1].
    refine_tree t;
    const std::uint32_t ll = add_leaf(t, vec3(0, 0, 0), vec3(1, 2, 3)), lr = add_leaf(t, vec3(4, 0, 0), vec3(5, 1, 1)),
                        rl = add_leaf(t, vec3(0, 0, 5), vec3(1, 1, 6)), rr = add_leaf(t, vec3(4, 1, 0), vec3(6, 2, 1));
    const std::uint32_t l = add_inner(t, ll, lr), r = add_inner(t, rl, rr), n = add_inner(t, l, r);
    t.root = n;
    const std::map<std::uint32_t, std::string> names{{ll, "LL"}, {lr, "LR"}, {rl, "RL"}, {rr, "RR"},
                                                     {l, "L"},   {r, "R"},   {n, "N"}};
    const float c_t = 1.0f;
    const rotation all[] = {rotation::left_right_left, rotation::left_right_right, rotation::right_left_left,
                            rotation::right_left_right};
    float delta[4];
    for (int k = 0; k < 4; ++k) delta[k] = rotation_cost(t, n, all[k], c_t);
    double inner_before = 0, leaves_before = 0;
    std::string terms_before, terms_after;
    sums(t, n, inner_before, leaves_before, terms_before);
    const double root_area = t.nodes[n].box.surface_area();
    const refine_tree before = t;
    const rotation_choice best = apply_best_rotation(t, n, 0, ch04::bvh_max_depth, c_t);
    double inner_after = 0, leaves_after = 0;
    sums(t, n, inner_after, leaves_after, terms_after);
    // The child whose content changed (it lost a grandchild, gained N's other child) and the child that moved.
    const bool into_right = best.r == rotation::left_right_left || best.r == rotation::left_right_right;
    const std::uint32_t changed = best.r == rotation::none ? no_node : into_right ? r : l;
    const std::uint32_t moved = best.r == rotation::none ? no_node : into_right ? l : r;

    diagram d(720, 540);
    const font title{15, "middle", ink::black, true};
    d.text(185, 24, "before", title);
    d.text(545, 24, std::string("after ") + to_string(best.r), title);
    draw_tree(d, before, names, 15, 62, 340, changed, moved);
    draw_tree(d, t, names, 375, 62, 340, changed, moved);
    d.arrow(330, 100, 400, 100, {ink::black, "none", 2.0});
    const font body{13, "middle"};
    d.text(185, 322, "inner areas: " + terms_before + " = " + number(inner_before), body);
    d.text(545, 322, "inner areas: " + terms_after + " = " + number(inner_after), body);
    // The four rotations at N, priced by rotation_cost.
    d.text(360, 358, "the four rotations at N: C_T (A(new box) - A(old box)) of the child that changes", title);
    for (int k = 0; k < 4; ++k) {
        const double x = 100 + 173.0 * k;
        const bool applied = all[k] == best.r;
        const font f{14, "middle", applied ? ink::red : ink::black, applied};
        d.text(x, 386, to_string(all[k]), f);
        d.text(x, 406, std::isinf(delta[k]) ? "impossible" : number(delta[k], true), f);
    }
    if (best.r == rotation::none) d.text(360, 442, "no rotation lowers the cost: none is applied", body);
    else {
        d.text(360, 442, "the lowest, " + number(best.delta, true) + ", is applied: " + names.at(moved) +
                             " (green) moves down into " + names.at(changed) + " (red), whose box shrinks;", body);
        d.text(360, 462, "N's box and every leaf stay as they were, so only " + names.at(changed) +
                             "'s area changes the cost", body);
    }
    const double cost_before = (c_t * inner_before + leaves_before) / root_area;
    const double cost_after = (c_t * inner_after + leaves_after) / root_area;
    d.text(360, 492, "C(T) = (C_T sum A(inner) + C_I sum N A(leaf)) / A(root) with C_T = C_I = 1: " +
                         number(cost_before) + " -> " + number(cost_after), body);
    d.text(360, 516, "a change of " + number(best.delta, true) + " / " + number(root_area) + " = " +
                         number(cost_after - cost_before, true), {14, "middle", ink::red, true});
    return d;
}

}  // namespace

std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force) {
    return write_figures(folder, force, {{"rotation.svg", rotation_figure}});
}

}  // namespace strahl::ch06
