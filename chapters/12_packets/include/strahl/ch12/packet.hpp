// Ray packets: P = V x K rays traced together, V vectors of K SIMD lanes, one ray per lane, in structure of
// arrays. Every lane carries the per-ray terms of chapter 05's fast slab test (computed in float, as chapter
// 13's wide walk computes them) and its own interval, so that one box test answers K rays, and a lane's
// answer is the answer that ray would get alone.
//   I. Wald, P. Slusallek, C. Benthin and M. Wagner, "Interactive rendering with coherent ray tracing",
//   Computer Graphics Forum (Eurographics) 2001 (packets of SIMD width, the active mask);
//   I. Wald, S. Boulos and P. Shirley, "Ray tracing deformable scenes using dynamic bounding volume
//   hierarchies", ACM TOG 26(1), 2007 (large packets, the first active ray, the interval-arithmetic frustum).
#pragma once
#include "strahl/inlining.hpp"
#include "strahl/aabb.hpp"
#include "strahl/ray.hpp"
#include "strahl/simd.hpp"
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace strahl::ch12 {

// A tree's box in the form the per-lane set-up needs: its centre and an upper bound on its diagonal (the sum
// of the extents), as chapter 13's wide_bvh keeps them.
struct tree_frame {
    aabb bounds;
    vec3 centre{0.0f};
    float diagonal = 0.0f;
    explicit tree_frame(const aabb& b = {}) : bounds(b) {
        if (b.is_empty()) return;
        centre = b.centroid();
        const vec3 e = b.extent();
        diagonal = e.x + e.y + e.z;
    }
};

// What one lane needs for the fast slab test, computed once per ray: chapter 13's wide_fast_slab set-up
// (float arithmetic, widened by 2^-19 of |plane| + |org|: ch05::fast_slab's proof with room for float) and
// wide_ray_slack. ok is false where the fast test cannot take the ray (a direction component zero,
// subnormal, or so small that a plane's t overflows); such a ray leaves the packet and is traced alone.
struct lane_terms {
    float inv[3], org_near[3], org_far[3], slack;
    bool ok = true;
    lane_terms(const ray& r, const tree_frame& f) {
        for (int a = 0; a < 3; ++a) {
            const float i = 1.0f / r.dir[a], o = r.org[a];
            const float span = std::max(std::fabs(f.bounds.min[a]), std::fabs(f.bounds.max[a])) + std::fabs(o);
            const float eps = 0x1p-19f * span, toward = std::copysign(eps, i);
            ok = ok && std::fabs(i) <= 0x1p100f && (span + eps) * std::fabs(i) <= 0x1p100f;
            inv[a] = i;
            org_near[a] = (o + toward) * i + 0x1p-126f;
            org_far[a] = (o - toward) * i - 0x1p-126f;
        }
        const vec3 to = r.org - f.centre;
        const float reach = (std::fabs(to.x) + std::fabs(to.y) + std::fabs(to.z)) + f.diagonal;
        const float len = std::max(std::fabs(r.dir.x), std::max(std::fabs(r.dir.y), std::fabs(r.dir.z)));
        slack = (reach * 0x1p-16f + 1e-5f * f.diagonal) / len * (1.0f + 0x1p-20f);
        ok = ok && std::isfinite(slack);
    }
};

// The packet. Lane j of vector v is ray v * K + j of the packet; `active` has a bit per lane still traced
// (a lane that never held a ray, or whose ray was answered or handed to the single-ray walk, is clear).
// t1 = tmax + slack is the far end of the box tests, kept up to date as hits shrink tmax.
template <int K, int V = 1>
struct alignas(64) ray_packet {
    static constexpr int lanes = K, vectors = V, size = K * V;
    using vf = simd::vfloat<K>;

    alignas(64) float org[3][size], dir[3][size];
    alignas(64) float inv[3][size], org_near[3][size], org_far[3][size];
    alignas(64) float tmin[size], tmax[size], slack[size], t0[size], t1[size];
    std::uint32_t ray_index[size];  // the ray's place in the batch
    // The best hit so far, lanes side by side (so that a triangle test records K lanes at once): t, u, v
    // and the triangle (invalid_id as int32: none yet; any hit: the blocking triangle). best(k), set_best().
    alignas(64) float best_t[size], best_u[size], best_v[size];
    alignas(64) std::int32_t best_prim[size];
    unsigned active[V];             // lane bits per vector
    int octant = 0;                 // the sign bits of every active lane, where they all agree ...
    bool coherent = true;           // ... which is when the whole packet can choose near planes once

    // Frustum: the active lanes' extremes, for the interval-arithmetic test (exercise 12.2): per axis the
    // range of the origins and of 1 / d, a margin (below), and the range of the intervals' ends.
    float org_lo[3], org_hi[3], inv_lo[3], inv_hi[3], margin[3], t0_lo, t1_hi;

    // Vector v of a field, one SIMD load.
    static vf get(const float* field, int v) { return vf::load(field + v * K); }

    // Lane k's best hit as a hit (a miss: hit{}), and set.
    hit best(int k) const {
        const auto prim = std::uint32_t(best_prim[k]);
        return prim == invalid_id ? hit{} : hit{best_t[k], prim, best_u[k], best_v[k], invalid_id};
    }
    void set_best(int k, const hit& h) {
        best_t[k] = h.t, best_prim[k] = std::int32_t(h.prim), best_u[k] = h.u, best_v[k] = h.v;
    }

    // Empties the packet: no lane active.
    void clear() {
        for (int v = 0; v < V; ++v) active[v] = 0;
    }
    // Puts ray r (the batch's ray `index`) into lane `lane`, with its fast-slab terms.
    void set(int lane, const ray& r, const lane_terms& l, std::uint32_t index) {
        set_ray(lane, r, index);
        for (int a = 0; a < 3; ++a)
            inv[a][lane] = l.inv[a], org_near[a][lane] = l.org_near[a], org_far[a][lane] = l.org_far[a];
        slack[lane] = l.slack, t0[lane] = r.tmin - l.slack, t1[lane] = r.tmax + l.slack;
    }
    // Puts ray r (the batch's ray `index`) into lane `lane` without its terms: set_terms() computes them for
    // every lane at once.
    void set_ray(int lane, const ray& r, std::uint32_t index) {
        for (int a = 0; a < 3; ++a) org[a][lane] = r.org[a], dir[a][lane] = r.dir[a];
        tmin[lane] = r.tmin, tmax[lane] = r.tmax;
        ray_index[lane] = index;
        set_best(lane, hit{});
        active[lane / K] |= 1u << (lane % K);
    }
    // Lanes 0..count-1 from rays[ids[0..count-1]], no best hit yet, the rest empty (set_ray for each, the
    // lane bits set once).
    void set_rays(const ray* rays, const std::uint32_t* ids, int count) {
        for (int lane = 0; lane < count; ++lane) {
            const ray& r = rays[ids[lane]];
            for (int a = 0; a < 3; ++a) org[a][lane] = r.org[a], dir[a][lane] = r.dir[a];
            tmin[lane] = r.tmin, tmax[lane] = r.tmax;
            ray_index[lane] = ids[lane];
        }
        for (int v = 0; v < V; ++v) {
            vf(inf).store(best_t + v * K), vf(0.0f).store(best_u + v * K), vf(0.0f).store(best_v + v * K);
            simd::vint<K>(std::int32_t(invalid_id)).store(best_prim + v * K);
            const int n = std::clamp(count - v * K, 0, K);
            active[v] = n == 32 ? ~0u : (1u << n) - 1u;
        }
    }
    // lane_terms for every lane, K at a time: the same operations in the same order, so the same bits (|x|
    // as max(x, -x): a zero's sign is lost in the sums it enters). refused[v]: the active lanes of vector v
    // whose ray no packet takes, for the caller to trace alone and clear: an empty interval (not tmin <
    // tmax), a ray tree_query.hpp's placeable() refuses (the same sums in the same order), or a direction
    // the fast test cannot take (lane_terms::ok false).
    void set_terms(const tree_frame& f, unsigned* refused) {
        const auto abs = [](vf x) { return simd::max(x, -x); };
        const vf largest(std::numeric_limits<float>::max());
        for (int v = 0; v < V; ++v) {
            const int at = v * K;
            const vf ox = get(org[0], v), oy = get(org[1], v), oz = get(org[2], v);
            const vf dx = get(dir[0], v), dy = get(dir[1], v), dz = get(dir[2], v);
            const vf d2 = dx * dx + dy * dy + dz * dz, o2 = ox * ox + oy * oy + oz * oz;
            simd::vmask<K> ok = (get(tmin, v) < get(tmax, v)) & (abs(ox) <= largest) & (abs(oy) <= largest) &
                                (abs(oz) <= largest) & (abs(d2) <= largest) & (d2 > vf(1e-30f)) & (o2 < vf(1e36f));
            vf reach = abs(get(org[0], v) - vf(f.centre[0]));
            reach = reach + abs(get(org[1], v) - vf(f.centre[1]));
            reach = reach + abs(get(org[2], v) - vf(f.centre[2]));
            reach = reach + vf(f.diagonal);
            const vf len = simd::max(abs(get(dir[0], v)), simd::max(abs(get(dir[1], v)), abs(get(dir[2], v))));
            for (int a = 0; a < 3; ++a) {
                const vf i = vf(1.0f) / get(dir[a], v), o = get(org[a], v);
                const float p = std::max(std::fabs(f.bounds.min[a]), std::fabs(f.bounds.max[a]));
                const vf span = vf(p) + abs(o), eps = vf(0x1p-19f) * span;
                const vf toward = simd::select(i < vf(0.0f), -eps, eps);
                ok = ok & (abs(i) <= vf(0x1p100f)) & ((span + eps) * abs(i) <= vf(0x1p100f));
                i.store(inv[a] + at);
                ((o + toward) * i + vf(0x1p-126f)).store(org_near[a] + at);
                ((o - toward) * i - vf(0x1p-126f)).store(org_far[a] + at);
            }
            const vf sl = (reach * vf(0x1p-16f) + vf(1e-5f * f.diagonal)) / len * vf(1.0f + 0x1p-20f);
            ok = ok & (abs(sl) <= vf(std::numeric_limits<float>::max()));
            sl.store(slack + at);
            (get(tmin, v) - sl).store(t0 + at);
            (get(tmax, v) + sl).store(t1 + at);
            refused[v] = active[v] & ~simd::movemask(ok);
        }
    }
    // Chapter 14's strict variant: every lane's boxes tested from tmin itself (t0 = tmin, no slack below).
    void drop_lower_slack() {
        for (int v = 0; v < V; ++v) get(tmin, v).store(t0 + v * K);
    }
    // Lanes that hold no ray get a copy of an active lane's terms (never active): every SIMD operation on
    // them is harmless, and the frustum's extremes are those of the active lanes. Then the octant and the
    // frustum's extremes; f: the tree the lanes' terms were made for.
    void finish(const tree_frame& f) {
        int any = -1;
        for (int i = 0; i < size && any < 0; ++i)
            if ((active[i / K] >> (i % K)) & 1u) any = i;
        if (any < 0) return;
        for (int i = 0; i < size; ++i) {
            if ((active[i / K] >> (i % K)) & 1u) continue;
            for (int a = 0; a < 3; ++a) {
                org[a][i] = org[a][any], dir[a][i] = dir[a][any], inv[a][i] = inv[a][any];
                org_near[a][i] = org_near[a][any], org_far[a][i] = org_far[a][any];
            }
            tmin[i] = tmin[any], tmax[i] = tmax[any], slack[i] = slack[any], t0[i] = t0[any], t1[i] = t1[any];
            ray_index[i] = invalid_id;
        }
        // The octant: each axis's sign bits over the lanes, all set or all clear (one test per vector).
        // Only a coherent packet has a frustum (the walks test it only then).
        const unsigned all = simd::detail::lane_bits(K);
        coherent = true;
        octant = 0;
        for (int a = 0; a < 3; ++a) {
            // Per vector: 1 all negative, 2 all positive; the packet agrees if every vector says the same.
            unsigned kinds = 0;
            for (int v = 0; v < V; ++v) {
                const unsigned m = simd::movemask(simd::as_int(get(dir[a], v)) < simd::vint<K>(0));
                kinds |= m == all ? 1u : m == 0 ? 2u : 4u;
            }
            coherent = coherent && (kinds == 1u || kinds == 2u);
            octant |= int(kinds == 1u) << a;
        }
        // The frustum: per axis the range of the origins and of 1 / d. The margin: a lane's computed near t
        // lies at most its widening (2^-19 of |plane| + |org|, lane_terms) and a few roundings (each 2^-24 of
        // the same) times |1 / d| below the exact (plane - org) / d; the frustum's own products in float
        // round by as much again. 2^-18 of the axis's span (the tree's largest |coordinate| plus the largest
        // |origin|) times the largest |1 / d| covers both, and 2^-125 the lanes' 2^-126 in t.
        if (!coherent) {
            t0_lo = -inf, t1_hi = inf;
            return;
        }
        for (int a = 0; a < 3; ++a) {
            vf olo = get(org[a], 0), ohi = olo, ilo = get(inv[a], 0), ihi = ilo;
            for (int v = 1; v < V; ++v) {
                olo = simd::min(olo, get(org[a], v)), ohi = simd::max(ohi, get(org[a], v));
                ilo = simd::min(ilo, get(inv[a], v)), ihi = simd::max(ihi, get(inv[a], v));
            }
            org_lo[a] = simd::reduce_min(olo), org_hi[a] = simd::reduce_max(ohi);
            inv_lo[a] = simd::reduce_min(ilo), inv_hi[a] = simd::reduce_max(ihi);
            const float p = std::max(std::fabs(f.bounds.min[a]), std::fabs(f.bounds.max[a]));
            const float o = std::max(std::fabs(org_lo[a]), std::fabs(org_hi[a]));
            margin[a] = 0x1p-18f * (p + o) * std::max(std::fabs(inv_lo[a]), std::fabs(inv_hi[a])) + 0x1p-125f;
        }
        vf lo = get(t0, 0);
        for (int v = 1; v < V; ++v) lo = simd::min(lo, get(t0, v));
        t0_lo = simd::reduce_min(lo);
        update_t1_hi();
    }
    void update_t1_hi() {
        vf hi = get(t1, 0);
        for (int v = 1; v < V; ++v) hi = simd::max(hi, get(t1, v));
        t1_hi = simd::reduce_max(hi);
    }
    bool empty() const {
        unsigned any = 0;
        for (int v = 0; v < V; ++v) any |= active[v];
        return any == 0;
    }
};

// K rays in SIMD registers, what the lane tests read: vector v of a packet (load), or K rays picked from a
// packet by their indices (gather: the large packets' active-ray lists).
template <int K>
struct lane_rays {
    using vf = simd::vfloat<K>;
    vf org[3], dir[3], inv[3], org_near[3], org_far[3], tmin, tmax, t0, t1;
    simd::vmask<K> negative[3];  // the direction's sign bit on each axis, per lane
};

template <int K, int V>
STRAHL_ALWAYS_INLINE inline lane_rays<K> load(const ray_packet<K, V>& p, int v) {
    using P = ray_packet<K, V>;
    lane_rays<K> r;
    for (int a = 0; a < 3; ++a) {
        r.org[a] = P::get(p.org[a], v), r.dir[a] = P::get(p.dir[a], v), r.inv[a] = P::get(p.inv[a], v);
        r.org_near[a] = P::get(p.org_near[a], v), r.org_far[a] = P::get(p.org_far[a], v);
        r.negative[a] = simd::as_int(r.dir[a]) < simd::vint<K>(0);
    }
    r.tmin = P::get(p.tmin, v), r.tmax = P::get(p.tmax, v), r.t0 = P::get(p.t0, v), r.t1 = P::get(p.t1, v);
    return r;
}

// After hits (or rays traced alone) shrank some lanes' reach: tmax and t1 of vector v again, the rest of r
// unchanged (cheaper than load, and no copy of the whole set).
template <int K, int V>
STRAHL_ALWAYS_INLINE inline void reload_reach(lane_rays<K>& r, const ray_packet<K, V>& p, int v) {
    using P = ray_packet<K, V>;
    r.tmax = P::get(p.tmax, v), r.t1 = P::get(p.t1, v);
}

// Lanes 0..n-1 from the packet's rays ids[0..n-1]; lanes n..K-1 repeat ids[0] (their answers are ignored).
template <int K, int V>
STRAHL_ALWAYS_INLINE inline lane_rays<K> gather(const ray_packet<K, V>& p, const std::uint16_t* ids, int n) {
    using vf = simd::vfloat<K>;
    alignas(64) float f[21][K];
    for (int j = 0; j < K; ++j) {
        const int i = ids[j < n ? j : 0];
        for (int a = 0; a < 3; ++a) {
            f[a][j] = p.org[a][i], f[3 + a][j] = p.dir[a][i], f[6 + a][j] = p.inv[a][i];
            f[9 + a][j] = p.org_near[a][i], f[12 + a][j] = p.org_far[a][i];
        }
        f[15][j] = p.tmin[i], f[16][j] = p.tmax[i], f[17][j] = p.t0[i], f[18][j] = p.t1[i];
    }
    lane_rays<K> r;
    for (int a = 0; a < 3; ++a) {
        r.org[a] = vf::load(f[a]), r.dir[a] = vf::load(f[3 + a]), r.inv[a] = vf::load(f[6 + a]);
        r.org_near[a] = vf::load(f[9 + a]), r.org_far[a] = vf::load(f[12 + a]);
        r.negative[a] = simd::as_int(r.dir[a]) < simd::vint<K>(0);
    }
    r.tmin = vf::load(f[15]), r.tmax = vf::load(f[16]), r.t0 = vf::load(f[17]), r.t1 = vf::load(f[18]);
    return r;
}

// The fast slab test of chapter 05, lanes being rays: one box (its corners broadcast) against K rays; each
// lane computes what ch05::fast_slab::entry computes for its ray, bit for bit (plane_t: fused where the
// processor has FMA, as there). Returns the lanes that enter the box within [t0, t1], and in `entry` where.
// Coherent packets (every lane in one octant, the sign bits `octant`) choose each axis's near and far plane
// once; the others choose per lane, by the lane's sign bits. Exercise 12.1 (packet_tests.cpp).
template <bool Coherent, int K>
simd::vmask<K> packet_box(const lane_rays<K>& r, const float* bmin, const float* bmax, int octant,
                          simd::vfloat<K>& entry);

// Exercise 12.2 (packet_tests.cpp): the interval-arithmetic frustum of a coherent packet against one box:
// true only where no active lane of the packet can enter the box (packet_box would give no lane). A lane's
// entry on axis a is (plane - o) * (1 / d) for o in [org_lo, org_hi] and 1 / d in [inv_lo, inv_hi]: at
// least the smallest of the four products of the ends, less the margin; its exit at most the largest, plus.
template <int K, int V>
bool frustum_misses(const ray_packet<K, V>& p, const float* bmin, const float* bmax);

// The triangle test of exercise 01.3 (Moeller-Trumbore from the corner v0 and the edges e1 = v1 - v0,
// e2 = v2 - v0), lanes being rays against one triangle: each lane computes exactly what the scalar test
// computes, operation for operation (chapter 13's block test with the roles of rays and triangles swapped),
// so its t, u and v are the scalar test's bits. Returns the lanes that hit with t in (tmin, tmax).
template <int K>
STRAHL_ALWAYS_INLINE inline unsigned packet_triangle(const lane_rays<K>& r, const float* v0, const float* e1,
                                                     const float* e2, simd::vfloat<K>& t, simd::vfloat<K>& u,
                                                       simd::vfloat<K>& w) {
    using vf = simd::vfloat<K>;
    const vf e1x(e1[0]), e1y(e1[1]), e1z(e1[2]), e2x(e2[0]), e2y(e2[1]), e2z(e2[2]);
    const vf &dx = r.dir[0], &dy = r.dir[1], &dz = r.dir[2];
    // Step 1, the determinant: p = d x e2, det = e1 . p.
    const vf px = dy * e2z - e2y * dz, py = dz * e2x - e2z * dx, pz = dx * e2y - e2x * dy;
    const vf det = e1x * px + e1y * py + e1z * pz;
    simd::vmask<K> hit = det != vf(0.0f);
    const vf inv_det = vf(1.0f) / det;
    // Step 2, u = s . p / det with s = org - v0.
    const vf sx = r.org[0] - vf(v0[0]), sy = r.org[1] - vf(v0[1]), sz = r.org[2] - vf(v0[2]);
    const vf bu = (sx * px + sy * py + sz * pz) * inv_det;
    hit = hit & (bu >= vf(0.0f)) & (bu <= vf(1.0f));
    // Step 3, v = d . q / det with q = s x e1.
    const vf qx = sy * e1z - e1y * sz, qy = sz * e1x - e1z * sx, qz = sx * e1y - e1x * sy;
    const vf bv = (dx * qx + dy * qy + dz * qz) * inv_det;
    hit = hit & (bv >= vf(0.0f)) & (bu + bv <= vf(1.0f));
    // Step 4, t = e2 . q / det, inside (tmin, tmax).
    const vf bt = (e2x * qx + e2y * qy + e2z * qz) * inv_det;
    hit = hit & (bt > r.tmin) & (bt < r.tmax);
    t = bt, u = bu, w = bv;
    return simd::movemask(hit);
}

// std::nextafter(x, inf) for x neither NaN nor +inf, without the library call: the next float up.
STRAHL_ALWAYS_INLINE inline float next_up(float x) {
    if (x == 0.0f) return std::numeric_limits<float>::denorm_min();
    const std::uint32_t b = std::bit_cast<std::uint32_t>(x);
    return std::bit_cast<float>(b >> 31 ? b - 1 : b + 1);
}

// The closest-hit step of chapter 01 (record_closest) on the lanes in `bits`: the nearer t wins, the lower
// id at equal t; the winner's tmax becomes the next float above t (and t1 with it).
// Lane j is the packet's ray at(j): v * K + j for a loaded vector, ids[j] for a gathered one.
template <int K, int V, class At>
STRAHL_ALWAYS_INLINE inline void packet_record(ray_packet<K, V>& p, unsigned bits, At at, std::uint32_t id,
                                               simd::vfloat<K> t, simd::vfloat<K> u, simd::vfloat<K> w) {
    alignas(64) float ts[K], us[K], ws[K];
    t.store(ts), u.store(us), w.store(ws);
    for (; bits != 0; bits &= bits - 1) {
        const int j = std::countr_zero(bits), i = at(j);
        if (!closer(ts[j], id, p.best(i))) continue;
        p.set_best(i, hit{ts[j], id, us[j], ws[j], invalid_id});
        p.tmax[i] = next_up(ts[j]);
        p.t1[i] = p.tmax[i] + p.slack[i];
    }
}

// packet_record on the lanes `win` of vector v (lane j is ray v * K + j), K at a time, as selects: no loop
// over the lanes that hit. The ids compare as signed int32: at equal t the lane holds a hit (t < inf), whose
// id, as every triangle's, is below 2^31.
template <int K, int V>
STRAHL_ALWAYS_INLINE inline void packet_record_lanes(ray_packet<K, V>& p, int v, simd::vmask<K> win,
                                                     std::uint32_t id, simd::vfloat<K> t, simd::vfloat<K> u,
                                                       simd::vfloat<K> w) {
    using vf = simd::vfloat<K>;
    using vi = simd::vint<K>;
    const int at = v * K;
    const vf bt = vf::load(p.best_t + at);
    const vi bid = vi::load(p.best_prim + at), idv{std::int32_t(id)};
    win = win & ((t < bt) | ((t == bt) & (idv < bid)));
    simd::select(win, t, bt).store(p.best_t + at);
    simd::select(win, idv, bid).store(p.best_prim + at);
    simd::select(win, u, vf::load(p.best_u + at)).store(p.best_u + at);
    simd::select(win, w, vf::load(p.best_v + at)).store(p.best_v + at);
    const vi b = simd::as_int(t);
    const vi up = simd::select(t == vf(0.0f), vi(1), simd::select(b < vi(0), b - vi(1), b + vi(1)));
    const vf tmax = simd::select(win, simd::as_float(up), vf::load(p.tmax + at));
    tmax.store(p.tmax + at);
    simd::select(win, tmax + vf::load(p.slack + at), vf::load(p.t1 + at)).store(p.t1 + at);
}

}  // namespace strahl::ch12

namespace strahl::ch12 {

// The three exercises called on their own, out of line (for the tests): 12.1 for K = 8 and 16, 12.2 for
// packets of 16 x 1 and 16 x 4 rays, 12.3 with K = 16 and bits[g] the lane bits of the g-th call.
template <bool Coherent, int K>
simd::vmask<K> packet_box_out_of_line(const lane_rays<K>& r, const float* bmin, const float* bmax, int octant,
                                      simd::vfloat<K>& entry);
template <int K, int V>
bool frustum_misses_out_of_line(const ray_packet<K, V>& p, const float* bmin, const float* bmax);
int partition_out_of_line(std::uint16_t* ids, int count, const std::vector<unsigned>& bits);

}  // namespace strahl::ch12
