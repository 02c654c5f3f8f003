// The chapter's figure, computed by the chapter's own tracer (`ch14 --diagrams DIR`):
//   switch.svg: a field of about 1,000 small upright triangles (seen from above) and two packets of 16 rays traced
//   by the hybrid tracer (make_accel: 16 lanes, the threshold chosen per packet by exercise 14.2's rule).
//   A camera tile's narrow fan (one octant, a small spread: the packet stays together down to a quarter of
//   its lanes); a wide fan in one octant (half of the lanes); 16 rays leaving one point in every direction,
//   as diffuse bounces do (half). Each ray is drawn to its hit, blue where the packet traced it to the end,
//   orange where it left (the tracer's per-ray figure, as in the chapter's departure images).
#include "strahl/ch14/accel.hpp"
#include "strahl/ch14/hybrid_walk.hpp"
#include "strahl/diagram.hpp"
#include "strahl/rng.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace strahl::ch14 {

namespace {

diagram switch_figure() {
    // The field: upright triangles from y = -1 to 1, short segments when seen from above (x across, z up).
    scene field;
    field.name = "field";
    pcg32 g(14, 2);
    for (int i = 0; i < 1000; ++i) {
        const float x = -7.0f + 14.0f * g.next_float(), z = -7.0f + 14.0f * g.next_float();
        if (x * x + z * z < 1.0f) continue;  // a clearing around the scattering point
        const float a = 6.2831853f * g.next_float(), len = 0.1f + 0.15f * g.next_float();
        const vec3 p(x, -1.0f, z), q(x + len * std::cos(a), -1.0f, z + len * std::sin(a));
        const auto v = std::uint32_t(field.mesh.positions.size());
        field.mesh.positions.insert(field.mesh.positions.end(), {p, q, 0.5f * (p + q) + vec3(0.0f, 2.0f, 0.0f)});
        field.mesh.indices.push_back(uvec3(v, v + 1, v + 2));
    }
    hybrid_config config;  // 16 lanes, the threshold per packet
    const auto tracer = make_accel("hybrid", config);
    tracer->build(field);

    // Three packets of 16 rays: a camera tile's narrow fan (one octant, spread 0.03), a wide fan (one octant,
    // spread 0.3) from the field's edge, and rays scattered from its middle into every direction.
    std::array<std::vector<ray>, 3> packets;
    for (int i = 0; i < 16; ++i) {
        packets[0].push_back(ray{vec3(-4.0f, 0.0f, -7.5f), vec3(0.05f + 0.002f * float(i), 0.01f, 1.0f)});
        packets[1].push_back(ray{vec3(1.0f, 0.0f, -7.5f), vec3(0.02f + 0.02f * float(i), 0.01f, 1.0f)});
        const float a = 6.2831853f * (float(i) + 0.5f * g.next_float()) / 16.0f;
        packets[2].push_back(ray{vec3(0.0f, 0.0f, 0.0f), vec3(std::cos(a), 0.2f * (g.next_float() - 0.5f), std::sin(a))});
    }
    const char* names[] = {"a camera tile: spread 0.03", "a wide fan: spread 0.3", "scattered: every octant"};

    diagram d(1000, 500);
    d.text(500, 24, "Rays leave their packet where it thins out: three packets of 16 rays through the hybrid tracer",
           {15, "middle", ink::black, true});
    for (int pi = 0; pi < 3; ++pi) {
        const std::vector<ray>& rays = packets[std::size_t(pi)];
        std::vector<hit> hits(rays.size());
        std::vector<float> share;
        const ch12::lane_stats stats = tracer->closest_lanes(rays, hits, &share);
        std::uint64_t packet_visits = 0;
        for (const std::uint64_t v : stats.visits) packet_visits += v;
        // The rule's threshold for this packet (exercise 14.2), from the packet as the tracer fills it.
        ch12::ray_packet<16, 1> p;
        std::array<std::uint32_t, 16> ids{};
        for (std::uint32_t i = 0; i < 16; ++i) ids[i] = i;
        p.set_rays(rays.data(), ids.data(), 16);
        const int threshold = packet_threshold(packet_coherence_out_of_line<16>(p), 16, threshold_rule{});

        const double left = 15 + 330.0 * pi;
        d.view(-7.5, -7.6, 7.5, 7.5, left, 50, 310, 310);
        d.rect(-7.5, -7.6, 7.5, 7.5, {ink::grey, "none", 1.0});
        for (std::size_t t = 0; t < field.mesh.triangle_count(); ++t) {
            const auto tri = field.mesh.triangle(t);
            d.line(tri[0].x, tri[0].z, tri[1].x, tri[1].z, {ink::grey, "none", 1.2});
        }
        int left_count = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const ray& r = rays[i];
            // To the hit, or to the field's edge (|x|, |z| = 7.5).
            float t = hits[i].t;
            if (!hits[i].found()) {
                t = inf;
                for (int a : {0, 2})
                    if (r.dir[a] != 0.0f) t = std::min(t, ((r.dir[a] > 0 ? 7.5f : -7.5f) - r.org[a]) / r.dir[a]);
            }
            const vec3 e = r.org + t * r.dir;
            const bool stayed = share[i] >= 1.0f;
            left_count += !stayed;
            const char* colour = stayed ? ink::blue : ink::orange;
            d.line(r.org.x, r.org.z, e.x, e.z, {colour, "none", 1.4});
            if (hits[i].found()) d.circle(e.x, e.z, 2.5, {colour, colour, 1.0});
        }
        d.circle(rays[0].org.x, rays[0].org.z, 4, {ink::black, ink::black, 1.0});
        d.pixels();
        const double mid = left + 155;
        d.text(mid, 382, names[pi], {13, "middle", ink::black, true});
        d.text(mid, 400, "threshold " + std::to_string(threshold) + " lanes: " + std::to_string(left_count) +
                             " of 16 rays left", {12, "middle"});
        d.text(mid, 417, "the packet: " + std::to_string(packet_visits) + " node visits, " +
                             number_text(stats.mean_active(), "%.1f") + " busy lanes each", {12, "middle"});
        d.text(mid, 434, "node visits in all, lone walks too: " + std::to_string(stats.counts.nodes_visited), {12, "middle"});
    }
    d.text(500, 470, "blue: traced in the packet to its hit; orange: left the packet and went on alone (chapter 13's "
                     "single-ray walk); seen from above", {12, "middle", ink::grey});
    d.text(500, 487, "the threshold by exercise 14.2's rule: a quarter of the lanes for one octant and a spread below "
                     "0.05, else half", {12, "middle", ink::grey});
    return d;
}

}  // namespace

std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force) {
    return write_figures(folder, force, {{"switch.svg", switch_figure}});
}

}  // namespace strahl::ch14
