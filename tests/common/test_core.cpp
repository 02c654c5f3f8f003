// Unit tests of common/'s core: boxes, camera, random numbers, sampling, counters, timing, progress bar and
// parallel tiles (the command line, the output rule, STRAHL_TODO and CSV reading: test_program.cpp).
#include <sched.h>
#include <catch2/catch.hpp>
#include "strahl/aabb.hpp"
#include "strahl/camera.hpp"
#include "strahl/parallel.hpp"
#include "strahl/procedural.hpp"
#include "strahl/program.hpp"
#include "strahl/progress.hpp"
#include "strahl/rng.hpp"
#include "strahl/sampling.hpp"
#include "strahl/stats.hpp"
#include "strahl/timer.hpp"
#include "strahl/todo.hpp"
#include "test_support.hpp"
#include <atomic>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sys/stat.h>
#include <unistd.h>

using namespace strahl;
using Catch::Matchers::Contains;

TEST_CASE("aabb: empty box, growing, union, area, extent, centroid", "[common][aabb]") {
    aabb b;
    CHECK(b.is_empty());
    CHECK(b.surface_area() == 0.0f);
    CHECK(b.extent() == vec3(0.0f));
    CHECK(unite(b, aabb{}).is_empty());

    b.grow(vec3(1, 2, 3));
    CHECK_FALSE(b.is_empty());
    CHECK(b.min == vec3(1, 2, 3));
    CHECK(b.max == vec3(1, 2, 3));
    CHECK(b.surface_area() == 0.0f);  // a point

    b.grow(vec3(3, 5, 7));
    CHECK(b.extent() == vec3(2, 3, 4));
    CHECK(b.centroid() == vec3(2, 3.5f, 5));
    CHECK(b.surface_area() == 2.0f * (2 * 3 + 3 * 4 + 4 * 2));
    CHECK(b.largest_axis() == 2);
    CHECK(b.contains(vec3(2, 3, 4)));
    CHECK_FALSE(b.contains(vec3(0, 3, 4)));

    const aabb c = aabb::from_points(vec3(10, -1, 0), vec3(9, 0, 1));
    const aabb u = unite(b, c);
    CHECK(u.min == vec3(1, -1, 0));
    CHECK(u.max == vec3(10, 5, 7));
    CHECK(unite(aabb{}, c).min == c.min);  // the empty box is the identity of union
    CHECK(unite(c, aabb{}).max == c.max);

    const aabb flat = aabb::from_points(vec3(0, 0, 0), vec3(2, 3, 0));  // zero thickness on z
    CHECK(flat.surface_area() == 12.0f);
    CHECK_FALSE(flat.is_empty());
}

TEST_CASE("camera: the centre ray looks at the target, row 0 is the top, rays are normalised", "[common][camera]") {
    camera_desc d;
    d.eye = vec3(1, 2, 10);
    d.target = vec3(1, 2, 0);
    d.vfov_degrees = 60.0f;
    const camera cam(d, 200, 100);
    CHECK(cam.aspect() == 2.0f);

    const ray centre = cam.generate(100.0f, 50.0f);
    CHECK(centre.org == d.eye);
    CHECK(centre.dir.x == Approx(0.0f).margin(1e-6));
    CHECK(centre.dir.y == Approx(0.0f).margin(1e-6));
    CHECK(centre.dir.z == Approx(-1.0f));
    CHECK(centre.tmin == 0.0f);
    CHECK(centre.tmax == inf);

    // Row 0 at the top: the ray through the top edge points up by half the vertical field of view.
    const ray top = cam.generate(100.0f, 0.0f);
    CHECK(top.dir.y > 0.0f);
    CHECK(std::atan2(top.dir.y, -top.dir.z) == Approx(glm::radians(30.0f)));
    // Column 0 at the left (right vector is +x for a camera looking down -z with +y up).
    CHECK(cam.generate(0.0f, 50.0f).dir.x < 0.0f);
    CHECK(cam.right().x == Approx(1.0f));
    // Horizontal extent follows the aspect ratio.
    const ray right_edge = cam.generate(200.0f, 50.0f);
    CHECK(right_edge.dir.x / -right_edge.dir.z == Approx(2.0f * std::tan(glm::radians(30.0f))));

    for (float y : {0.0f, 13.5f, 99.9f})
        for (float x : {0.0f, 77.25f, 199.0f}) CHECK(glm::length(cam.generate(x, y).dir) == Approx(1.0f));

    // pixel_ray defaults to the pixel centre.
    const ray p = cam.pixel_ray(3, 4);
    const ray q = cam.generate(3.5f, 4.5f);
    CHECK(p.dir == q.dir);
}

