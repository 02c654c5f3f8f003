// Chapter 11 beyond the exercises (0 points): every step exact against brute force, on triangles alone and
// with spheres and planes; the renderers' images equal chapter 01's brute-force render bit for bit; what
// each step keeps in memory.
#include "strahl/ch01/render.hpp"
#include "strahl/ch11/steps.hpp"
#include "strahl/parallel.hpp"
#include "strahl/procedural.hpp"
#include "bvh_rays.hpp"
#include "exactness.hpp"
#include <catch2/catch.hpp>
#include <cstring>
#include <set>

using namespace strahl;
using namespace strahl::ch11;

namespace {

void check_every_step(const triangle_mesh& m, std::size_t n_rays) {
    for (const step_info& st : all_steps()) {
        const auto a = make_accel(st.id);
        a->build(test::mesh_only(m));
        INFO(st.name << ", " << m.triangle_count() << " triangles");
        CHECK(test::disagreements_with_brute_force(*a, m, test::nasty_rays(a->tree(), n_rays, 23)) == 0);
    }
}

}  // namespace

TEST_CASE("ch11 steps: six steps with distinct names, each a structure named after it", "[ch11]") {
    std::set<std::string> names;
    for (const step_info& st : all_steps()) {
        names.insert(st.name);
        CHECK(make_accel(st.id)->name() == std::string("ch11-") + st.name);
    }
    CHECK(names.size() == 6);
    CHECK(all_renderers().size() == 4);
}

TEST_CASE("ch11 steps: every step equals brute force on the teapot, a soup, planar and tied triangles",
          "[ch11][adversarial]") {
    check_every_step(teapot_mesh(3), 300);
    check_every_step(random_soup(1000, 7, 0.1f), 300);
    triangle_mesh flat = random_soup(500, 5, 0.1f);
    for (vec3& p : flat.positions) p.z = 0.5f;
    check_every_step(flat, 200);
    check_every_step(test::copies(400, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)), 100);
    check_every_step(test::copies(1, vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)), 100);
    check_every_step(triangle_mesh{}, 50);
}

TEST_CASE("ch11 steps: a triangle with an infinite vertex is left loose and still found", "[ch11][adversarial]") {
    triangle_mesh m = random_soup(200, 9, 0.1f);
    m.positions.push_back(vec3(0.5f, 0.5f, 0.5f));
    m.positions.push_back(vec3(inf, 0.5f, 0.5f));
    m.positions.push_back(vec3(0.5f, 0.9f, 0.5f));
    const std::uint32_t n = std::uint32_t(m.positions.size());
    m.indices.push_back(uvec3(n - 3, n - 2, n - 1));
    check_every_step(m, 200);
}

TEST_CASE("ch11 steps: with spheres and planes, every step equals chapter 01's world", "[ch11][adversarial]") {
    scene s = teapot_scene(3);  // a ground plane
    s.spheres.push_back({vec3(1.5f, 0.5f, 1.0f), 0.5f, 0});
    s.spheres.push_back({vec3(1.5f, 0.5f, 1.0f), 0.5f, 0});  // twice: the tie goes to the lower id
    s.planes.push_back({vec3(0, 0, 1), -3.0f, 1});
    const ch01::world w = ch01::build_world(s);
    for (const step_info& st : all_steps()) {
        const auto a = make_accel(st.id, true);
        a->build(s);
        const std::vector<ray> rays = test::nasty_rays(a->tree(), 300, 31);
        std::vector<hit> got(rays.size());
        std::vector<std::uint8_t> blocked(rays.size());
        a->intersect(rays, got);
        a->occluded(rays, blocked);
        std::size_t wrong = 0, hits = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            ch01::surface ref;
            counting c;
            const hit want = w.closest_hit(rays[i], ref, c) ? ref.h : hit{};
            hits += want.found() && want.prim >= s.mesh.triangle_count();
            wrong += !test::bit_equal(got[i], want) || (blocked[i] != 0) != w.occluded(rays[i], c);
        }
        INFO(st.name);
        CHECK(wrong == 0);
        CHECK(hits > 20);  // the rays do meet the spheres and planes
    }
}

TEST_CASE("ch11 renderers: the same image as chapter 01's brute force, bit for bit", "[ch11]") {
    const scene s = cornell_box(true);
    const camera cam(s.camera, 24, 24);
    ch01::render_settings settings;
    settings.tile_size = 8;
    const thread_limit two(2);
    const ch01::world w = ch01::build_world(s, 4);
    const ch01::render_result want = ch01::render(w, cam, settings);
    for (const renderer& how : all_renderers()) {
        const ch01::render_result got = render(s, cam, how, settings, 4);
        INFO(how.name);
        REQUIRE(got.img.pixels.size() == want.img.pixels.size());
        CHECK(std::memcmp(got.img.pixels.data(), want.img.pixels.data(), want.img.pixels.size() * sizeof(color)) == 0);
        CHECK(got.counts.total() == want.counts.total());
        CHECK(got.counts.reflection > 100);  // the mirrors' rays are there
    }
}

TEST_CASE("ch11 steps: triangles only keep less than chapter 01's objects", "[ch11]") {
    const scene s = test::mesh_only(teapot_mesh(6));
    std::vector<std::size_t> bytes;
    for (const step_info& st : all_steps()) {
        const auto a = make_accel(st.id);
        a->build(s);
        bytes.push_back(a->memory_bytes());
    }
    CHECK(bytes[3] < bytes[1]);  // edges in leaf order: 36 bytes and an id, against a 48-byte variant
    CHECK(bytes[1] < bytes[0]);  // one array of values against heap objects and pointers
    CHECK(bytes[4] == bytes[3]);
    CHECK(bytes[5] == bytes[3]);
}
