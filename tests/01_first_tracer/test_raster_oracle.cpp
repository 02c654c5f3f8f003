// Exercise 01.3 ray/triangle (2 of its 6 points): brute force primary visibility with the student's
// triangle test, against the OSMesa rasteriser's triangle-id buffer, an independent answer.
//
// Speed: every pixel is traced, but not against every triangle. Triangles are binned in screen space
// conservatively: a triangle with all three vertices in front of the eye can only be hit by rays through
// the 2D box of its projected vertices, widened here by 2 pixels for rounding; a triangle with a vertex on
// or behind the eye plane goes into every bin. So each pixel's closest hit over its bin's triangles is the
// closest hit over all triangles: brute force, with the triangles that cannot matter left out.
#include "strahl/ch01/shapes.hpp"
#include "strahl/display.hpp"
#include "strahl/procedural.hpp"
#include "strahl/scene.hpp"
#include "test_support.hpp"
#include <catch2/catch.hpp>
#include <algorithm>
#include <string>
#include <vector>

using namespace strahl;

namespace {

constexpr int bin_size = 8;

struct oracle_stats {
    std::size_t pixels = 0, covered = 0, mismatches = 0, unexplained = 0;
    std::string first_unexplained;  // the first few, one a line
};

// Triangles binned in screen space, conservatively (see the top).
struct screen_bins {
    int bins_x = 0;
    std::vector<std::vector<std::uint32_t>> bins;
};

screen_bins bin_triangles(const triangle_mesh& mesh, const camera& cam) {
    const int w = cam.width(), h = cam.height();
    const int bins_x = (w + bin_size - 1) / bin_size, bins_y = (h + bin_size - 1) / bin_size;
    screen_bins sb{bins_x, std::vector<std::vector<std::uint32_t>>(std::size_t(bins_x) * bins_y)};
    const float sx = cam.tan_half_fov() * cam.aspect(), sy = cam.tan_half_fov();
    for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
        float x0 = inf, y0 = inf, x1 = -inf, y1 = -inf;
        bool everywhere = false;
        for (const vec3& p : mesh.triangle(i)) {
            const vec3 q = p - cam.eye();
            const float z = glm::dot(q, cam.forward());
            if (!(z > 1e-6f * glm::length(q))) { everywhere = true; break; }
            const float px = (glm::dot(q, cam.right()) / (z * sx) + 1.0f) * 0.5f * float(w);
            const float py = (1.0f - glm::dot(q, cam.up()) / (z * sy)) * 0.5f * float(h);
            x0 = std::min(x0, px); x1 = std::max(x1, px); y0 = std::min(y0, py); y1 = std::max(y1, py);
        }
        int bx0 = 0, bx1 = bins_x - 1, by0 = 0, by1 = bins_y - 1;
        if (!everywhere) {
            if (x1 < -2.0f || y1 < -2.0f || x0 > float(w) + 2.0f || y0 > float(h) + 2.0f) continue;
            bx0 = std::max(0, int(std::floor(x0 - 2.0f)) / bin_size);
            by0 = std::max(0, int(std::floor(y0 - 2.0f)) / bin_size);
            bx1 = std::min(bins_x - 1, int(std::floor(x1 + 2.0f)) / bin_size);
            by1 = std::min(bins_y - 1, int(std::floor(y1 + 2.0f)) / bin_size);
        }
        for (int by = by0; by <= by1; ++by)
            for (int bx = bx0; bx <= bx1; ++bx) sb.bins[std::size_t(by) * bins_x + bx].push_back(std::uint32_t(i));
    }
    return sb;
}

// Brute force closest hit of a ray through pixel (x, y) at the given offset, over the pixel's bin.
std::uint32_t closest(const triangle_mesh& mesh, const screen_bins& sb, const camera& cam, int x, int y,
                      vec2 offset = vec2(0.5f)) {
    ray r = cam.pixel_ray(x, y, offset);
    std::uint32_t id = invalid_id;
    for (const std::uint32_t i : sb.bins[std::size_t(y / bin_size) * sb.bins_x + x / bin_size]) {
        const auto v = mesh.triangle(i);
        float t, u, bv;
        if (ch01::intersect_triangle(r, v[0], v[1], v[2], t, u, bv)) {
            r.tmax = t;
            id = i;
        }
    }
    return id;
}

// A triangle id in a message: "none" for a miss.
std::string name_of(std::uint32_t id) { return id == invalid_id ? std::string("none") : std::to_string(id); }

bool share_vertex(const triangle_mesh& mesh, std::uint32_t a, std::uint32_t b) {
    const uvec3 ia = mesh.indices[a], ib = mesh.indices[b];
    const auto pa = mesh.triangle(a), pb = mesh.triangle(b);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (ia[i] == ib[j] || pa[std::size_t(i)] == pb[std::size_t(j)]) return true;
    return false;
}