TEST_CASE("camera: agrees with its OpenGL matrices at pixel centres", "[common][camera]") {
    camera_desc d;
    d.eye = vec3(-3, 4, 5);
    d.target = vec3(0.5f, 0, -1);
    d.up = vec3(0, 1, 0);
    d.vfov_degrees = 35.0f;
    const camera cam(d, 64, 48);
    const mat4 vp = cam.projection_matrix(0.1f, 100.0f) * cam.view_matrix();
    for (int py : {0, 17, 47})
        for (int px : {0, 31, 63}) {
            const ray r = cam.pixel_ray(px, py);
            const vec4 clip = vp * vec4(r.at(7.0f), 1.0f);
            const float wx = (clip.x / clip.w + 1.0f) * 0.5f * 64.0f;
            const float wy_gl = (clip.y / clip.w + 1.0f) * 0.5f * 48.0f;  // GL rows count from the bottom
            CHECK(wx == Approx(px + 0.5f).margin(1e-3));
            CHECK(48.0f - wy_gl == Approx(py + 0.5f).margin(1e-3));
        }
}

TEST_CASE("camera: bad set-ups are refused", "[common][camera]") {
    camera_desc d;
    CHECK_THROWS_AS(camera(d, 0, 10), std::invalid_argument);
    d.vfov_degrees = 180.0f;
    CHECK_THROWS_AS(camera(d, 10, 10), std::invalid_argument);
    d = camera_desc{};
    d.target = d.eye;
    CHECK_THROWS_AS(camera(d, 10, 10), std::invalid_argument);
    d = camera_desc{};
    d.up = d.target - d.eye;
    CHECK_THROWS_AS(camera(d, 10, 10), std::invalid_argument);
    d = camera_desc{};
    d.eye.x = std::nanf("");
    CHECK_THROWS_AS(camera(d, 10, 10), std::invalid_argument);
}

TEST_CASE("scene_camera: a scene whose camera cannot be made is named, with the cause", "[common][camera]") {
    // One triangle of size s at offset o from the origin, framed as load_scene frames a mesh file.
    const auto one_triangle = [](const char* name, float s, float o) {
        triangle_mesh m;
        m.positions = {vec3(o), vec3(o + s, o, o + s), vec3(o, o + s, o + s)};
        m.indices = {uvec3(0, 1, 2)};
        return mesh_scene(name, m);
    };
    CHECK(scene_camera(one_triangle("fine.obj", 1e12f, 0.0f), 8, 8).width() == 8);
    // An extent of 2e19: the framing squares it (beyond 3.4e38) and its fallback distance is lost.
    CHECK_THROWS_WITH(scene_camera(one_triangle("huge.obj", 2e19f, 0.0f), 8, 8),
                      Contains("scene 'huge.obj'") && Contains("eye equals target") &&
                          Contains("extent (2e+19 x 2e+19 x 2e+19)") && Contains("overflows float arithmetic"));
    // A size of 1e-3 at 1e9 from the origin: the camera's distance is below float's spacing there.
    CHECK_THROWS_WITH(scene_camera(one_triangle("far.obj", 1e-3f, 1e9f), 8, 8),
                      Contains("scene 'far.obj'") && Contains("too far from the origin for its size"));
}

