// Chapter 16's shared ray sets (ray_sets.hpp): primary rays in scanline order from the scene's camera,
// diffuse rays deterministic per seed and leaving the surface on the side the ray came from, shadow rays
// ending just short of the light, and clear refusals of what cannot be made.
#include "strahl/procedural.hpp"
#include "strahl/race/brute_force.hpp"
#include "strahl/race/measure.hpp"
#include "strahl/race/ray_sets.hpp"
#include <catch2/catch.hpp>
#include <cstring>

using namespace strahl;
using namespace strahl::race;

namespace {

bool same_bits(const vec3& a, const vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_rays(const std::vector<ray>& a, const std::vector<ray>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!same_bits(a[i].org, b[i].org) || !same_bits(a[i].dir, b[i].dir) ||
            std::memcmp(&a[i].tmin, &b[i].tmin, 4) != 0 || std::memcmp(&a[i].tmax, &b[i].tmax, 4) != 0)
            return false;
    return true;
}

// The teapot's primary rays and their exact hits, small.
struct teapot_fixture {
    scene s = builtin_scene("teapot");
    int width = 40, height = 30;
    brute_force exact;
    std::vector<ray> primary;
    std::vector<hit> hits;

    teapot_fixture() {
        exact.build(s);
        primary = primary_rays(s, width, height);
        hits.resize(primary.size());
        trace_closest(exact, primary, hits, 2);
    }
    std::size_t hit_count() const {
        std::size_t n = 0;
        for (const hit& h : hits) n += h.found();
        return n;
    }
};

}  // namespace

TEST_CASE("ch16 ray sets: ray kinds parse and print, junk is refused", "[ch16][ray_sets]") {
    for (ray_kind k : {ray_kind::primary, ray_kind::diffuse, ray_kind::shadow}) CHECK(parse_ray_kind(to_string(k)) == k);
    CHECK(is_any_hit(ray_kind::shadow));
    CHECK_FALSE(is_any_hit(ray_kind::primary));
    CHECK_FALSE(is_any_hit(ray_kind::diffuse));
    for (const char* junk : {"", "Primary", "primary ", "shadows", "ambient", "0"}) {
        INFO("'" << junk << "'");
        CHECK_THROWS_AS(parse_ray_kind(junk), std::invalid_argument);
    }
    CHECK_THROWS_WITH(parse_ray_kind("ambient"), Catch::Contains("ambient") && Catch::Contains("primary, diffuse, shadow"));
}

TEST_CASE("ch16 ray sets: primary rays are the camera's pixel rays in scanline order, row 0 at the top",
          "[ch16][ray_sets]") {
    const scene s = builtin_scene("teapot");
    const int w = 7, h = 5;
    const std::vector<ray> rays = primary_rays(s, w, h);
    REQUIRE(rays.size() == std::size_t(w * h));
    const camera cam(s.camera, w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            INFO("pixel " << x << ", " << y);
            const ray expect = cam.pixel_ray(x, y);
            const ray& got = rays[std::size_t(y) * w + x];
            CHECK(same_bits(got.org, expect.org));
            CHECK(same_bits(got.dir, expect.dir));
            CHECK(got.tmin == expect.tmin);
            CHECK(got.tmax == expect.tmax);
        }
    // Row 0 looks up, the last row down; column 0 looks left.
    CHECK(glm::dot(rays.front().dir, cam.up()) > 0.0f);
    CHECK(glm::dot(rays.back().dir, cam.up()) < 0.0f);
    CHECK(glm::dot(rays.front().dir, cam.right()) < 0.0f);
    CHECK(glm::dot(rays[w - 1].dir, cam.right()) > 0.0f);
}

TEST_CASE("ch16 ray sets: diffuse rays, one per primary hit, deterministic per seed, on the ray's side",
          "[ch16][ray_sets]") {
    const teapot_fixture f;
    const std::size_t n = f.hit_count();
    REQUIRE(n > f.primary.size() / 10);  // the teapot fills part of the image...
    REQUIRE(n < f.primary.size());       // ...but not all of it
    const std::vector<ray> a = secondary_rays(ray_kind::diffuse, f.s, f.primary, f.hits, 7);
    const std::vector<ray> b = secondary_rays(ray_kind::diffuse, f.s, f.primary, f.hits, 7);
    const std::vector<ray> c = secondary_rays(ray_kind::diffuse, f.s, f.primary, f.hits, 8);
    REQUIRE(a.size() == n);
    CHECK(same_rays(a, b));
    REQUIRE(c.size() == n);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < n; ++i) differ += !same_bits(a[i].dir, c[i].dir);
    CHECK(differ > n * 9 / 10);
    // make_rays gives the same set.
    CHECK(same_rays(make_rays(ray_kind::diffuse, f.s, f.width, f.height, 7, f.exact, 1), a));

    // Ray k belongs to the k-th primary hit: it starts near that hit and points into the hemisphere of the
    // geometric normal turned towards the incoming ray.
    std::size_t k = 0;
    for (std::size_t i = 0; i < f.primary.size(); ++i) {
        const hit& h = f.hits[i];
        if (!h.found()) continue;
        INFO("pixel " << i << ", diffuse ray " << k);
        const ray& r = a[k++];
        const auto tri = f.s.mesh.triangle(h.prim);
        vec3 normal = glm::cross(tri[1] - tri[0], tri[2] - tri[0]);
        if (glm::length(normal) == 0.0f) continue;  // a degenerate pole triangle: no normal to check against
        normal = glm::normalize(normal);
        if (glm::dot(normal, f.primary[i].dir) > 0.0f) normal = -normal;
        CHECK(glm::dot(r.dir, normal) >= 0.0f);
        CHECK(glm::length(r.org - f.primary[i].at(h.t)) < 1e-2f);
        CHECK(glm::dot(r.org - f.primary[i].at(h.t), normal) > 0.0f);  // lifted off the surface, ray side
        CHECK(glm::length(r.dir) == Approx(1.0f).epsilon(1e-4));
        CHECK(r.tmax == inf);
    }
    CHECK(k == n);
}

