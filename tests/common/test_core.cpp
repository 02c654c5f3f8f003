// Unit tests of common/'s core: boxes, camera, random numbers, sampling, counters, timing, progress bar,
// parallel tiles, the command line, the output rule and STRAHL_TODO.
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

TEST_CASE("cli: options, flags, defaults, --help and clear errors", "[common][cli]") {
    auto make = [] {
        cli c("prog", "Does things.");
        c.option("width", "W", "640", "image width").option("scale", "S", "1.5", "scale").flag("quick", "be quick");
        return c;
    };
    {
        cli c = make();
        const char* argv[] = {"prog", "--width", "320", "--scale=2.25", "--quick"};
        REQUIRE(c.parse(5, argv));
        CHECK(c.get_int("width") == 320);
        CHECK(c.get_double("scale") == 2.25);
        CHECK(c.has("quick"));
        CHECK(c.has("width"));
    }
    {
        cli c = make();
        const char* argv[] = {"prog"};
        REQUIRE(c.parse(1, argv));
        CHECK(c.get_int("width") == 640);
        CHECK_FALSE(c.has("quick"));
        CHECK_FALSE(c.has("width"));
        CHECK_THAT(c.usage(), Contains("--width W") && Contains("(default: 640)") && Contains("--help"));
    }
    {
        cli c = make();
        const char* argv[] = {"prog", "--help"};
        CHECK_FALSE(c.parse(2, argv));
    }
    auto fails = [&](std::vector<const char*> args, const std::string& what) {
        cli c = make();
        args.insert(args.begin(), "prog");
        CHECK_THROWS_WITH(c.parse(int(args.size()), args.data()) && (c.get_int("width"), c.get_double("scale"), true),
                          Contains(what));
    };
    fails({"--nope"}, "unknown option --nope");
    fails({"--width"}, "needs a value");
    fails({"--width", "12x"}, "expects an integer");
    fails({"--width", "99999999999"}, "expects an integer");
    fails({"--width", "99999999999"}, "out of range");
    fails({"--scale", "nan"}, "expects a finite number");
    fails({"--scale", "1e999"}, "out of range");
    fails({"--scale", "1e-999"}, "out of range");
    {
        // A subnormal is a number like any other.
        cli c = make();
        const char* argv[] = {"prog", "--scale", "4e-320"};
        REQUIRE(c.parse(3, argv));
        CHECK(c.get_double("scale") == 4e-320);
    }
    fails({"--quick=1"}, "takes no value");
    fails({"stray"}, "unexpected argument");
}

TEST_CASE("cli: the shared options (--out with --force, --threads, --scene) and the scene names", "[common][cli]") {
    const auto make = [] {
        cli c("prog", "Does things.");
        c.scene_option({"stadium", "bunny", "teapot"}, {"stadium", "bunny"}, "the meshes where present")
            .threads_option("0", "worker threads")
            .output_options("write x.csv into DIR/");
        return c;
    };
    const auto names = [&](std::vector<const char*> args) {
        cli c = make();
        args.insert(args.begin(), "prog");
        REQUIRE(c.parse(int(args.size()), args.data()));
        return read_scene_names(c, {"stadium", "bunny", "teapot"}, {"stadium", "bunny"});
    };
    CHECK(names({}) == std::vector<std::string>{"stadium", "bunny"});
    CHECK(names({"--scene", "teapot"}) == std::vector<std::string>{"teapot"});
    CHECK_THROWS_WITH(names({"--scene", "sponza"}), Contains("--scene must be stadium, bunny, teapot or all, not 'sponza'"));
    cli c = make();
    CHECK_THAT(c.usage(), Contains("--scene NAME") && Contains("stadium, bunny, teapot or all (all: stadium, bunny; the "
                                                               "meshes where present)") &&
                              Contains("--out DIR") && Contains("--force") && Contains("--threads N"));
    const char* argv[] = {"prog", "--out", "somewhere", "--force", "--threads", "3"};
    REQUIRE(c.parse(6, argv));
    CHECK(c.get("out") == "somewhere");
    CHECK(c.has("force"));
    CHECK(c.get_int("threads") == 3);
    CHECK(course_scene("stadium")->name == "teapot_stadium");
    CHECK(course_scene("teapot")->mesh.triangle_count() > 0);
}

static int throws_usage(int, const char* const*) { throw usage_error("bad flag"); }
static int throws_todo(int, const char* const*) { STRAHL_TODO("01.2 ray/sphere"); }
static int throws_other(int, const char* const*) { throw std::runtime_error("disk full"); }
static int returns_zero(int, const char* const*) { return 0; }

