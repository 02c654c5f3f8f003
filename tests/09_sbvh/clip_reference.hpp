// What chapter 09's tests share: a plain clipper (the triangle's part in a slab, in long double, as a box
// in long double, not rounded), to check exercise 09.1 against and to hand exercise 09.2 as its clipper;
// and random triangles.
#pragma once
#include "strahl/ch09/chopped_bins.hpp"
#include "strahl/ch09/clip.hpp"
#include "strahl/rng.hpp"
#include <algorithm>
#include <cmath>
#include <vector>

namespace strahl::test {

struct exact_box {
    long double min[3] = {INFINITY, INFINITY, INFINITY}, max[3] = {-INFINITY, -INFINITY, -INFINITY};
    bool empty = true;
};

// The part of t with lo <= x[axis] <= hi (Sutherland-Hodgman, twice), boxed, intersected with box.
inline exact_box exact_clip(const ch09::triangle& t, int axis, float lo, float hi, const aabb& box) {
    using P = std::array<long double, 3>;
    std::vector<P> poly;
    for (const vec3& v : {t.v0, t.v1, t.v2}) poly.push_back({v.x, v.y, v.z});
    const auto clip = [&](long double at, long double s) {
        std::vector<P> out;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const P &p = poly[i], &q = poly[(i + 1) % poly.size()];
            const long double dp = s * (p[axis] - at), dq = s * (q[axis] - at);
            if (dp >= 0) out.push_back(p);
            if ((dp > 0 && dq < 0) || (dp < 0 && dq > 0)) {
                P c;
                for (int a = 0; a < 3; ++a) c[a] = p[a] + dp / (dp - dq) * (q[a] - p[a]);
                c[axis] = at;
                out.push_back(c);
            }
        }
        poly = out;
    };
    if (std::isfinite(lo)) clip(lo, 1);
    if (std::isfinite(hi) && !poly.empty()) clip(hi, -1);
    exact_box b;
    if (poly.empty()) return b;
    b.empty = false;
    for (const P& p : poly)
        for (int a = 0; a < 3; ++a) b.min[a] = std::min(b.min[a], p[a]), b.max[a] = std::max(b.max[a], p[a]);
    for (int a = 0; a < 3; ++a) {
        b.min[a] = std::max(b.min[a], (long double)box.min[a]), b.max[a] = std::min(b.max[a], (long double)box.max[a]);
        if (b.min[a] > b.max[a]) b.empty = true;
    }
    return b;
}

// The same as a float box, rounded to nearest: the clipper the tests hand exercise 09.2.
inline aabb rounded_clip(const ch09::triangle& t, int axis, float lo, float hi, const aabb& box) {
    const exact_box e = exact_clip(t, axis, lo, hi, box);
    if (e.empty) return aabb{};
    aabb b;
    for (int a = 0; a < 3; ++a) b.min[a] = float(e.min[a]), b.max[a] = float(e.max[a]);
    return b;
}

// A random triangle with corners in [lo, hi]^3.
inline ch09::triangle random_triangle(pcg32& g, float lo, float hi) {
    const auto p = [&] { return vec3(g.next_float(), g.next_float(), g.next_float()) * (hi - lo) + lo; };
    return {p(), p(), p()};
}

}  // namespace strahl::test
