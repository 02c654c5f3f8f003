// common/display: the OSMesa rasteriser as an oracle for primary visibility, and line overlays.
// The central check: away from triangle edges, the id buffer agrees with a ray/triangle test through the
// camera's pixel centres, so rasteriser and tracer share pixel centres and projection exactly.
#include "strahl/display.hpp"
#include "test_support.hpp"
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <thread>

using namespace strahl;

namespace {

// Moeller-Trumbore in double precision (Moeller and Trumbore, "Fast, minimum storage ray-triangle
// intersection", 1997): the distance t along the ray, or -1 for a miss.
double moeller_trumbore(const ray& r, const std::array<vec3, 3>& v) {
    const glm::dvec3 o(r.org), d(r.dir), v0(v[0]), e1 = glm::dvec3(v[1]) - v0, e2 = glm::dvec3(v[2]) - v0;
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0) return -1.0;
    const glm::dvec3 s = o - v0;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return -1.0;
    const glm::dvec3 q = glm::cross(s, e1);
    const double w = glm::dot(d, q) / det;
    if (w < 0.0 || u + w > 1.0) return -1.0;
    const double t = glm::dot(e2, q) / det;
    return t > 0.0 ? t : -1.0;
}

// Image coordinates of a point in front of the camera (the inverse of camera::generate).
glm::dvec2 project(const camera& cam, const vec3& p) {
    const glm::dvec3 q = glm::dvec3(p) - glm::dvec3(cam.eye());
    const double z = glm::dot(q, glm::dvec3(cam.forward()));
    const double tx = double(cam.tan_half_fov()) * double(cam.aspect()), ty = double(cam.tan_half_fov());
    const double ndc_x = glm::dot(q, glm::dvec3(cam.right())) / (z * tx), ndc_y = glm::dot(q, glm::dvec3(cam.up())) / (z * ty);
    return {(ndc_x + 1.0) * 0.5 * cam.width(), (1.0 - ndc_y) * 0.5 * cam.height()};
}

double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double s = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + s * ab));
}

triangle_mesh one_triangle(vec3 a, vec3 b, vec3 c) {
    triangle_mesh m;
    m.positions = {a, b, c};
    m.indices = {uvec3(0, 1, 2)};
    return m;
}

// Compares the id buffer with ray casting at every pixel whose centre lies at least `margin` pixels from
// every projected edge (all triangles must lie in front of the eye). Returns the number of pixels checked.
int check_against_rays(const triangle_mesh& mesh, const camera& cam, double margin, int& covered) {
    const raster_result r = rasterize(mesh, cam);
    REQUIRE(r.ids.size() == std::size_t(cam.width()) * cam.height());
    std::vector<std::array<glm::dvec2, 3>> screen;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        const auto v = mesh.triangle(t);
        screen.push_back({project(cam, v[0]), project(cam, v[1]), project(cam, v[2])});
    }
    int checked = 0, mismatches = 0;
    covered = 0;
    for (int y = 0; y < cam.height(); ++y)
        for (int x = 0; x < cam.width(); ++x) {
            const glm::dvec2 centre(x + 0.5, y + 0.5);
            double edge = inf;
            for (const auto& s : screen)
                for (int k = 0; k < 3; ++k) edge = std::min(edge, distance_to_segment(centre, s[k], s[(k + 1) % 3]));
            if (edge < margin) continue;
            // Closest hit by brute force.
            const ray pr = cam.pixel_ray(x, y);
            double best = inf;
            std::uint32_t want = invalid_id;
            for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
                const double d = moeller_trumbore(pr, mesh.triangle(t));
                if (d > 0.0 && d < best) best = d, want = std::uint32_t(t);
            }
            const std::uint32_t got = r.ids[std::size_t(y) * cam.width() + x];
            ++checked;
            covered += want != invalid_id ? 1 : 0;
            if (got != want) {
                ++mismatches;
                if (mismatches <= 5) FAIL_CHECK("pixel (" << x << ", " << y << "): raster " << got << ", ray " << want);
            }
            if (want != invalid_id) CHECK(r.depth[std::size_t(y) * cam.width() + x] == Approx(best).epsilon(1e-3));
        }
    CHECK(mismatches == 0);
    return checked;
}

}  // namespace