TEST_CASE("pcg32: deterministic, seed- and stream-dependent, in range, unbiased enough", "[common][rng]") {
    pcg32 a(42, 1), b(42, 1), c(43, 1), d(42, 2);
    bool differs_seed = false, differs_stream = false;
    for (int i = 0; i < 100; ++i) {
        const auto x = a.next_u32();
        CHECK(x == b.next_u32());
        differs_seed |= x != c.next_u32();
        differs_stream |= x != d.next_u32();
    }
    CHECK(differs_seed);
    CHECK(differs_stream);

    // Reference values of the PCG32 XSH-RR generator seeded as in pcg32-demo (seed 42, stream 54).
    pcg32 demo(42, 54);
    CHECK(demo.next_u32() == 0xa15c02b7u);
    CHECK(demo.next_u32() == 0x7b47f409u);
    CHECK(demo.next_u32() == 0xba1d3330u);

    pcg32 r(7);
    double sum = 0.0;
    int buckets[10] = {};
    for (int i = 0; i < 100000; ++i) {
        const float f = r.next_float();
        REQUIRE(f >= 0.0f);
        REQUIRE(f < 1.0f);
        sum += f;
        const auto k = r.next_bounded(10);
        REQUIRE(k < 10u);
        ++buckets[k];
    }
    CHECK(sum / 100000.0 == Approx(0.5).margin(0.01));
    for (int k : buckets) CHECK(k == Approx(10000).margin(500));
}

TEST_CASE("sampling: shapes, ranges and moments", "[common][sampling]") {
    pcg32 r(3);
    double mean_cos = 0.0, mean_z_sphere = 0.0, mean_r2_disk = 0.0;
    const int n = 50000;
    for (int i = 0; i < n; ++i) {
        const vec2 u(r.next_float(), r.next_float());
        const vec2 d = sample_disk(u);
        REQUIRE(glm::dot(d, d) <= 1.0f + 1e-6f);
        mean_r2_disk += glm::dot(d, d);
        const vec3 s = sample_sphere(u);
        REQUIRE(glm::length(s) == Approx(1.0f).margin(1e-5));
        mean_z_sphere += s.z;
        const vec3 h = sample_cosine_hemisphere(u);
        REQUIRE(glm::length(h) == Approx(1.0f).margin(1e-5));
        REQUIRE(h.z >= 0.0f);
        mean_cos += h.z;
    }
    CHECK(mean_r2_disk / n == Approx(0.5).margin(0.01));    // uniform disk: E[r^2] = 1/2
    CHECK(mean_z_sphere / n == Approx(0.0).margin(0.01));   // uniform sphere: E[z] = 0
    CHECK(mean_cos / n == Approx(2.0 / 3.0).margin(0.01));  // cosine-weighted: E[cos] = 2/3
    CHECK(sample_disk(vec2(0.5f)) == vec2(0.0f));
}

TEST_CASE("sampling: frame is orthonormal and maps +z to the normal", "[common][sampling]") {
    pcg32 r(11);
    for (int i = 0; i < 1000; ++i) {
        vec3 n = sample_sphere(vec2(r.next_float(), r.next_float()));
        if (i == 0) n = vec3(0, 0, -1);  // the branch point of the construction
        if (i == 1) n = vec3(0, 0, 1);
        const frame f(n);
        CHECK(glm::dot(f.t, f.b) == Approx(0.0f).margin(1e-5));
        CHECK(glm::dot(f.t, f.n) == Approx(0.0f).margin(1e-5));
        CHECK(glm::dot(f.b, f.n) == Approx(0.0f).margin(1e-5));
        CHECK(glm::length(f.t) == Approx(1.0f).margin(1e-5));
        CHECK(glm::length(f.b) == Approx(1.0f).margin(1e-5));
        const vec3 z = f.to_world(vec3(0, 0, 1));
        CHECK(glm::distance(z, n) < 1e-5f);
        const vec3 v(0.3f, -0.2f, 0.9f);
        CHECK(glm::distance(f.to_local(f.to_world(v)), v) < 1e-5f);
    }
}

template <class Stats>
static int count_loop(Stats& s) {
    for (int i = 0; i < 10; ++i) { s.box_test(); s.prim_test(2); }
    s.ray();
    s.node_visit(5);
    return 0;
}

TEST_CASE("stats: counters count when on, hold nothing when off", "[common][stats]") {
    counting on;
    not_counting off;
    count_loop(on);
    count_loop(off);
    const counter_values v = on.values();
    CHECK(v.box_tests == 10);
    CHECK(v.prim_tests == 20);
    CHECK(v.rays == 1);
    CHECK(v.nodes_visited == 5);
    CHECK(v.per_ray(v.prim_tests) == 20.0);
    CHECK(off.values().box_tests == 0);
    STATIC_REQUIRE(std::is_empty_v<not_counting>);
    counting other;
    count_loop(other);
    on.merge(other);
    CHECK(on.values().box_tests == 20);
    CHECK(counter_values{}.per_ray(5) == 0.0);
}

