// Exercise 09.1 clip a triangle to a slab (6 points). Read: clip.hpp; M. Stich, H. Friedrich and
// A. Dietrich, "Spatial splits in bounding volume hierarchies", HPG 2009, section 3.
#include "strahl/ch09/clip.hpp"
#include <algorithm>
#include <cmath>

namespace strahl::ch09 {

namespace {

struct point {
    double x[3];
};

// One Sutherland-Hodgman pass: the polygon `in` (n corners) clipped to the side where s * (x[axis] - at)
// >= 0 (s = +1: above the plane, -1: below); crossing points get x[axis] = at exactly.
int clip_plane(const point* in, int n, int axis, double at, double s, point* out) {
    int m = 0;
    for (int i = 0; i < n; ++i) {
        const point& p = in[i];
        const point& q = in[(i + 1) % n];
        const double dp = s * (p.x[axis] - at), dq = s * (q.x[axis] - at);
        if (dp >= 0) out[m++] = p;
        if ((dp > 0 && dq < 0) || (dp < 0 && dq > 0)) {
            const double f = dp / (dp - dq);
            point c;
            for (int a = 0; a < 3; ++a) c.x[a] = p.x[a] + f * (q.x[a] - p.x[a]);
            c.x[axis] = at;
            out[m++] = c;
        }
    }
    return m;
}

// The float no greater (down) or no less (up) than d.
float round_down(double d) {
    const float f = float(d);
    return double(f) > d ? std::nextafter(f, -INFINITY) : f;
}
float round_up(double d) {
    const float f = float(d);
    return double(f) < d ? std::nextafter(f, INFINITY) : f;
}

}  // namespace

// 09.1: Sutherland-Hodgman in double against the slab's two planes, the box rounded outwards, then
// intersected with `box`.
aabb clip_to_slab(const triangle& t, int axis, float lo, float hi, const aabb& box) {
    // STEP 1, clip: the triangle as a polygon, against x[axis] >= lo, then x[axis] <= hi.
    point a[max_clipped_corners + 1], b[max_clipped_corners + 1];
    const vec3 v[3] = {t.v0, t.v1, t.v2};
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) a[i].x[k] = double(v[i][k]);
    int n = 3;
    if (lo > -INFINITY) n = clip_plane(a, n, axis, double(lo), 1.0, b);
    else std::copy(a, a + n, b);
    if (hi < INFINITY && n > 0) n = clip_plane(b, n, axis, double(hi), -1.0, a);
    else std::copy(b, b + n, a);
    if (n == 0) return aabb{};
    // STEP 2, box: around the corners, rounded outwards.
    aabb out;
    for (int k = 0; k < 3; ++k) {
        double mn = a[0].x[k], mx = a[0].x[k];
        for (int i = 1; i < n; ++i) mn = std::min(mn, a[i].x[k]), mx = std::max(mx, a[i].x[k]);
        out.min[k] = round_down(mn), out.max[k] = round_up(mx);
    }
    // STEP 3, intersect with the reference's box.
    out.min = glm::max(out.min, box.min), out.max = glm::min(out.max, box.max);
    return out.is_empty() ? aabb{} : out;
}

}  // namespace strahl::ch09