TEST_CASE("display: one big triangle facing the camera", "[common][display]") {
    const camera cam(camera_desc{vec3(0.0f, 0.0f, 5.0f), vec3(0.0f), vec3(0.0f, 1.0f, 0.0f), 45.0f}, 64, 48);
    const triangle_mesh mesh = one_triangle(vec3(-1.5f, -1.0f, 0.0f), vec3(1.5f, -1.0f, 0.0f), vec3(0.0f, 1.2f, 0.0f));
    const raster_result r = rasterize(mesh, cam);
    REQUIRE(r.width == 64);
    REQUIRE(r.height == 48);
    REQUIRE(r.ids.size() == 64u * 48u);
    REQUIRE(r.depth.size() == 64u * 48u);
    REQUIRE(r.colour.width == 64);

    // The centre pixel names the triangle, at the analytic distance to the plane z = 0.
    const std::size_t centre = 24u * 64u + 32u;
    CHECK(r.ids[centre] == 0u);
    const ray pr = cam.pixel_ray(32, 24);
    const double analytic = -double(pr.org.z) / double(pr.dir.z);
    CHECK(r.depth[centre] == Approx(analytic).epsilon(1e-3));
    CHECK(r.colour.at(32, 24).r > 0.5f);  // faces the camera: bright

    // The corners are empty.
    for (auto [x, y] : {std::pair{0, 0}, std::pair{63, 0}, std::pair{0, 47}, std::pair{63, 47}}) {
        CHECK(r.ids[std::size_t(y) * 64 + x] == invalid_id);
        CHECK(r.depth[std::size_t(y) * 64 + x] == inf);
    }
}

TEST_CASE("display: row 0 is at the top, column 0 at the left", "[common][display]") {
    const camera cam(camera_desc{}, 40, 40);
    // A triangle in the upper left quadrant of the view only.
    const raster_result r = rasterize(one_triangle(vec3(-1.5f, 0.2f, 0.0f), vec3(-0.2f, 0.2f, 0.0f), vec3(-1.0f, 1.5f, 0.0f)), cam);
    int upper_left = 0, elsewhere = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x)
            if (r.ids[std::size_t(y) * 40 + x] == 0u) (y < 20 && x < 20 ? upper_left : elsewhere)++;
    CHECK(upper_left > 20);
    CHECK(elsewhere == 0);
}

TEST_CASE("display: id buffer equals ray casting through the camera's pixel centres", "[common][display]") {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    // Random triangles in separate depth slabs (no interpenetration, so the visible one is unambiguous).
    triangle_mesh mesh;
    for (int t = 0; t < 12; ++t) {
        const float z = -1.0f + 0.15f * float(t);
        const vec3 c(0.7f * u(rng), 0.7f * u(rng), z);
        for (int k = 0; k < 3; ++k) mesh.positions.push_back(c + vec3(1.6f * u(rng), 1.6f * u(rng), 0.05f * u(rng)));
        mesh.indices.push_back(uvec3(3 * t, 3 * t + 1, 3 * t + 2));
    }
    // Non-square images, odd sizes, a tilted up vector and an off-centre view.
    const camera_desc views[] = {
        {vec3(0.0f, 0.0f, 5.0f), vec3(0.0f), vec3(0.0f, 1.0f, 0.0f), 45.0f},
        {vec3(1.3f, -0.7f, 4.1f), vec3(0.2f, 0.1f, -0.3f), vec3(0.3f, 1.0f, 0.1f), 38.0f},
        {vec3(-1.2f, 0.9f, 2.4f), vec3(0.0f, 0.0f, -0.5f), vec3(0.0f, 1.0f, 0.0f), 50.0f},
    };
    const std::pair<int, int> sizes[] = {{160, 120}, {97, 131}, {200, 77}};
    for (int v = 0; v < 3; ++v) {
        const camera cam(views[v], sizes[v].first, sizes[v].second);
        int covered = 0;
        const int checked = check_against_rays(mesh, cam, 0.01, covered);
        INFO("view " << v);
        CHECK(checked > sizes[v].first * sizes[v].second * 8 / 10);
        CHECK(covered > checked / 10);
    }
}

