// The chapter's figure, computed by the chapter's own code (`ch11 --diagrams DIR`):
//   layouts.svg: one leaf of five primitives (three triangles, a sphere, a plane, in the tree's order) as each
//   step of the chapter holds it in memory, every size from the code's own types (sizeof): step 1, owning
//   pointers to heap objects, each starting with its vtable pointer; step 2, one array of std::variant, each
//   slot as large as the largest type plus the index; step 3, one array per type and a range per type in the
//   leaf (sort_leaf_by_type, exercise 11.3); steps 4 and 5, the triangles alone, v0 and two edges, the leaf
//   a range; step 6, the same nine floats as nine arrays, the leaf a run in each.
#include "strahl/ch01/shapes.hpp"
#include "strahl/ch11/shapes.hpp"
#include "strahl/ch11/triangles.hpp"
#include "strahl/ch11/type_sorted.hpp"
#include "strahl/diagram.hpp"
#include <memory>
#include <string>
#include <vector>

namespace strahl::ch11 {

namespace {

diagram layouts_figure() {
    // The leaf, in the tree's order: triangle, sphere, triangle, plane, triangle (ids into `shapes`).
    const std::vector<shape> shapes = {
        triangle_shape{vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)}, sphere_shape{vec3(2, 0, 0), 0.5f},
        triangle_shape{vec3(1, 1, 0), vec3(2, 1, 0), vec3(1, 2, 0)}, plane_shape{vec3(0, 1, 0), -1.0f},
        triangle_shape{vec3(0, 2, 0), vec3(1, 2, 0), vec3(0, 3, 0)}};
    const std::vector<std::uint32_t> leaf = {0, 1, 2, 3, 4};
    sorted_primitives sorted;
    const sorted_leaf ranges = sort_leaf_by_type(leaf, shapes, sorted);

    const char* type_name[] = {"triangle", "sphere", "plane"};
    const char* stroke[] = {ink::blue, ink::green, ink::orange};
    const char* fill[] = {ink::pale_blue, ink::pale_green, ink::pale_orange};
    const std::size_t object_bytes[] = {sizeof(ch01::triangle), sizeof(ch01::sphere), sizeof(ch01::plane)};
    const double px = 2.5;  // pixels per byte

    diagram d(1100, 610);
    const font title{15, "middle", ink::black, true}, step{13, "start", ink::black, true}, body{12, "start"},
        cell{11, "middle"};
    d.text(550, 24, "One leaf of five primitives, as each step holds it in memory (widths to scale: " +
                        number_text(px, "%.1f") + " pixels per byte)", title);
    const double left = 250;

    // Step 1: owning pointers, objects on the heap.
    double y = 60;
    d.text(20, y + 14, "1 virtual", step);
    d.text(20, y + 31, "pointers to heap objects", body);
    for (std::size_t i = 0; i < leaf.size(); ++i) {
        const double x = left + 8 * px * double(i);
        d.rect(x, y, x + 8 * px, y + 20, {ink::black, "white", 1.0});
    }
    d.text(left + 8 * px * 5 + 8, y + 14, "8 bytes each", body);
    // Wherever the allocator put them: two rows, out of order.
    const double at_x[] = {420, 130, 0, 330, 210}, at_row[] = {0, 1, 0, 1, 0};
    for (std::size_t i = 0; i < leaf.size(); ++i) {
        const int t = int(shapes[leaf[i]].index());
        const double w = double(object_bytes[t]) * px, ox = left + 100 + at_x[i], oy = y + 45 + 34.0 * at_row[i];
        d.arrow(left + 8 * px * (double(i) + 0.5), y + 20, ox + 4 * px, oy, {ink::grey, "none", 1.0});
        d.rect(ox, oy, ox + w, oy + 18, {stroke[t], fill[t], 1.2});
        d.rect(ox, oy, ox + 8 * px, oy + 18, {stroke[t], "white", 1.2});
        d.text(ox + 4 * px, oy + 13, "vt", {10, "middle"});
        d.text(ox + w / 2 + 4 * px, oy + 13, type_name[t] + std::string(" ") + std::to_string(object_bytes[t]) + " B", {9, "middle"});
    }
    d.text(left + 100, y + 117, "each object on the heap, its vtable pointer (vt) first", body);