TEST_CASE("timer and median", "[common][timer]") {
    CHECK(median({3.0, 1.0, 2.0}) == 2.0);
    CHECK(median({4.0, 1.0, 3.0, 2.0}) == 2.5);
    CHECK(median({5.0}) == 5.0);
    CHECK_THROWS_AS(median({}), std::invalid_argument);
    timer t;
    CHECK(t.seconds() >= 0.0);
}

TEST_CASE("progress bar: text shows percentage, rate and ETA, silent off a terminal", "[common][progress]") {
    const std::string half = progress_bar::format("render", 50, 100, 2.0, "rows", 10);
    CHECK_THAT(half, Contains("render  [#####     ]"));
    CHECK_THAT(half, Contains(" 50%"));
    CHECK_THAT(half, Contains("25.0 rows/s"));
    CHECK_THAT(half, Contains("ETA 2.0 s"));
    const std::string done = progress_bar::format("render", 100, 100, 4.0, "rows", 10);
    CHECK_THAT(done, Contains("100%"));
    CHECK_THAT(done, Contains("4.0 s"));
    CHECK_THAT(progress_bar::format("x", 5000, 10000, 1.0, "px", 4), Contains("5.0 kpx/s"));
    CHECK_THAT(progress_bar::format("x", 0, 0, 0.0, "px", 4), Contains("100%"));  // nothing to do is done

    progress_bar bar("quiet", 10);
    bar.set_drawing(false);
    parallel_for_chunks(10, 1, [&](std::size_t b, std::size_t e) { bar.add(e - b); });
    CHECK(bar.done() == 10);
    bar.finish();
    bar.finish();  // idempotent
}

TEST_CASE("parallel_for_tiles covers every pixel exactly once, with stable tile indices", "[common][parallel]") {
    const int w = 37, h = 23;
    std::vector<std::atomic<int>> hits(w * h);
    std::vector<int> tile_of(w * h, -1);
    parallel_for_tiles(w, h, 8, [&](const tile& t) {
        for (int y = t.y0; y < t.y1; ++y)
            for (int x = t.x0; x < t.x1; ++x) {
                ++hits[y * w + x];
                tile_of[y * w + x] = t.index;
            }
    });
    for (auto& c : hits) REQUIRE(c.load() == 1);
    CHECK(tile_of[0] == 0);
    CHECK(tile_of[9] == 1);                  // second tile in the first row of tiles
    CHECK(tile_of[8 * w] == 5);              // (37 + 7) / 8 = 5 tiles per row
    CHECK(tile_of[w * h - 1] == 5 * 3 - 1);  // 3 rows of tiles

    const thread_limit one(1);
    std::atomic<int> total{0};
    parallel_for_chunks(1000, 10, [&](std::size_t b, std::size_t e) { total += int(e - b); });
    CHECK(total == 1000);
}

TEST_CASE("pinned_thread keeps the thread on one CPU and gives back the CPUs it had", "[parallel]") {
    cpu_set_t before;
    REQUIRE(sched_getaffinity(0, sizeof before, &before) == 0);
    const int cpu = first_allowed_cpu();
    CHECK(cpu_allowed(cpu));
    CHECK_FALSE(cpu_allowed(-1));
    CHECK_FALSE(cpu_allowed(CPU_SETSIZE));
    {
        const pinned_thread pin(cpu);
        cpu_set_t now;
        REQUIRE(sched_getaffinity(0, sizeof now, &now) == 0);
        CHECK(CPU_COUNT(&now) == 1);
        CHECK(CPU_ISSET(cpu, &now));
        CHECK(sched_getcpu() == cpu);
    }
    cpu_set_t after;
    REQUIRE(sched_getaffinity(0, sizeof after, &after) == 0);
    CHECK(CPU_EQUAL(&before, &after));
    {
        const pinned_thread none(-1);  // changes nothing
        cpu_set_t now;
        REQUIRE(sched_getaffinity(0, sizeof now, &now) == 0);
        CHECK(CPU_EQUAL(&before, &now));
    }
    CHECK_THROWS_AS(pinned_thread(CPU_SETSIZE + 5), std::invalid_argument);
}