TEST_CASE("STRAHL_TODO names the exercise, file and line, guarded_main maps errors to exit codes", "[common][todo]") {
    try {
        STRAHL_TODO("05.2 bin the centroids");
    } catch (const not_implemented& e) {
        CHECK(e.id() == "05.2 bin the centroids");
        CHECK_THAT(e.what(), Contains("exercise 05.2 (bin the centroids) is not done yet: tests/common/test_core.cpp:"));
        CHECK(e.line() > 0);
    }
    const char* argv[] = {"prog"};
    CHECK(guarded_main("prog", throws_usage, 1, argv) == 2);
    CHECK(guarded_main("prog", throws_todo, 1, argv) == 3);
    CHECK(guarded_main("prog", throws_other, 1, argv) == 1);
    CHECK(guarded_main("prog", returns_zero, 1, argv) == 0);
}

TEST_CASE("read_threads: --threads within [lo, 1024], a clear error beyond", "[common][cli]") {
    const auto threads = [](const char* value, int lo) {
        cli c("prog", "Does things.");
        c.option("threads", "N", "0", "threads");
        const char* argv[] = {"prog", "--threads", value};
        REQUIRE(c.parse(3, argv));
        return read_threads(c, lo);
    };
    CHECK(threads("0", 0) == 0);
    CHECK(threads("1024", 1) == 1024);
    CHECK_THROWS_WITH(threads("2147483647", 1), Contains("--threads must lie in [1, 1024], not 2147483647") &&
                                                    Contains("hardware threads"));
    CHECK_THROWS_WITH(threads("1025", 0), Contains("[0, 1024] (0: one per core)"));
    CHECK_THROWS_WITH(threads("0", 1), Contains("[1, 1024]"));
    CHECK_THROWS_AS(threads("-1", 0), usage_error);
}

TEST_CASE("check_memory: work needing more memory than there is is refused, saying how much", "[common][memory]") {
    CHECK(available_memory() > 0);
    CHECK_NOTHROW(check_memory(1 << 20, "a small image"));
    setenv("STRAHL_MEMORY_LIMIT_MB", "512", 1);
    CHECK(available_memory() <= (std::uint64_t(512) << 20));
    CHECK_NOTHROW(check_memory(std::uint64_t(100) << 20, "a small image"));
    CHECK_THROWS_WITH(check_memory(std::uint64_t(17) << 30, "a 16384 x 16384 image"),
                      Contains("a 16384 x 16384 image: about 17.0 GiB of memory needed, but only 512 MiB available"));
    setenv("STRAHL_MEMORY_LIMIT_MB", "lots", 1);
    CHECK_THROWS_WITH(available_memory(), Contains("STRAHL_MEMORY_LIMIT_MB") && Contains("'lots'"));
    unsetenv("STRAHL_MEMORY_LIMIT_MB");
}

TEST_CASE("prepare_output: creates folders, never overwrites a user's file unasked", "[common][output]") {
    const auto dir = test::scratch_dir("prepare_output");
    const auto nested = dir / "a" / "b" / "image.png";
    REQUIRE_NOTHROW(prepare_output(nested, true, false));
    CHECK(std::filesystem::is_directory(nested.parent_path()));

    std::ofstream(dir / "mine.png") << "precious";
    CHECK_THROWS_WITH(prepare_output(dir / "mine.png", true, false), Contains("not overwriting") && Contains("--force"));
    CHECK_NOTHROW(prepare_output(dir / "mine.png", true, true));
    CHECK_NOTHROW(prepare_output(dir / "mine.png", false, false));  // the course's own output: regenerated
    CHECK_THROWS_WITH(prepare_output(dir, true, true), Contains("is a folder"));
    std::ofstream(dir / "file") << "x";
    CHECK_THROWS_WITH(prepare_output(dir / "file" / "x.png", false, false), Contains("cannot create folder"));
    if (geteuid() != 0) {  // root may write anywhere
        std::filesystem::create_directories(dir / "locked");
        chmod((dir / "locked").c_str(), 0500);
        CHECK_THROWS_WITH(prepare_output(dir / "locked" / "x.png", false, false), Contains("permission denied"));
        chmod((dir / "locked").c_str(), 0700);
        // A read-only file is found before the work, --force or not.
        std::ofstream(dir / "read_only.png") << "x";
        chmod((dir / "read_only.png").c_str(), 0400);
        CHECK_THROWS_WITH(prepare_output(dir / "read_only.png", true, true),
                          Contains("cannot replace") && Contains("read-only"));
        CHECK_THROWS_WITH(prepare_output(dir / "read_only.png", false, false), Contains("cannot replace"));
    }
    // A symbolic link to nothing: not written through (its target would be created wherever it points).
    std::filesystem::create_symlink(dir / "nowhere" / "target.png", dir / "dangling.png");
    CHECK_THROWS_WITH(prepare_output(dir / "dangling.png", true, true),
                      Contains("is a symbolic link to") && Contains("which does not exist"));
    CHECK_FALSE(std::filesystem::exists(dir / "nowhere"));
    // A link to an existing file is that file: replaced with --force, as the user asked.
    std::filesystem::create_symlink(dir / "mine.png", dir / "link.png");
    CHECK_THROWS_WITH(prepare_output(dir / "link.png", true, false), Contains("not overwriting"));
    CHECK_NOTHROW(prepare_output(dir / "link.png", true, true));
}