    // Step 2: one array of variants.
    y = 200;
    d.text(20, y + 14, "2 variant", step);
    d.text(20, y + 31, "std::variant by value", body);
    for (std::size_t i = 0; i < leaf.size(); ++i) {
        const int t = int(shapes[leaf[i]].index());
        const double x = left + double(sizeof(shape)) * px * double(i);
        d.rect(x, y, x + double(sizeof(shape)) * px, y + 20, {stroke[t], fill[t], 1.2});
        d.text(x + double(sizeof(shape)) * px / 2, y + 14, type_name[t] + std::string(" (index ") + std::to_string(t) + ")", cell);
    }
    d.text(left + double(sizeof(shape)) * px * 5 + 8, y + 14, std::to_string(sizeof(shape)) + " bytes each", body);

    // Step 3: an array per type, the leaf a range in each.
    y = 265;
    d.text(20, y + 14, "3 type-sorted", step);
    d.text(20, y + 31, "a range per type (11.3)", body);
    const std::size_t type_bytes[] = {sizeof(triangle_shape), sizeof(sphere_shape), sizeof(plane_shape)};
    for (int t = 0; t < shape_types; ++t) {
        const double row = y + 26.0 * t;
        for (std::uint32_t k = 0; k < ranges.count[std::size_t(t)]; ++k) {
            const double x = left + double(type_bytes[t]) * px * double(ranges.first[std::size_t(t)] + k);
            d.rect(x, row, x + double(type_bytes[t]) * px, row + 20, {stroke[t], fill[t], 1.2});
            d.text(x + double(type_bytes[t]) * px / 2, row + 14, "id " + std::to_string(sorted.ids[std::size_t(t)][ranges.first[std::size_t(t)] + k]), cell);
        }
        const double end = left + double(type_bytes[t]) * px * double(ranges.first[std::size_t(t)] + ranges.count[std::size_t(t)]);
        d.text(end + 8, row + 14, std::string(type_name[t]) + "s: [" + std::to_string(ranges.first[std::size_t(t)]) + ", " +
                                      std::to_string(ranges.first[std::size_t(t)] + ranges.count[std::size_t(t)]) + "), " +
                                      std::to_string(type_bytes[t]) + " bytes each", body);
    }

    // Steps 4 and 5: triangles only, v0 and the edges.
    y = 360;
    d.text(20, y + 14, "4, 5 triangles only", step);
    d.text(20, y + 31, "v0, e1, e2; in leaf order", body);
    const double tw = double(sizeof(edge_triangle)) * px;
    for (int k = 0; k < 3; ++k) {
        const double x = left + tw * k;
        d.rect(x, y, x + tw, y + 20, {stroke[0], fill[0], 1.2});
        for (int f = 1; f < 3; ++f) d.line(x + tw * f / 3, y, x + tw * f / 3, y + 20, {stroke[0], "none", 0.6});
        d.text(x + tw / 6, y + 14, "v0", cell), d.text(x + tw / 2, y + 14, "e1", cell), d.text(x + 5 * tw / 6, y + 14, "e2", cell);
    }
    d.text(left + tw * 3 + 8, y + 14, std::to_string(sizeof(edge_triangle)) +
                                          " bytes each; the leaf: a range of slots (the sphere and the plane traced apart)", body);

    // Step 6: nine arrays.
    y = 425;
    d.text(20, y + 14, "6 structure of arrays", step);
    d.text(20, y + 31, "nine floats, nine arrays", body);
    const char* rows[] = {"v0.x", "v0.y", "v0.z", "e1.x", "e1.y", "e1.z", "e2.x", "e2.y", "e2.z"};
    edge_triangles_soa soa;
    for (const triangle_shape& t : sorted.triangles) soa.push_back(make_edge_triangle(t.v0, t.v1, t.v2));
    for (int r = 0; r < 9; ++r) {
        const double row = y + 17.0 * r, fw = 4 * px * 4;  // a float drawn 4 times wider to fit its digits
        d.text(left - 8, row + 12, rows[r], {11, "end"});
        for (std::size_t k = 0; k < soa.size(); ++k) {
            const double x = left + fw * double(k);
            d.rect(x, row, x + fw, row + 15, {stroke[0], fill[0], 0.8});
            d.text(x + fw / 2, row + 11, number_text(soa.c[r][k], "%g"), {10, "middle"});
        }
    }
    d.text(left + 4 * px * 4 * 3 + 12, y + 70, "a leaf's triangles: nine runs of consecutive floats (floats drawn 4x wider)", body);
    return d;
}

}  // namespace

std::vector<std::filesystem::path> write_diagrams(const std::filesystem::path& folder, bool force) {
    return write_figures(folder, force, {{"layouts.svg", layouts_figure}});
}

}  // namespace strahl::ch11
