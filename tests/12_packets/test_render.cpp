// Chapter 12's packet renderer: chapter 11's Whitted renderer with its primary and shadow rays traced in
// packets gives the single-ray renderer's image bit for bit (mirrors, rough mirrors, several lights, tiles
// cut by the image's edge), for packet tracers of every tree.
#include "strahl/ch05/sah.hpp"
#include "strahl/ch12/accel.hpp"
#include "strahl/ch12/render.hpp"
#include "strahl/ch13/accel.hpp"
#include "strahl/procedural.hpp"
#include <catch2/catch.hpp>
#include <cstring>

using namespace strahl;

TEST_CASE("ch12 render: primary and shadow rays in packets give the single-ray Whitted image bit for bit", "[ch12]") {
    for (scene s : {teapot_in_stadium(4, 16), cornell_box(false)}) {
        REQUIRE(!s.lights.empty());
        // Every third triangle a mirror, every third a rough mirror: reflection rays, traced one at a time.
        s.materials.push_back({});
        s.materials.back().kind = material_kind::mirror;
        s.materials.push_back({});
        s.materials.back().kind = material_kind::rough_mirror, s.materials.back().roughness = 0.2f;
        const std::uint32_t first = std::uint32_t(s.materials.size()) - 2;
        s.triangle_materials.resize(s.mesh.triangle_count());
        for (std::size_t i = 0; i < s.triangle_materials.size(); ++i)
            s.triangle_materials[i] = i % 3 == 0 ? 0u : first + std::uint32_t(i % 3 - 1);
        const camera cam = scene_camera(s, 37, 29);  // 16-pixel tiles cut at the right and bottom edges
        ch01::render_settings settings;
        settings.max_depth = 3;
        ch13::wide_config c;
        c.collapse.method = ch13::collapse_method::optimal;
        const auto single = ch13::make_accel("single", [](std::span<const aabb> b, std::span<const vec3> ctr) {
            return ch05::build_sah_bvh_fast(b, ctr);
        }, c);
        single->build(s);
        const ch01::render_result want = ch12::render_single(*single, s, cam, settings, 4);
        for (const ch12::packet_config& pc : {ch12::packet_config{ch12::walk_kind::wide, 16, 4, 4, 0},
                                              ch12::packet_config{ch12::walk_kind::masked, 16, 4, 4, 0},
                                              ch12::packet_config{ch12::walk_kind::frustum, 16, 4, 4, 0}}) {
            const auto packets = ch12::make_accel("packets", pc);
            packets->build(s);
            const ch01::render_result got = ch12::render_packets(*packets, *single, s, cam, settings, 4);
            INFO(s.name << ", " << ch12::describe(pc));
            REQUIRE(got.img.pixels.size() == want.img.pixels.size());
            CHECK(std::memcmp(got.img.pixels.data(), want.img.pixels.data(), want.img.pixels.size() * sizeof(color)) == 0);
            CHECK(got.counts.primary == want.counts.primary);
            CHECK(got.counts.shadow == want.counts.shadow);
            CHECK(got.counts.reflection == want.counts.reflection);
            CHECK(got.rays_per_pixel == want.rays_per_pixel);
        }
        // The image is not black: the test compares something.
        float sum = 0.0f;
        for (const color& p : want.img.pixels) sum += p.r + p.g + p.b;
        CHECK(sum > 0.0f);
        CHECK(want.counts.reflection > 0);
    }
}