TEST_CASE("ch16 ray sets: shadow rays end just short of the light", "[ch16][ray_sets]") {
    const teapot_fixture f;
    REQUIRE_FALSE(f.s.lights.empty());
    const vec3 light = f.s.lights.front().position;
    const std::vector<ray> rays = secondary_rays(ray_kind::shadow, f.s, f.primary, f.hits, 1);
    REQUIRE(rays.size() == f.hit_count());
    CHECK(same_rays(make_rays(ray_kind::shadow, f.s, f.width, f.height, 1, f.exact, 2), rays));
    std::size_t k = 0;
    for (std::size_t i = 0; i < f.primary.size(); ++i) {
        if (!f.hits[i].found()) continue;
        INFO("pixel " << i << ", shadow ray " << k);
        const ray& r = rays[k++];
        const vec3 end = r.at(r.tmax);
        const float to_light = glm::length(r.dir);  // the direction reaches the light at t = 1
        CHECK(glm::length(end - light) > 0.0f);
        CHECK(glm::length(end - light) < 1e-3f * to_light);
        CHECK(glm::dot(light - end, r.dir) > 0.0f);  // short of the light, not past it
        CHECK(glm::length(r.org - f.primary[i].at(f.hits[i].t)) < 1e-2f);
        CHECK(r.tmin >= 0.0f);
        CHECK(r.tmax < 1.0f);
    }
}

TEST_CASE("ch16 ray sets: what cannot be made is refused", "[ch16][ray_sets]") {
    teapot_fixture f;
    scene dark = f.s;
    dark.lights.clear();
    CHECK_THROWS_AS(secondary_rays(ray_kind::shadow, dark, f.primary, f.hits), std::invalid_argument);
    CHECK_THROWS_WITH(secondary_rays(ray_kind::shadow, dark, f.primary, f.hits), Catch::Contains("light"));
    CHECK_THROWS_AS(make_rays(ray_kind::shadow, dark, 8, 6, 1, f.exact), std::invalid_argument);
    CHECK_NOTHROW(secondary_rays(ray_kind::diffuse, dark, f.primary, f.hits));  // diffuse rays need no light
    CHECK_THROWS_AS(secondary_rays(ray_kind::primary, f.s, f.primary, f.hits), std::invalid_argument);
    f.hits.pop_back();
    CHECK_THROWS_AS(secondary_rays(ray_kind::diffuse, f.s, f.primary, f.hits), std::invalid_argument);
}

TEST_CASE("ch16 ray sets: tracing on several threads gives the same hits as on one", "[ch16][ray_sets]") {
    const teapot_fixture f;  // traced on 2 threads
    std::vector<hit> one(f.primary.size());
    trace_closest(f.exact, f.primary, one, 1);
    for (std::size_t i = 0; i < one.size(); ++i) {
        INFO("ray " << i);
        REQUIRE(agrees(one[i], f.hits[i], true));
    }
    const std::vector<ray> shadow = secondary_rays(ray_kind::shadow, f.s, f.primary, f.hits);
    std::vector<std::uint8_t> b1(shadow.size()), b3(shadow.size());
    trace_any(f.exact, shadow, b1, 1);
    trace_any(f.exact, shadow, b3, 3);
    CHECK(b1 == b3);
}

TEST_CASE("ch16 ray sets: the threads' chunks keep whole rows of tiles, and share a small set evenly",
          "[ch16][ray_sets]") {
    using ch01::thread_chunk;
    // A large set: about 1,024 rays per chunk, whole rows of tiles (768 = 4 rows of 192).
    CHECK(thread_chunk(1'000'000, 768, 2) == 1536);
    CHECK(thread_chunk(1'000'000, 1, 2) == 1024);
    CHECK(thread_chunk(1'000'000, 4096, 4) == 4096);
    // The bunny's 3,926 diffuse rays against rows of 768 on two threads: with chunks of whole rows one
    // thread traced 2,390 of them (a bound of 1.64x); now no thread takes more than half and a chunk.
    for (const int threads : {2, 3, 4, 16}) {
        for (const std::size_t n : {std::size_t(1), std::size_t(31), std::size_t(3926), std::size_t(27150),
                                    std::size_t(100'000)}) {
            for (const std::size_t align : {std::size_t(1), std::size_t(768), std::size_t(4096)}) {
                INFO(n << " rays, alignment " << align << ", " << threads << " threads");
                const std::size_t c = thread_chunk(n, align, threads);
                REQUIRE(c > 0);
                CHECK(c <= (std::max<std::size_t>(1024, align) + align - 1) / align * align);
                // Whole rows of tiles, or (a small set) at most an eighth of a thread's share, in steps of 32.
                CHECK((c % align == 0 || c % 32 == 0));
                if (c % align != 0) CHECK(c <= std::max<std::size_t>(32, (n + 8 * threads - 1) / (8 * threads)) + 31);
            }
        }
    }
    const std::size_t c = thread_chunk(3926, 768, 2);
    const std::size_t chunks = (3926 + c - 1) / c;
    CHECK(chunks >= 12);
    CHECK((chunks + 1) / 2 * c <= 3926 / 2 + c);
}
