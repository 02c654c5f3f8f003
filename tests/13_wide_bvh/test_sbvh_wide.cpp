// Chapter 09's SBVH collapsed into wide nodes (0 points): make_accel_from_mesh hands the builder the mesh;
// the binary tree's leaves may reference a triangle more than once, in different leaves, and the wide
// walk's answers are still brute force's bit for bit, closest and any hit, at every width.
#include "strahl/ch09/sbvh.hpp"
#include "strahl/ch13/accel.hpp"
#include "strahl/procedural.hpp"
#include "bvh_rays.hpp"
#include "exactness.hpp"
#include "test_support.hpp"
#include <catch2/catch.hpp>

using namespace strahl;

TEST_CASE("ch13 wide BVH over chapter 09's SBVH: duplicated references, brute force's answers", "[ch13][adversarial]") {
    triangle_mesh slivers;  // long thin crossing triangles: spatial splits everywhere
    for (std::uint32_t k = 0; k < 300; ++k) {
        const float y = 0.01f * float(k), z = 0.37f * float(k % 7);
        slivers.positions.insert(slivers.positions.end(), {vec3(0, y, z), vec3(10, y + 4, z + 1), vec3(10, y + 4.01f, z)});
        slivers.indices.push_back(uvec3(3 * k, 3 * k + 1, 3 * k + 2));
    }
    const std::vector<std::pair<std::string, triangle_mesh>> meshes = {
        {"teapot in a stadium", builtin_scene("teapot_stadium").mesh}, {"crossing slivers", slivers}};
    for (const auto& [name, mesh] : meshes)
        for (const int width : {4, 8, 16}) {
            ch09::sbvh_params p;
            p.alpha = 0.0f, p.budget = 2.0f;
            ch13::wide_config c;
            c.width = width, c.block = 4, c.collapse.method = ch13::collapse_method::optimal;
            const auto a = ch13::make_accel_from_mesh("sbvh-wide", [p](const triangle_mesh& m) { return ch09::build_sbvh(m, p); }, c);
            a->build(test::mesh_only(mesh));
            INFO(name << ", width " << width);
            const ch04::bvh source = ch09::build_sbvh(mesh, p);  // the tree the accel collapsed (the same build)
            CHECK(source.prim_ids.size() > mesh.triangle_count());       // references duplicated ...
            CHECK(a->stats().triangles == source.prim_ids.size());       // ... and kept in the wide leaves
            CHECK(test::disagreements_with_brute_force(*a, mesh, test::nasty_rays(source, 600, 13)) == 0);
        }
}
