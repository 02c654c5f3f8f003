// Exercises 15.1 (the permutation and the shear, 3 points) and 15.2 (the edge functions with the double
// fallback, 5 points). Read: S. Woop, C. Benthin and I. Wald, "Watertight ray/triangle intersection",
// JCGT 2(1), 2013, sections 3 and 4 (its figure 7 is the whole test).
#include "strahl/ch15/watertight.hpp"
#include <cmath>
#include <utility>

namespace strahl::ch15 {

shear make_shear(const vec3& dir) {
    // The axis of the largest |dir|, the other two after it, swapped to keep the winding.
    const vec3 a = glm::abs(dir);
    shear s;
    s.kz = a.x >= a.y ? (a.x >= a.z ? 0 : 2) : (a.y >= a.z ? 1 : 2);
    s.kx = (s.kz + 1) % 3;
    s.ky = (s.kx + 1) % 3;
    if (dir[s.kz] < 0.0f) std::swap(s.kx, s.ky);
    // The shear that takes dir to (0, 0, 1).
    s.sx = dir[s.kx] / dir[s.kz];
    s.sy = dir[s.ky] / dir[s.kz];
    s.sz = 1.0f / dir[s.kz];
    return s;
}

bool intersect_watertight(const ray& r, const shear& s, const vec3& v0, const vec3& v1, const vec3& v2, float& t,
                          float& u, float& v) {
    // a. The vertices relative to the origin, sheared in x and y.
    const vec3 a = v0 - r.org, b = v1 - r.org, c = v2 - r.org;
    const float ax = a[s.kx] - s.sx * a[s.kz], ay = a[s.ky] - s.sy * a[s.kz];
    const float bx = b[s.kx] - s.sx * b[s.kz], by = b[s.ky] - s.sy * b[s.kz];
    const float cx = c[s.kx] - s.sx * c[s.kz], cy = c[s.ky] - s.sy * c[s.kz];
    // b. The edge functions; where one is exactly 0, all three again in double (the products are exact).
    float eu = cx * by - cy * bx;
    float ev = ax * cy - ay * cx;
    float ew = bx * ay - by * ax;
    if (eu == 0.0f || ev == 0.0f || ew == 0.0f) {
        eu = float(double(cx) * double(by) - double(cy) * double(bx));
        ev = float(double(ax) * double(cy) - double(ay) * double(cx));
        ew = float(double(bx) * double(ay) - double(by) * double(ax));
    }
    // c. Mixed signs: outside. det = 0 (or NaN): in the plane, or degenerate; so are parallel edges.
    if ((eu < 0.0f || ev < 0.0f || ew < 0.0f) && (eu > 0.0f || ev > 0.0f || ew > 0.0f)) return false;
    const float det = eu + ev + ew;
    if (!(std::fabs(det) > 0.0f)) return false;
    if (glm::cross(v1 - v0, v2 - v0) == vec3(0.0f)) return false;  // parallel edges: degenerate
    // d. The sheared depths and the scaled distance T.
    const float az = s.sz * a[s.kz], bz = s.sz * b[s.kz], cz = s.sz * c[s.kz];
    const float big_t = eu * az + ev * bz + ew * cz;
    // e. t in (tmin, tmax); the barycentrics of v1 and v2.
    const float tt = big_t / det;
    if (!(tt > r.tmin && tt < r.tmax)) return false;
    t = tt;
    u = ev / det;
    v = ew / det;
    return true;
}

}  // namespace strahl::ch15