TEST_CASE("display: ids above 255 survive the colour encoding", "[common][display]") {
    // A 20 x 20 grid of quads (800 triangles, ids using two bytes) facing the camera, slightly tilted.
    triangle_mesh mesh;
    const int n = 20;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const float x = -1.5f + 3.0f * float(i) / n, y = -1.5f + 3.0f * float(j) / n;
            mesh.positions.push_back(vec3(x, y, 0.1f * x));
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const unsigned a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            mesh.indices.push_back(uvec3(a, b, d));
            mesh.indices.push_back(uvec3(a, d, c));
        }
    const camera cam(camera_desc{}, 150, 150);
    int covered = 0;
    check_against_rays(mesh, cam, 0.01, covered);
    const raster_result r = rasterize(mesh, cam);
    std::vector<bool> seen(mesh.triangle_count(), false);
    for (std::uint32_t id : r.ids)
        if (id != invalid_id) seen.at(id) = true;
    CHECK(std::count(seen.begin(), seen.end(), true) == int(mesh.triangle_count()));
}

TEST_CASE("display: a triangle reaching behind the eye is clipped, not wrapped around", "[common][display]") {
    const camera cam(camera_desc{}, 64, 64);
    // A floor under the eye that runs from far in front to far behind it.
    triangle_mesh mesh = one_triangle(vec3(-20.0f, -1.0f, -30.0f), vec3(20.0f, -1.0f, -30.0f), vec3(0.0f, -1.0f, 40.0f));
    const raster_result r = rasterize(mesh, cam);
    int floor_rows = 0;
    for (int y = 0; y < 64; ++y) {
        const std::uint32_t id = r.ids[std::size_t(y) * 64 + 32];
        const ray pr = cam.pixel_ray(32, y);
        std::uint32_t want = invalid_id;
        if (pr.dir.y < 0.0f) {  // downward rays meet the floor plane y = -1; the triangle ends at z = -30
            const float hit_z = pr.org.z + (-1.0f - pr.org.y) / pr.dir.y * pr.dir.z;
            if (std::abs(hit_z + 30.0f) < 1.0f) continue;  // near the far edge
            want = hit_z > -30.0f ? 0u : invalid_id;
            // The depth, with znear pushed out to the floor's distance, is good to 1e-4 even near the horizon.
            if (want == 0u && id == 0u)
                CHECK(r.depth[std::size_t(y) * 64 + 32] == Approx((-1.0 - pr.org.y) / pr.dir.y).epsilon(1e-4));
        }
        CHECK(id == want);
        floor_rows += id == 0u ? 1 : 0;
    }
    CHECK(floor_rows > 20);
    // The bottom row (the ray steepest downwards) hits the floor close in front of the eye.
    const ray pr = cam.pixel_ray(32, 63);
    CHECK(r.depth[63u * 64u + 32u] == Approx((-1.0 - pr.org.y) / pr.dir.y).epsilon(1e-3));
}

TEST_CASE("display: an empty mesh and a mesh behind the eye give no ids", "[common][display]") {
    const camera cam(camera_desc{}, 16, 8);
    for (const triangle_mesh& mesh : {triangle_mesh{}, one_triangle(vec3(-1, -1, 9), vec3(1, -1, 9), vec3(0, 1, 9))}) {
        const raster_result r = rasterize(mesh, cam);
        REQUIRE(r.ids.size() == 128u);
        CHECK(std::all_of(r.ids.begin(), r.ids.end(), [](std::uint32_t id) { return id == invalid_id; }));
        CHECK(std::all_of(r.depth.begin(), r.depth.end(), [](float d) { return d == inf; }));
    }
    triangle_mesh bad = one_triangle(vec3(0), vec3(1, 0, 0), vec3(0, 1, 0));
    bad.indices[0].z = 7;
    CHECK_THROWS_AS(rasterize(bad, cam), std::runtime_error);
}