// Every mismatch must be explained: on a silhouette (a 3x3 neighbour in the id buffer is background), a
// hit/miss difference at an edge (a neighbour names another triangle), two triangles sharing a vertex
// (a shared edge, where the two answers may round either way), sub-pixel rounding, or a depth tie.
oracle_stats compare(const triangle_mesh& mesh, const camera& cam) {
    const raster_result raster = rasterize(mesh, cam);
    REQUIRE(raster.width == cam.width());
    REQUIRE(raster.height == cam.height());
    const screen_bins sb = bin_triangles(mesh, cam);
    const int w = cam.width(), h = cam.height();
    std::vector<std::uint32_t> traced(std::size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) traced[std::size_t(y) * w + x] = closest(mesh, sb, cam, x, y);
    oracle_stats s;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint32_t a = traced[std::size_t(y) * w + x], b = raster.ids[std::size_t(y) * w + x];
            ++s.pixels;
            if (b != invalid_id) ++s.covered;
            if (a == b) continue;
            ++s.mismatches;
            bool silhouette = false, edge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const std::uint32_t n = raster.ids[std::size_t(ny) * w + nx];
                    silhouette = silhouette || n == invalid_id;
                    edge = edge || n != b;
                }
            // Sub-pixel rounding: the rasteriser snaps vertices to a sub-pixel grid, so where the pixel centre
            // lies within 1/8 pixel of an edge, the raster's answer is what a ray 1/8 pixel away sees.
            bool subpixel = false;
            for (const vec2 o : {vec2(0.625f, 0.5f), vec2(0.375f, 0.5f), vec2(0.5f, 0.625f), vec2(0.5f, 0.375f)})
                subpixel = subpixel || closest(mesh, sb, cam, x, y, o) == b;
            const bool hit_miss_edge = (a == invalid_id || b == invalid_id) && edge;
            const bool shared = a != invalid_id && b != invalid_id && share_vertex(mesh, a, b);
            // Where two surfaces meet or cross (the teapot's spout and handle enter its body), both
            // triangles lie at the same depth along the pixel's ray: a tie that either answer may win.
            float ta = inf, tb = inf;
            if (a != invalid_id && b != invalid_id) {
                float u, v;
                const ray r = cam.pixel_ray(x, y);
                const auto va = mesh.triangle(a), vb = mesh.triangle(b);
                if (!ch01::intersect_triangle(r, va[0], va[1], va[2], ta, u, v)) ta = inf;
                if (!ch01::intersect_triangle(r, vb[0], vb[1], vb[2], tb, u, v)) tb = raster.depth[std::size_t(y) * w + x];
            }
            const bool tie = std::isfinite(ta) && std::abs(ta - tb) <= 1e-3f * ta;
            if (!(silhouette || hit_miss_edge || shared || subpixel || tie)) {
                ++s.unexplained;
                if (s.unexplained <= 5)
                    s.first_unexplained += "\n  unexplained mismatch at pixel (" + std::to_string(x) + ", " +
                                           std::to_string(y) + "): traced triangle " + name_of(a) + " at t = " +
                                           std::to_string(ta) + ", rasterised " + name_of(b) + " at t = " +
                                           std::to_string(tb);
            }
        }
    return s;
}

void check_against_raster(const std::string& name, const triangle_mesh& mesh, const camera& cam) {
    const oracle_stats s = compare(mesh, cam);
    INFO(name << ": " << s.pixels << " pixels, " << s.covered << " covered, " << s.mismatches
              << " differ, " << s.unexplained << " unexplained");
    CHECK(s.covered > s.pixels / 10);  // the mesh is in view
    CHECK(double(s.pixels - s.mismatches) >= 0.995 * double(s.pixels));
    INFO("the first " << std::min<std::size_t>(s.unexplained, 5) << " unexplained:" << s.first_unexplained);
    CHECK(s.unexplained == 0);
}

}  // namespace

TEST_CASE("01.3 ray/triangle: brute force names the rasteriser's triangle on the teapot and the bunny",
          "[ch01][pts:2][oracle]") {
    {
        const triangle_mesh teapot = teapot_mesh(8);
        // Seen from above and the front, close enough to fill about a third of the picture.
        const aabb box = teapot.bounds();
        const float radius = 0.5f * glm::length(box.extent());
        const vec3 eye = box.centroid() + glm::normalize(vec3(0.3f, 0.5f, 1.0f)) * (2.4f * radius);
        check_against_raster("teapot", teapot, camera(camera_desc{eye, box.centroid(), vec3(0, 1, 0), 40.0f}, 256, 192));
    }
    const auto bunny_file = test::shared_scene("bunny.ply");
    if (bunny_file.empty()) {
        WARN("bunny: skipped: ../shared/scenes not found");
        return;
    }
    const scene bunny = load_scene(bunny_file);
    check_against_raster("bunny", bunny.mesh, camera(bunny.camera, 256, 256));
}
