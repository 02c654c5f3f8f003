// The chapter's figure, computed by the chapter's own code (`ch12 --diagrams DIR`):
//   packet.svg: a packet of 16 rays from one eye (a fan in x, seen from above) against three boxes, with
//   the packet's box test (exercise 12.1: one test, a bit per lane) and its interval-arithmetic frustum
//   (exercise 12.2: one test for the whole packet). A box inside the fan gives the lanes that enter it; a
//   box between two rays lies inside the frustum, so only the lane test can say that no ray enters; a box
//   beside the fan is culled by the frustum alone. Below, the packet's rows in memory (structure of arrays).
#include "strahl/ch12/packet.hpp"
#include "strahl/diagram.hpp"
#include <array>
#include <bit>
#include <string>
#include <vector>

namespace strahl::ch12 {

namespace {

diagram packet_figure() {
    constexpr int K = 16;
    std::array<ray, K> rays;
    std::array<std::uint32_t, K> ids;
    for (int i = 0; i < K; ++i) rays[i] = ray{vec3(0.0f), vec3(0.1f + 0.04f * float(i), 0.05f, 1.0f)}, ids[i] = std::uint32_t(i);
    struct box_case {
        aabb box;
        const char* name;
        const char* colour;
        const char* fill;
    };
    const box_case boxes[] = {
        {aabb(vec3(0.75f, -1.0f, 3.0f), vec3(1.6f, 1.0f, 4.0f)), "inside the fan", ink::blue, ink::pale_blue},
        {aabb(vec3(3.80f, -1.0f, 8.0f), vec3(3.97f, 1.0f, 8.2f)), "between two rays", ink::orange, ink::pale_orange},
        {aabb(vec3(3.6f, -1.0f, 2.2f), vec3(4.6f, 1.0f, 3.0f)), "beside the fan", ink::green, ink::pale_green}};
    aabb all;
    for (const box_case& b : boxes) all.grow(b.box);
    const tree_frame frame(all);
    ray_packet<K, 1> p;
    p.set_rays(rays.data(), ids.data(), K);
    unsigned refused[1] = {0};
    p.set_terms(frame, refused);
    p.finish(frame);
    const lane_rays<K> lanes = load(p, 0);

    diagram d(1000, 560);
    d.text(500, 24, "One packet, one test per box: 16 rays in SIMD lanes (seen from above)", {15, "middle", ink::black, true});
    const float z_end = 9.0f;
    d.view(-0.5, -0.4, 6.2, 9.4, 20, 40, 560, 380);
    // The frustum: the region between the outermost rays.
    const vec3 d0 = rays[0].dir, d1 = rays[K - 1].dir;
    d.polygon({{0, 0}, {d0.x * z_end, z_end}, {d1.x * z_end, z_end}}, {"none", ink::pale_grey, 1.0});
    std::vector<unsigned> masks;
    for (const box_case& b : boxes) {
        simd::vfloat<K> entry;
        const unsigned bits = simd::movemask(packet_box_out_of_line<true, K>(lanes, &b.box.min[0], &b.box.max[0], p.octant, entry));
        masks.push_back(bits & p.active[0]);
    }
    for (int i = 0; i < K; ++i) {
        const bool in = (masks[0] >> i) & 1u;
        d.line(0, 0, rays[i].dir.x * z_end, z_end, {in ? ink::blue : ink::grey, "none", in ? 1.6 : 1.0});
    }
    for (const box_case& b : boxes) d.rect(b.box.min.x, b.box.min.z, b.box.max.x, b.box.max.z, {b.colour, b.fill, 1.8, false, 0.85});
    d.circle(0, 0, 5, {ink::black, ink::black, 1.0});
    d.text(0.1, -0.3, "eye", {12, "start"});
    d.text(rays[0].dir.x * z_end, z_end + 0.15, "lane 0", {11, "middle", ink::grey});
    d.text(rays[K - 1].dir.x * z_end, z_end + 0.15, "lane 15", {11, "middle", ink::grey});
    d.pixels();

    // Right: per box, what the two tests say.
    const font head{14, "start", ink::black, true}, body{13, "start"};
    double y = 70;
    for (std::size_t b = 0; b < 3; ++b) {
        const bool culled = frustum_misses_out_of_line<K, 1>(p, &boxes[b].box.min[0], &boxes[b].box.max[0]);
        std::string bits;
        for (int i = 0; i < K; ++i) bits += ((masks[b] >> i) & 1u) ? '1' : '0';
        d.text(600, y, boxes[b].name, {14, "start", boxes[b].colour, true});
        d.text(600, y + 20, "frustum test (12.2): " + std::string(culled ? "misses: culled, no lane tested" : "cannot rule it out"), body);
        d.text(600, y + 40, "lane test (12.1), lanes 0 to 15:", body);
        d.text(600, y + 58, bits, {13, "start", ink::black, true});
        d.text(600, y + 76, std::to_string(std::popcount(masks[b])) + " of 16 rays enter" +
                                (masks[b] == 0 && !culled ? ": 16 lanes of work for nothing" : ""),
               body);
        y += 115;
    }

    // Below: the packet in memory, a row of 16 floats per field.
    const double top = 450, left = 120, cell = 48;
    d.text(500, top - 10, "the packet's rays in memory: one row of 16 lanes per field, each row one 64-byte SIMD load", {13, "middle"});
    const char* fields[] = {"org x", "dir x", "1/d x"};
    const float* rows[] = {p.org[0], p.dir[0], p.inv[0]};
    for (int r = 0; r < 3; ++r) {
        d.text(left - 10, top + 18 + 22.0 * r, fields[r], {12, "end", ink::black, true});
        for (int i = 0; i < K; ++i) {
            const double x = left + cell * i;
            d.rect(x, top + 4 + 22.0 * r, x + cell, top + 24 + 22.0 * r, {ink::grey, ((masks[0] >> i) & 1u) ? ink::pale_blue : "white", 0.8});
            d.text(x + cell / 2, top + 18 + 22.0 * r, number_text(rows[r][i], "%.2f"), {11, "middle"});
        }
    }
    d.text(500, top + 96, "... and dir y, dir z, the slab terms, tmin, tmax, the best hit: " +
                               std::to_string(sizeof(p)) + " bytes for 16 rays", {12, "middle", ink::grey});
    return d;
}

}  // namespace

std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force) {
    return write_figures(folder, force, {{"packet.svg", packet_figure}});
}

}  // namespace strahl::ch12