TEST_CASE("display: draw_lines colours pixels along a segment and leaves the rest", "[common][display]") {
    const camera cam(camera_desc{}, 64, 64);
    image img(64, 64, color(0.25f));
    const color hdr_red(4.0f, 0.0f, 0.0f);  // linear and above one: kept exactly
    draw_lines(img, cam, {line_segment{vec3(-1.0f, 0.5f, 0.0f), vec3(1.0f, 0.5f, 0.0f), hdr_red}}, 1.0f);
    // The segment's image row, from the camera's projection.
    const double row = (1.0 - 0.5 / (5.0 * cam.tan_half_fov())) * 32.0;
    int on_line = 0;
    for (int x = 0; x < 64; ++x) {
        const ray pr = cam.pixel_ray(x, int(row));
        if (std::abs(pr.dir.x / -pr.dir.z * 5.0f) < 0.9f) on_line += img.at(x, int(row)) == hdr_red ? 1 : 0;
    }
    CHECK(on_line > 10);
    CHECK(img.at(0, 0) == color(0.25f));
    CHECK(img.at(63, 63) == color(0.25f));
    CHECK(img.at(32, 50) == color(0.25f));
    int changed = 0;
    for (const color& c : img.pixels) changed += c != color(0.25f) ? 1 : 0;
    CHECK(changed < 64 * 3);

    // Wider lines cover more pixels.
    image wide(64, 64, color(0.25f));
    draw_lines(wide, cam, {line_segment{vec3(-1.0f, 0.5f, 0.0f), vec3(1.0f, 0.5f, 0.0f), hdr_red}}, 5.0f);
    int wide_changed = 0;
    for (const color& c : wide.pixels) wide_changed += c != color(0.25f) ? 1 : 0;
    CHECK(wide_changed > 3 * changed);

    image wrong(10, 10);
    CHECK_THROWS_AS(draw_lines(wrong, cam, {}), std::invalid_argument);
}

TEST_CASE("display: box_wireframe has the 12 edges of the box", "[common][display]") {
    const aabb box{vec3(-1.0f, 0.0f, 2.0f), vec3(3.0f, 0.5f, 4.0f)};
    const std::vector<line_segment> edges = box_wireframe(box, color(0.0f, 1.0f, 0.0f));
    REQUIRE(edges.size() == 12);
    int per_axis[3] = {0, 0, 0};
    for (const line_segment& e : edges) {
        CHECK(box.contains(e.a));
        CHECK(box.contains(e.b));
        CHECK(e.c == color(0.0f, 1.0f, 0.0f));
        const vec3 d = glm::abs(e.b - e.a);
        const int axis = max_axis(d);
        CHECK(d[axis] == box.extent()[axis]);
        CHECK(d[(axis + 1) % 3] == 0.0f);
        CHECK(d[(axis + 2) % 3] == 0.0f);
        ++per_axis[axis];
    }
    CHECK(per_axis[0] == 4);
    CHECK(per_axis[1] == 4);
    CHECK(per_axis[2] == 4);
    CHECK(box_wireframe(aabb::empty(), color(1.0f)).empty());
}

TEST_CASE("display: threads rasterise at the same time, each with its own context", "[common][display]") {
    const triangle_mesh mesh = one_triangle(vec3(-1.5f, -1.0f, 0.0f), vec3(1.5f, -1.0f, 0.0f), vec3(0.0f, 1.2f, 0.0f));
    const raster_result want = rasterize(mesh, camera(camera_desc{}, 48, 40));
    std::vector<raster_result> got(4);
    std::vector<std::thread> threads;
    for (int k = 0; k < 4; ++k)
        threads.emplace_back([&, k] {
            for (int rep = 0; rep < 3; ++rep) got[k] = rasterize(mesh, camera(camera_desc{}, 48, 40));
        });
    for (std::thread& t : threads) t.join();
    for (const raster_result& r : got) {
        CHECK(r.ids == want.ids);
        CHECK(r.depth == want.depth);
    }
}
