// The chapter's figures, computed by the chapter's own code (`ch15 --diagrams DIR`):
//   crack.svg:   a closed sphere (24 x 12, radius 1, at the origin) and the first shared edge whose midpoint
//                ray escapes Moeller-Trumbore; around it, a grid of rays one ulp apart (directions stepped by
//                2^-24 of their length along and across the edge), each coloured by which of the two
//                triangles it hits: with Moeller-Trumbore (exercise 01.3) some hit neither (the crack), with
//                the watertight test (exercises 15.1 and 15.2) every ray hits one or both;
//   shear.svg:   one ray and one triangle through the watertight test's steps: the (x, z) plane before, the
//                same after moving the origin to 0 and shearing the ray onto +z (make_shear), and ray space
//                seen along the ray, where the edge functions U, V, W are twice the areas the ray's point
//                makes with each edge (computed as the exercise computes them, the hit's t from
//                intersect_watertight);
//   offsets.svg: a triangle tilted in (x, z) at coordinates about 1,000, where floats are 2^-14 apart; 48 rays
//                hit it, each hit point interpolated from its barycentrics lands on the float lattice, above
//                or below the plane; from each, a ray leaves at 40 degrees to the surface: how many hit their
//                own triangle with no offset, with p + 1e-4 n, and with pbrt-v4's bounded offset.
#include "strahl/ch01/shapes.hpp"
#include "strahl/ch15/experiments.hpp"
#include "strahl/ch15/spawn.hpp"
#include "strahl/ch15/watertight.hpp"
#include "strahl/diagram.hpp"
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace strahl::ch15 {

namespace {

const font title{15, "middle", ink::black, true}, body{13, "middle"};

// --- crack.svg -------------------------------------------------------------------------------------------

// Which of two triangles a ray hits: 1 the first, 2 the second, 3 both, 0 neither (the crack).
template <class Test>
int hits_of(const ray& r, const std::array<vec3, 3>& a, const std::array<vec3, 3>& b, Test test) {
    return (test(r, a) ? 1 : 0) | (test(r, b) ? 2 : 0);
}

bool mt(const ray& r, const std::array<vec3, 3>& p) {
    float t, u, v;
    return ch01::intersect_triangle(r, p[0], p[1], p[2], t, u, v);
}
bool watertight(const ray& r, const std::array<vec3, 3>& p) {
    float t, u, v;
    return intersect_watertight(r, make_shear(r.dir), p[0], p[1], p[2], t, u, v);
}

diagram crack_figure() {
    const placement pl{1.0f, 0.0f};
    const triangle_mesh sphere = placed_sphere(12, 24, pl);
    const vec3 o = pl.inside();
    // The sides of every triangle by their two vertices, to find each edge's other triangle.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> side_of;
    for (std::uint32_t i = 0; i < sphere.indices.size(); ++i)
        for (int k = 0; k < 3; ++k) side_of[{sphere.indices[i][k], sphere.indices[i][(k + 1) % 3]}] = i;
    // The first side whose midpoint ray (aimed as exercise 15.4 aims it) hits neither triangle.
    std::uint32_t ta = 0, tb = 0, ia = 0, ib = 0;
    bool found = false;
    for (std::uint32_t i = 0; i < sphere.indices.size() && !found; ++i)
        for (int k = 0; k < 3 && !found; ++k) {
            const std::uint32_t a = sphere.indices[i][k], b = sphere.indices[i][(k + 1) % 3];
            const auto other = side_of.find({b, a});
            if (other == side_of.end()) continue;
            const vec3 mid = 0.5f * (sphere.positions[a] + sphere.positions[b]);
            if (hits_of(ray{o, mid - o}, sphere.triangle(i), sphere.triangle(other->second), mt) == 0)
                ta = i, tb = other->second, ia = a, ib = b, found = true;
        }
    const std::array<vec3, 3> A = sphere.triangle(ta), B = sphere.triangle(tb);
    const vec3 pa = sphere.positions[ia], pb = sphere.positions[ib];
    const vec3 mid = 0.5f * (pa + pb), dir0 = mid - o;
    // The grid: directions dir0 + i s along + j s across, in double and rounded once.
    const glm::dvec3 d0(dir0), ed = glm::normalize(d0);
    glm::dvec3 along = glm::dvec3(pb - pa);
    along = glm::normalize(along - glm::dot(along, ed) * ed);
    const glm::dvec3 across = glm::cross(ed, along);
    const double step = glm::length(d0) * 0x1p-24;
    constexpr int half_w = 32, half_h = 16;
    auto grid_ray = [&](int i, int j) { return ray{o, vec3(d0 + (i * step) * along + (j * step) * across)}; };

    diagram d(1040, 400);
    d.text(520, 24, "A ray aimed at a shared edge, and its neighbours one ulp apart", title);
    // Left: the two triangles as the rays see them (projected from o onto the plane at dir0's tip).
    auto seen = [&](const vec3& q) {
        const glm::dvec3 rel = glm::dvec3(q) - glm::dvec3(o);
        const double depth = glm::dot(rel, ed) / glm::length(d0);
        return point2{glm::dot(rel, along) / depth, glm::dot(rel, across) / depth};
    };
    std::vector<point2> pa2, pb2;
    for (const vec3& v : A) pa2.push_back(seen(v));
    for (const vec3& v : B) pb2.push_back(seen(v));
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const auto* poly : {&pa2, &pb2})
        for (const point2& p : *poly) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    d.view(x0, y0, x1, y1, 20, 60, 260, 260);
    d.polygon(pa2, {ink::blue, ink::pale_blue, 1.5});
    d.polygon(pb2, {ink::orange, ink::pale_orange, 1.5});
    const point2 m2 = seen(mid);
    d.circle(m2.x, m2.y, 5, {ink::red, ink::red, 1.5});
    d.pixels();
    d.text(150, 345, "triangles " + std::to_string(ta) + " (blue) and " + std::to_string(tb) + " (orange),", body);
    d.text(150, 362, "seen from inside the sphere; the red", body);
    d.text(150, 379, "point: the edge's midpoint, aimed at", body);

    // Middle and right: the grid with each test; one cell per ray.
    const char* fills[] = {ink::red, ink::pale_blue, ink::pale_orange, ink::purple};
    auto panel = [&](double left, const char* name, auto test) {
        const double cell = 5.0, top = 80;
        int escapes = 0, both = 0;
        for (int j = half_h; j >= -half_h; --j) {
            const double y = top + (half_h - j) * cell;
            // Runs of one colour along a row as one rectangle.
            int run_start = -half_w, run_class = hits_of(grid_ray(-half_w, j), A, B, test);
            for (int i = -half_w; i <= half_w + 1; ++i) {
                const int c = i <= half_w ? hits_of(grid_ray(i, j), A, B, test) : -1;
                if (i <= half_w) escapes += c == 0, both += c == 3;
                if (c == run_class) continue;
                d.rect(left + (run_start + half_w) * cell, y, left + (i + half_w) * cell, y + cell,
                       {"none", fills[run_class], 1.0});
                run_start = i, run_class = c;
            }
        }
        const double w = (2 * half_w + 1) * cell, h = (2 * half_h + 1) * cell;
        d.rect(left, top, left + w, top + h, {ink::black, "none", 1.0});
        d.circle(left + half_w * cell + cell / 2, top + half_h * cell + cell / 2, 3, {ink::black, "none", 1.0});
        d.text(left + w / 2, top - 12, name, {14, "middle", ink::black, true});
        const int rays = (2 * half_w + 1) * (2 * half_h + 1);
        d.text(left + w / 2, top + h + 22,
               std::to_string(escapes) + " of " + std::to_string(rays) + " rays hit neither (red)", body);
        d.text(left + w / 2, top + h + 39, std::to_string(both) + " hit both (purple)", body);
    };
    panel(320, "Moeller-Trumbore (exercise 01.3)", mt);
    panel(685, "watertight (exercises 15.1, 15.2)", watertight);
    d.text(665, 330, "one cell per ray: pale blue hits the blue triangle only, pale orange the orange one; the directions", body);
    d.text(665, 347, "step by 2^-24 of their length along the edge (left to right) and across it; the circle: the aimed ray", body);
    return d;
}

// --- shear.svg -------------------------------------------------------------------------------------------

diagram shear_figure() {
    const ray r{vec3(1.0f, 0.5f, 0.0f), vec3(0.6f, 0.3f, 2.0f)};
    const std::array<vec3, 3> tri = {vec3(1.2f, 0.3f, 3.4f), vec3(3.4f, 0.9f, 4.6f), vec3(2.0f, 2.4f, 4.1f)};
    const shear s = make_shear(r.dir);
    // Step 2a of the exercise: the vertices relative to the origin, sheared.
    struct sheared {
        float x, y, z;
    };
    std::array<sheared, 3> q{};
    for (int k = 0; k < 3; ++k) {
        const vec3 a = tri[k] - r.org;
        q[k] = {a[s.kx] - s.sx * a[s.kz], a[s.ky] - s.sy * a[s.kz], s.sz * a[s.kz]};
    }
    const sheared &qa = q[0], &qb = q[1], &qc = q[2];
    const float U = qc.x * qb.y - qc.y * qb.x, V = qa.x * qc.y - qa.y * qc.x, W = qb.x * qa.y - qb.y * qa.x;
    float t = 0, u = 0, v = 0;
    const bool hit = intersect_watertight(r, s, tri[0], tri[1], tri[2], t, u, v);
    const char* names[] = {"A", "B", "C"};

    diagram d(1040, 430);
    d.text(520, 24, "The watertight test: move the ray to the origin, shear it onto +z, decide in 2D", title);
    // (a) The (kx, kz) plane before: the ray and the triangle's corners.
    const std::string ax(1, "xyz"[s.kx]), az(1, "xyz"[s.kz]), ay(1, "xyz"[s.ky]);
    d.view(-0.5, -0.5, 4.0, 5.5, 30, 60, 290, 290);
    d.line(-0.5, 0, 4.0, 0, {ink::grey, "none", 1.0});
    d.line(0, -0.5, 0, 5.5, {ink::grey, "none", 1.0});
    const float t_end = 2.6f;
    d.arrow(r.org[s.kx], r.org[s.kz], r.org[s.kx] + t_end * r.dir[s.kx], r.org[s.kz] + t_end * r.dir[s.kz],
            {ink::red, "none", 2.0});
    std::vector<point2> before;
    for (const vec3& p : tri) before.push_back({p[s.kx], p[s.kz]});
    d.polygon(before, {ink::blue, ink::pale_blue, 1.5, false, 0.6});
    for (int k = 0; k < 3; ++k) d.text(before[k].x + 0.08, before[k].y + 0.08, names[k], {13, "start", ink::blue, true, true});
    d.circle(r.org[s.kx], r.org[s.kz], 4, {ink::red, ink::red, 1.0});
    d.pixels();
    d.text(175, 372, "1. the (" + ax + ", " + az + ") plane: the ray from its origin", body);
    d.text(175, 389, "and the triangle's corners, as given", body);

    // (b) After: origin at 0, sheared; the ray is the +z axis.
    double lo_x = 0, hi_x = 0, hi_z = 0;
    for (const sheared& p : q) lo_x = std::min<double>(lo_x, p.x), hi_x = std::max<double>(hi_x, p.x), hi_z = std::max<double>(hi_z, p.z);
    d.view(lo_x - 0.3, -0.3, hi_x + 0.3, hi_z + 0.3, 370, 60, 290, 290);
    d.line(lo_x - 0.3, 0, hi_x + 0.3, 0, {ink::grey, "none", 1.0});
    d.arrow(0, 0, 0, hi_z + 0.2, {ink::red, "none", 2.0});
    std::vector<point2> after;
    for (const sheared& p : q) after.push_back({p.x, p.z});
    d.polygon(after, {ink::blue, ink::pale_blue, 1.5, false, 0.6});
    for (int k = 0; k < 3; ++k) d.text(after[k].x + 0.05 * (hi_x - lo_x), after[k].y, names[k], {13, "start", ink::blue, true, true});
    d.circle(0, 0, 4, {ink::red, ink::red, 1.0});
    d.pixels();
    d.text(515, 372, "2. minus the origin, then " + ax + " - sx " + az + " and sz " + az + " (make_shear:", body);
    d.text(515, 389, "sx = " + number_text(s.sx, "%.2f") + ", sz = " + number_text(s.sz, "%.2f") + "): the ray runs up the axis", body);

    // (c) Ray space seen along the ray: the ray is the point (0, 0); U, V, W the areas it makes with the edges.
    double lo = 0, hi = 0;
    for (const sheared& p : q) lo = std::min({lo, double(p.x), double(p.y)}), hi = std::max({hi, double(p.x), double(p.y)});
    d.view(lo - 0.3, lo - 0.3, hi + 0.3, hi + 0.3, 720, 60, 290, 290);
    const point2 O{0, 0}, PA{qa.x, qa.y}, PB{qb.x, qb.y}, PC{qc.x, qc.y};
    d.polygon({O, PB, PC}, {"none", ink::pale_orange, 1.0});
    d.polygon({O, PC, PA}, {"none", ink::pale_green, 1.0});
    d.polygon({O, PA, PB}, {"none", ink::pale_purple, 1.0});
    d.polygon({PA, PB, PC}, {ink::blue, "none", 1.5});
    for (const point2& p : {PA, PB, PC}) d.line(0, 0, p.x, p.y, {ink::grey, "none", 1.0, true});
    auto centre = [](point2 a, point2 b, point2 c) { return point2{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3}; };
    const point2 cu = centre(O, PB, PC), cv = centre(O, PC, PA), cw = centre(O, PA, PB);
    d.text(cu.x, cu.y, "U = " + number_text(U, "%.3f"), {12, "middle", ink::orange, true, true});
    d.text(cv.x, cv.y, "V = " + number_text(V, "%.3f"), {12, "middle", ink::green, true, true});
    d.text(cw.x, cw.y, "W = " + number_text(W, "%.3f"), {12, "middle", ink::purple, true, true});
    const point2 all[] = {PA, PB, PC};
    for (int k = 0; k < 3; ++k) d.text(all[k].x, all[k].y + 0.1, names[k], {13, "middle", ink::blue, true, true});
    d.circle(0, 0, 4, {ink::red, ink::red, 1.0});
    d.pixels();
    d.text(865, 372, "3. seen along the ray (" + ax + ", " + ay + "): same signs, inside;", body);
    d.text(865, 389, hit ? "t = (U Az + V Bz + W Cz) / (U + V + W) = " + number_text(t, "%.4g")
                         : std::string("no hit"), body);
    d.text(520, 418, "A shared edge's function is the same two products subtracted the other way round in the neighbour: "
                     "exactly its negative, so no ray is outside both", {13, "middle", ink::grey});
    return d;
}

// --- offsets.svg -----------------------------------------------------------------------------------------

diagram offsets_figure() {
    // The plane z = 1000 + (x - 1000) / 2, every corner a float; its normal has no y, so (x, z) shows it.
    const std::array<vec3, 3> tri = {vec3(999.0f, -1.0f, 999.5f), vec3(1001.0f, -1.0f, 1000.5f), vec3(1000.0f, 2.0f, 1000.0f)};
    const vec3 n = glm::normalize(glm::cross(tri[1] - tri[0], tri[2] - tri[0]));  // (-1, 0, 2) / sqrt 5
    const vec3 nn = n.z > 0 ? n : -n;
    const vec3 w_out = glm::normalize(nn + vec3(1.2f, 0.0f, 0.0f) * 0.9f);          // about 40 degrees off the plane
    const float ulp = 0x1p-14f;                                                     // floats in [512, 1024)
    constexpr int points = 48;
    struct spawn_point {
        vec3 p;
        float u, v;
    };
    std::vector<spawn_point> hits;
    const vec3 d_in(-0.2f, -0.05f, -1.0f);
    for (int k = 0; k < points; ++k) {
        const float x = 1000.0f + (float(k) - points / 2) * 0.37f * ulp;
        const vec3 target(x, 0.25f + 0.013f * float(k), 1000.0f + (x - 1000.0f) * 0.5f);
        const ray r{target - 3.0f * d_in, d_in};
        float t, u, v;
        if (!intersect_watertight(r, make_shear(r.dir), tri[0], tri[1], tri[2], t, u, v)) continue;
        hits.push_back({(1.0f - u - v) * tri[0] + u * tri[1] + v * tri[2], u, v});
    }
    auto self_hit = [&](const vec3& origin) {
        const ray r{origin, w_out};
        float t, u, v;
        return intersect_watertight(r, make_shear(r.dir), tri[0], tri[1], tri[2], t, u, v);
    };
    struct panel_spec {
        const char* name;
        offset_kind kind;
    };
    const panel_spec panels[] = {{"no offset (tmin = 0)", offset_kind::none},
                                 {"p + 1e-4 n (one epsilon)", offset_kind::fixed},
                                 {"pbrt-v4: p's error bound along n", offset_kind::bounded}};
    auto moved = [&](const spawn_point& h, offset_kind k) {
        switch (k) {
            case offset_kind::none: return h.p;
            case offset_kind::fixed: return offset_fixed(h.p, n, w_out, fixed_epsilon);
            case offset_kind::bounded:
                return offset_bounded(h.p, interpolation_error(1.0f - h.u - h.v, h.u, h.v, tri[0], tri[1], tri[2]), n, w_out);
            case offset_kind::integer: return offset_integer(h.p, n, w_out);
        }
        return h.p;
    };
    // One window (in ulps from (1000, 1000)) for the three panels: every point with a margin.
    double lx = 0, hx = 0, lz = 0, hz = 0;
    for (const spawn_point& h : hits)
        for (const panel_spec& ps : panels) {
            const vec3 m = moved(h, ps.kind);
            lx = std::min(lx, (m.x - 1000.0) / ulp), hx = std::max(hx, (m.x - 1000.0) / ulp);
            lz = std::min(lz, (m.z - 1000.0) / ulp), hz = std::max(hz, (m.z - 1000.0) / ulp);
        }
    lx = std::floor(lx) - 1, hx = std::ceil(hx) + 1, lz = std::floor(lz) - 1, hz = std::ceil(hz) + 1;

    diagram d(1040, 440);
    d.text(520, 24, "Where a secondary ray starts: hit points on the float lattice, near 1,000 (floats 2^-14 apart)", title);
    for (int pi = 0; pi < 3; ++pi) {
        const double left = 20 + 340.0 * pi;
        d.view(lx, lz, hx, hz, left, 60, 320, 300);
        for (double x = lx; x <= hx; ++x)
            for (double z = lz; z <= hz; ++z) d.circle(x, z, 1.2, {"none", ink::grey, 1.0});
        // The plane z - 1000 = (x - 1000) / 2, in ulps, inside the window.
        const double xa = std::max(lx, 2 * lz), xb = std::min(hx, 2 * hz);
        d.line(xa, xa / 2, xb, xb / 2, {ink::blue, "none", 2.0});
        int self_hits = 0;
        for (const spawn_point& h : hits) {
            const vec3 m = moved(h, panels[pi].kind);
            const bool bad = self_hit(m);
            self_hits += bad;
            const double x = (m.x - 1000.0) / ulp, z = (m.z - 1000.0) / ulp;
            if (panels[pi].kind != offset_kind::none)
                d.line((h.p.x - 1000.0) / ulp, (h.p.z - 1000.0) / ulp, x, z, {ink::grey, "none", 0.8});
            d.circle(x, z, 4, {bad ? ink::red : ink::green, bad ? ink::pale_red : ink::pale_green, 1.5});
        }
        d.pixels();
        d.text(left + 160, 52, panels[pi].name, {14, "middle", ink::black, true});
        d.text(left + 160, 382, std::to_string(self_hits) + " of " + std::to_string(hits.size()) + " hit their own triangle (red)", body);
    }
    // Waechter and Binder's offset moves by ulps too, but by int(256 n) of them: far off this window.
    const vec3 wb = offset_integer(hits.front().p, n, w_out);
    d.text(520, 408, "48 hit points (several on one float); from each a ray leaves at 40 degrees to the surface; blue: the plane; "
                     "grey dots: every float in x and z", {12, "middle", ink::grey});
    d.text(520, 425, "Waechter and Binder's integer offset moves each point by " +
                         number_text((wb.x - hits.front().p.x) / ulp, "%.0f") + " ulps in x and " +
                         number_text((wb.z - hits.front().p.z) / ulp, "%.0f") + " in z, far beyond this window",
           {12, "middle", ink::grey});
    return d;
}

}  // namespace

std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force) {
    return write_figures(folder, force,
                         {{"crack.svg", crack_figure}, {"shear.svg", shear_figure}, {"offsets.svg", offsets_figure}});
}

}  // namespace strahl::ch15
