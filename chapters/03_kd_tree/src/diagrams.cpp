// The chapter's figure, drawn by the chapter's own traversal step (`ch03 --diagrams DIR`):
//   near_far.svg: a node split by a plane, a ray's segment [t0, t1] in it, cut at t_split into the near
//                 child's part, visited first, and the far child's, pushed on the stack for later; once for a ray going
//                 up the split axis and once for one going down it. The root clip and the t-ranges come from
//                 clip_to_box and near_far (exercise 03.3), in the plane z = 0.
#include "strahl/ch03/traverse.hpp"
#include "strahl/diagram.hpp"
#include "strahl/program.hpp"
#include <cstdio>
#include <string>
#include <vector>

namespace strahl::ch03 {

namespace {

std::string fixed(double v) { return number_text(v, "%.1f"); }

void near_far_panel(diagram& d, double left, const ray& r, const std::string& heading) {
    const aabb node{vec3(0, 0, -1), vec3(10, 6, 1)};
    const float split = 4.0f;
    const double wx0 = -2.0, wy0 = -0.8, wx1 = 12.0, wy1 = 7.2, width = 345;
    d.pixels();
    d.text(left + width / 2, 24, heading, {15, "middle", ink::black, true});
    d.view(wx0, wy0, wx1, wy1, left, 40, width, 200);
    const vec3 inv_dir = 1.0f / r.dir;
    float t0 = 0, t1 = 0;
    clip_to_box(r, inv_dir, node, 0.0f, t0, t1);
    const child_visit v = near_far(r, inv_dir, 0, split, t0, t1, 0.0f);
    const float t_split = (split - r.org.x) * inv_dir.x;
    // The two children: the near one (visited first) green, the far one blue.
    const double child_x[2][2] = {{node.min.x, split}, {split, node.max.x}};
    const char* fills[2] = {ink::pale_green, ink::pale_blue};
    const char* inks[2] = {ink::green, ink::blue};
    for (int k = 0; k < v.count; ++k) {
        const int c = v.child[k];
        d.rect(child_x[c][0], node.min.y, child_x[c][1], node.max.y, {"none", fills[k], 0.0});
        const double mid = 0.5 * (child_x[c][0] + child_x[c][1]);
        d.text(mid, node.max.y + 0.3, k == 0 ? "near: first" : "far: pushed", {13, "middle", inks[k], true, true});
        d.text(child_x[c][1] - 0.2, node.min.y + 0.35, c == 0 ? "left child" : "right child", {12, "end", ink::grey, false, true});
    }
    d.rect(node.min.x, node.min.y, node.max.x, node.max.y, {ink::black, "none", 2.0});
    d.line(split, wy0 + 0.2, split, wy1, {ink::red, "none", 2.0, true});
    d.text(split + 0.15, wy0 + 0.25, "split x = 4", {12, "start", ink::red, true});
    // The ray, its two parts, and the three t values.
    const auto p = [&](double t) { return point2{r.org.x + t * r.dir.x, r.org.y + t * r.dir.y}; };
    const point2 end = p(t1 + 1.2);
    d.arrow(r.org.x, r.org.y, end.x, end.y, {ink::black, "none", 1.5});
    d.circle(r.org.x, r.org.y, 4, {ink::black, ink::black, 1.0});
    for (int k = 0; k < v.count; ++k) {
        const point2 a = p(v.t0[k]), b = p(v.t1[k]);
        d.line(a.x, a.y, b.x, b.y, {inks[k], "none", 5.0});
    }
    const double s = d.scale();
    const std::pair<double, const char*> marks[] = {{t0, "t0"}, {t_split, "t_split"}, {t1, "t1"}};
    for (const auto& [t, name] : marks) {
        const point2 q = p(t);
        d.circle(q.x, q.y, 4.5, {ink::black, "white", 1.5});
        d.text(q.x + 7.0 / s, q.y - 17.0 / s, name, {13, "start", ink::black, true, true});  // below the ray
    }

    // Below: the segment on the t axis, cut at t_split.
    d.pixels();
    const double axis_left = left + 60, axis_right = left + width - 18, t_max = 14.0, row0 = 258;
    const auto px = [&](double t) { return axis_left + (axis_right - axis_left) * t / t_max; };
    for (int k = 0; k < v.count; ++k) {
        const double y = row0 + 26.0 * k;
        d.text(left + 4, y + 19, k == 0 ? "near" : "far", {12, "start", inks[k], true});
        d.rect(px(v.t0[k]), y + 12, px(v.t1[k]), y + 20, {"none", inks[k], 0.0});
        const std::string range = "[" + fixed(v.t0[k]) + ", " + fixed(v.t1[k]) + "]";
        d.text(0.5 * (px(v.t0[k]) + px(v.t1[k])), y + 9, range, {12, "middle", inks[k]});
    }
    const double y = row0 + 58;
    d.line(axis_left, y, axis_right, y, {ink::grey, "none", 1.0});
    for (int t = 0; t <= int(t_max); t += 2) {
        d.line(px(t), y - 3, px(t), y + 3, {ink::grey, "none", 1.0});
        d.text(px(t), y + 16, std::to_string(t), {11, "middle", ink::grey});
    }
    d.text(axis_right + 8, y + 4, "t", {13, "start", ink::grey, true});
    d.line(px(t_split), row0 + 4, px(t_split), y, {ink::red, "none", 1.5, true});
    const auto term = [](double v) { return v < 0 ? "(" + fixed(v) + ")" : fixed(v); };
    const std::string formula = "t_split = (4 - " + term(r.org.x) + ") / " + term(r.dir.x) + " = " + fixed(t_split);
    d.text(left + width / 2, y + 42, formula, {13, "middle", ink::red, true});
}

diagram near_far_figure() {
    diagram d(720, 400);
    ray up, down;
    up.org = vec3(-1.5f, 0.6f, 0.0f), up.dir = vec3(1.0f, 0.42f, 0.0f);
    down.org = vec3(11.5f, 5.6f, 0.0f), down.dir = vec3(-1.0f, -0.38f, 0.0f);
    near_far_panel(d, 12, up, "going up x: the left child is near");
    near_far_panel(d, 372, down, "going down x: the right child is near");
    d.pixels();
    d.text(360, 388, "t_split before t0 or beyond t1: the segment stays on one side, one child only",
           {13, "middle", ink::grey});
    return d;
}

}  // namespace

std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force) {
    return write_figures(folder, force, {{"near_far.svg", near_far_figure}});
}

}  // namespace strahl::ch03
