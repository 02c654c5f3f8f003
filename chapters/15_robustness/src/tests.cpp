// Chapter 15's shared code: the names of the tests and walks, Moeller-Trumbore with the paper's epsilon,
// the watertight test in double, and pbrt-v4's bounded offset.
#include "strahl/ch04/traverse.hpp"
#include "strahl/ch15/robust_bvh.hpp"
#include "strahl/ch15/spawn.hpp"
#include <cmath>

namespace strahl::ch15 {

const char* name(test_kind k) {
    switch (k) {
        case test_kind::mt: return "mt";
        case test_kind::mt_epsilon: return "mt-epsilon";
        case test_kind::mt_edges: return "mt-edges";
        case test_kind::watertight: return "watertight";
        case test_kind::watertight_double: return "watertight-double";
    }
    return "?";
}

const char* describe(test_kind k) {
    switch (k) {
        case test_kind::mt: return "Moeller-Trumbore, no epsilon (exercise 01.3)";
        case test_kind::mt_epsilon: return "Moeller-Trumbore with the paper's |det| >= 1e-6";
        case test_kind::mt_edges: return "Moeller-Trumbore from precomputed edges (exercise 11.2)";
        case test_kind::watertight: return "watertight, float, double fallback on zero edges (Woop et al. 2013)";
        case test_kind::watertight_double: return "watertight, double throughout";
    }
    return "?";
}

const char* name(box_kind k) {
    switch (k) {
        case box_kind::plain: return "plain";
        case box_kind::conservative: return "conservative";
        case box_kind::fast: return "fast";
    }
    return "?";
}

bool intersect_mt_epsilon(const ray& r, const vec3& v0, const vec3& v1, const vec3& v2, float& t, float& u,
                          float& v) {
    const vec3 e1 = v1 - v0;
    const vec3 e2 = v2 - v0;
    const vec3 p = glm::cross(r.dir, e2);
    const float det = glm::dot(e1, p);
    if (!(std::fabs(det) >= 1e-6f)) return false;  // the paper's EPSILON
    const float inv_det = 1.0f / det;
    const vec3 s = r.org - v0;
    const float bu = glm::dot(s, p) * inv_det;
    if (!(bu >= 0.0f && bu <= 1.0f)) return false;
    const vec3 q = glm::cross(s, e1);
    const float bv = glm::dot(r.dir, q) * inv_det;
    if (!(bv >= 0.0f && bu + bv <= 1.0f)) return false;
    const float bt = glm::dot(e2, q) * inv_det;
    if (!(bt > r.tmin && bt < r.tmax)) return false;
    t = bt, u = bu, v = bv;
    return true;
}

bool intersect_watertight_double(const ray& r, const vec3& v0, const vec3& v1, const vec3& v2, float& t,
                                 float& u, float& v) {
    const glm::dvec3 d(r.dir), o(r.org);
    const glm::dvec3 ad = glm::abs(d);
    const int kz = ad.x >= ad.y ? (ad.x >= ad.z ? 0 : 2) : (ad.y >= ad.z ? 1 : 2);
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0.0) std::swap(kx, ky);
    const double sx = d[kx] / d[kz], sy = d[ky] / d[kz], sz = 1.0 / d[kz];
    const glm::dvec3 a = glm::dvec3(v0) - o, b = glm::dvec3(v1) - o, c = glm::dvec3(v2) - o;
    const double ax = a[kx] - sx * a[kz], ay = a[ky] - sy * a[kz];
    const double bx = b[kx] - sx * b[kz], by = b[ky] - sy * b[kz];
    const double cx = c[kx] - sx * c[kz], cy = c[ky] - sy * c[kz];
    const double eu = cx * by - cy * bx, ev = ax * cy - ay * cx, ew = bx * ay - by * ax;
    if ((eu < 0.0 || ev < 0.0 || ew < 0.0) && (eu > 0.0 || ev > 0.0 || ew > 0.0)) return false;
    const double det = eu + ev + ew;
    if (!(std::fabs(det) > 0.0)) return false;
    if (glm::cross(glm::dvec3(v1) - glm::dvec3(v0), glm::dvec3(v2) - glm::dvec3(v0)) == glm::dvec3(0.0)) return false;
    const double tt = (eu * (sz * a[kz]) + ev * (sz * b[kz]) + ew * (sz * c[kz])) / det;
    if (!(tt > double(r.tmin) && tt < double(r.tmax))) return false;
    const float tf = float(tt);
    if (!(tf > r.tmin && tf < r.tmax)) return false;  // rounded to float, still inside the interval
    t = tf, u = float(ev / det), v = float(ew / det);
    return true;
}

vec3 interpolation_error(float b0, float b1, float b2, const vec3& v0, const vec3& v1, const vec3& v2) {
    return ch04::gamma(7) * (glm::abs(b0 * v0) + glm::abs(b1 * v1) + glm::abs(b2 * v2));
}

vec3 offset_bounded(const vec3& p, const vec3& p_error, const vec3& n, const vec3& w) {
    const vec3 nf = facing(n, w);
    const float d = glm::dot(glm::abs(nf), p_error);
    const vec3 offset = d * nf;
    vec3 po = p + offset;
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0.0f) po[i] = std::nextafter(po[i], inf);
        else if (offset[i] < 0.0f) po[i] = std::nextafter(po[i], -inf);
    }
    return po;
}

}  // namespace strahl::ch15