TEST_CASE("read_csv and csv_number: a program's own table back, anything else refused with file and line",
          "[common][csv]") {
    const auto dir = test::scratch_dir("read_csv");
    const std::string header = "scene,ms,count";
    const auto file = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return dir / name;
    };
    const auto good = file("good.csv", header + "\nbunny,1.5,3\n\nsponza,0,12\n");
    const std::vector<csv_row> rows = read_csv(good, header, "a test table");
    REQUIRE(rows.size() == 2);  // the blank line skipped
    CHECK(rows[0].line == 2);
    CHECK(rows[1].line == 4);
    CHECK(rows[1].cells == std::vector<std::string>{"sponza", "0", "12"});
    CHECK(csv_number(good, rows[0], 1) == 1.5);
    CHECK(csv_number(good, rows[1], 2) == 12.0);

    CHECK_THROWS_WITH(read_csv(dir / "absent.csv", header, "a test table"), Contains("cannot read"));
    CHECK_THROWS_WITH(read_csv(file("foreign.csv", "a,b\n1,2\n"), header, "a test table"),
                      Contains("is not a test table") && Contains(header));
    CHECK_THROWS_WITH(read_csv(file("empty.csv", ""), header, "a test table"), Contains("is not a test table"));
    CHECK_THROWS_WITH(read_csv(file("rowless.csv", header + "\n"), header, "a test table"), Contains("holds no rows"));
    CHECK_THROWS_WITH(read_csv(file("short.csv", header + "\nbunny,1\n"), header, "a test table"),
                      Contains("line 2") && Contains("3 fields expected, not 2"));
    CHECK_THROWS_WITH(read_csv(file("trailing.csv", header + "\nbunny,1,2,\n"), header, "a test table"),
                      Contains("not 4"));

    // Quoted fields (RFC 4180): commas, doubled quotes and line breaks inside them come back whole.
    const std::vector<std::string> names = {"plain", "a,b", "say \"hi\"", "two\nlines", "", ",\""};
    std::string quoted = header + "\n";
    for (const std::string& n : names) quoted += csv_field(n) + ",1," + csv_field(n) + "\n";
    CHECK(csv_field("plain") == "plain");
    CHECK(csv_field("a,b") == "\"a,b\"");
    CHECK(csv_field("say \"hi\"") == "\"say \"\"hi\"\"\"");
    const std::vector<csv_row> q = read_csv(file("quoted.csv", quoted), header, "a test table");
    REQUIRE(q.size() == names.size());
    for (std::size_t i = 0; i < names.size(); ++i) CHECK(q[i].cells == std::vector<std::string>{names[i], "1", names[i]});
    CHECK(q[4].line == 8);  // the row after the one that ran over lines 5 to 7
    CHECK_THROWS_WITH(read_csv(file("open.csv", header + "\n\"bunny,1,2\n"), header, "a test table"),
                      Contains("line 2") && Contains("not closed"));
    CHECK_THROWS_WITH(read_csv(file("after.csv", header + "\n\"bunny\"x,1,2\n"), header, "a test table"),
                      Contains("line 2") && Contains("follows its closing quote"));

    const auto bad = file("bad.csv", header + "\nx,nan,3\nx,-1,3\nx,1.5ms,3\nx,,3\nx,inf,1e400\n");
    const std::vector<csv_row> b = read_csv(bad, header, "a test table");
    REQUIRE(b.size() == 5);
    for (const csv_row& r : b) CHECK_THROWS_WITH(csv_number(bad, r, 1), Contains("line " + std::to_string(r.line)) &&
                                                                            Contains("is not a number >= 0"));
    CHECK_THROWS_WITH(csv_number(bad, b[4], 2), Contains("'1e400'") && Contains("is out of range"));

    // A subnormal is a number; a number beyond double's range in either direction is out of range.
    const auto tiny = file("tiny.csv", header + "\nx,4e-320,1e-400\n");
    const std::vector<csv_row> t = read_csv(tiny, header, "a test table");
    CHECK(csv_number(tiny, t[0], 1) == 4e-320);
    CHECK_THROWS_WITH(csv_number(tiny, t[0], 2), Contains("'1e-400' is out of range"));
}
