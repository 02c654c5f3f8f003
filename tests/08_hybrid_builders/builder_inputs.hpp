// What chapter 08's builder tests share: the inputs every builder must survive, by name, and the
// comparison of two binary trees node for node (the same tree on 1 and 2 threads, or against a plain
// version of an algorithm).
#pragma once
#include "strahl/ch08/binary_tree.hpp"
#include "strahl/procedural.hpp"
#include "strahl/scene.hpp"
#include "exactness.hpp"
#include "flat_bvh_check.hpp"
#include "test_support.hpp"
#include <filesystem>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace strahl::test {

// The inputs every builder of the chapter must survive, by name.
inline std::vector<std::pair<std::string, triangle_mesh>> hard_meshes() {
    std::vector<std::pair<std::string, triangle_mesh>> m;
    m.emplace_back("teapot", builtin_scene("teapot").mesh);
    m.emplace_back("soup", random_soup(3000, 4, 0.05f));
    m.emplace_back("empty", triangle_mesh{});
    for (const std::size_t n : {1, 2, 3}) m.emplace_back(std::to_string(n) + " triangles", random_soup(n, 7, 0.1f));
    m.emplace_back("3000 identical triangles", copies(3000, vec3(0), vec3(1, 0, 0), vec3(0, 1, 0)));
    triangle_mesh centred;  // boxes of growing size, all centred on the origin
    for (std::uint32_t k = 0; k < 2000; ++k) {
        const float s = 1.0f + 0.01f * float(k);
        centred.positions.insert(centred.positions.end(), {vec3(-s, -s, 0), vec3(s, -s, 0), vec3(0, s, 0)});
        centred.indices.push_back(uvec3(3 * k, 3 * k + 1, 3 * k + 2));
    }
    m.emplace_back("all centroids equal", centred);
    triangle_mesh outlier = random_soup(2000, 6, 0.1f);
    const auto b = std::uint32_t(outlier.positions.size());
    outlier.positions.insert(outlier.positions.end(), {vec3(1e30f), vec3(1e30f, 0, 0), vec3(0, 1e30f, 0)});
    outlier.indices.push_back(uvec3(b, b + 1, b + 2));
    m.emplace_back("a 1e30 outlier", outlier);
    triangle_mesh odd = random_soup(300, 9, 0.1f);
    odd.positions[0].x = std::numeric_limits<float>::quiet_NaN();
    odd.positions[5].y = std::numeric_limits<float>::infinity();
    m.emplace_back("non-finite vertices", odd);
    return m;
}

inline bool same_tree(const ch08::binary_tree& a, const ch08::binary_tree& b) {
    if (a.root != b.root || a.nodes.size() != b.nodes.size() || a.loose != b.loose) return false;
    for (std::size_t i = 0; i < a.nodes.size(); ++i) {
        const ch08::tree_node &x = a.nodes[i], &y = b.nodes[i];
        if (!same_box(x.box, y.box) || x.left != y.left || x.right != y.right || x.parent != y.parent ||
            x.prim != y.prim)
            return false;
    }
    return true;
}

// The meshes the exactness tests walk: the teapot in a stadium, a soup of 1,500 triangles, and the bunny
// (said where it is skipped: not beside the clone).
inline std::vector<std::pair<std::string, triangle_mesh>> exactness_meshes() {
    std::vector<std::pair<std::string, triangle_mesh>> meshes = {{"teapot in a stadium", builtin_scene("teapot_stadium").mesh},
                                                                 {"soup", random_soup(1500, 3, 0.1f)}};
    const std::filesystem::path bunny = shared_scene("bunny.ply");
    if (bunny.empty())
        WARN("skipped the bunny: ../shared/scenes/bunny.ply is not beside this clone");
    else
        meshes.emplace_back("bunny", load_mesh(bunny));
    return meshes;
}

}  // namespace strahl::test
